// Unzips a .fmu with libzip. An FMU comes from anywhere, so every entry name is checked before a byte
// is written: the zip format allows "../x", "/etc/x" and symlink entries, all of which could write
// outside the extraction directory ("zip slip").
#include "fmi_loader/fmu_archive.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zip.h>

#include <array>
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <memory>
#include <string>
#include <system_error>

#include "fmi_loader/loader_error.hpp"

namespace fmi_loader {
namespace {

namespace fs = std::filesystem;

struct ZipCloser {
    void operator()(zip_t* z) const noexcept { zip_discard(z); }  // read-only: nothing to write back
};
struct ZipFileCloser {
    void operator()(zip_file_t* f) const noexcept { zip_fclose(f); }
};

std::string zip_error_text(int code) {
    zip_error_t err;
    zip_error_init_with_code(&err, code);
    std::string text = zip_error_strerror(&err);
    zip_error_fini(&err);
    return text;
}

// Returns why `name` is unsafe, or an empty string when it stays inside the root.
std::string unsafe_reason(const std::string& name) {
    if (name.empty()) return "empty entry name";
    if (name.front() == '/') return "absolute path";
    // The zip format uses '/' only; a backslash or drive letter means a path meant for another OS.
    if (name.find('\\') != std::string::npos) return "backslash in entry name";
    if (name.find(':') != std::string::npos) return "':' (drive letter or stream) in entry name";
    std::size_t begin = 0;
    while (begin <= name.size()) {
        std::size_t end = name.find('/', begin);
        if (end == std::string::npos) end = name.size();
        if (name.compare(begin, end - begin, "..") == 0 && end - begin == 2) return "'..' path component";
        begin = end + 1;
    }
    return {};
}

[[noreturn]] void fail(LoaderErrc code, const fs::path& fmu, const std::string& cause) {
    throw LoaderError(code, "'" + fmu.string() + "': " + cause);
}

[[noreturn]] void fail_limit(const fs::path& fmu, const std::string& what, std::uint64_t value, std::uint64_t limit,
                             const char* unit, const char* limit_name) {
    fail(LoaderErrc::limit, fmu,
         what + " " + std::to_string(value) + unit + ", more than the limit of " + std::to_string(limit) + unit + " (" +
             limit_name + ")");
}

void check_cancel(const fs::path& fmu) {
    if (cancel_requested()) fail(LoaderErrc::cancelled, fmu, "extraction interrupted");
}

// The sizes the central directory declares, checked before a byte is written: the stream is then
// held to the declared size, so a lying header cannot write more either.
void check_declared(const zip_stat_t& st, const std::string& name, std::uint64_t& total, const Limits& limits,
                    const fs::path& fmu) {
    const std::uint64_t size = (st.valid & ZIP_STAT_SIZE) ? st.size : 0;
    if (size > limits.max_entry_bytes)
        fail_limit(fmu, "entry '" + name + "' is", size, limits.max_entry_bytes, " bytes uncompressed",
                   "max_entry_bytes");
    total += size;
    if (total > limits.max_total_bytes)
        fail_limit(fmu, "the entries up to '" + name + "' are", total, limits.max_total_bytes, " bytes uncompressed",
                   "max_total_bytes");
    if (size >= limits.ratio_min_bytes) {
        const std::uint64_t packed = (st.valid & ZIP_STAT_COMP_SIZE) ? st.comp_size : 0;
        const double ratio = packed > 0 ? static_cast<double>(size) / static_cast<double>(packed)
                                        : std::numeric_limits<double>::infinity();
        if (ratio > limits.max_compression_ratio)
            fail(LoaderErrc::limit, fmu,
                 "entry '" + name + "' expands " + std::to_string(packed) + " bytes to " + std::to_string(size) +
                     " (ratio " + std::to_string(ratio) + "), more than the limit of " +
                     std::to_string(limits.max_compression_ratio) + " (max_compression_ratio): a zip bomb?");
    }
}

void extract_entry(zip_t* archive, zip_uint64_t index, const std::string& name, zip_uint64_t size,
                   const fs::path& target, const fs::path& fmu) {
    std::unique_ptr<zip_file_t, ZipFileCloser> in(zip_fopen_index(archive, index, 0));
    if (!in) fail(LoaderErrc::extract_io, fmu, "cannot open entry '" + name + "': " + zip_strerror(archive));
    // O_EXCL: a second entry of the same name is refused instead of overwriting the first;
    // O_NOFOLLOW: never write through a link, even though none can be created by this code.
    const int fd = ::open(target.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
    if (fd < 0) fail(LoaderErrc::extract_io, fmu, "cannot create '" + target.string() + "': " + std::strerror(errno));
    std::array<char, 1 << 16> buffer{};
    zip_uint64_t total = 0;
    bool ok = true;
    std::string cause;
    for (;;) {
        const zip_int64_t n = zip_fread(in.get(), buffer.data(), buffer.size());
        if (n < 0) {
            ok = false;
            cause = std::string("read error: ") + zip_file_strerror(in.get());
            break;
        }
        if (n == 0) break;
        total += static_cast<zip_uint64_t>(n);
        if (total > size) {
            ok = false;
            cause = "holds more than its declared " + std::to_string(size) + " bytes";
            break;
        }
        if (cancel_requested()) {
            ok = false;
            cause = "extraction interrupted";
            break;
        }
        const char* p = buffer.data();
        zip_int64_t left = n;
        while (left > 0) {
            const ssize_t w = ::write(fd, p, static_cast<size_t>(left));
            if (w < 0) {
                if (errno == EINTR) continue;
                ok = false;
                cause = std::string("write error: ") + std::strerror(errno);
                break;
            }
            p += w;
            left -= w;
        }
        if (!ok) break;
    }
    if (::close(fd) != 0 && ok) {
        ok = false;
        cause = std::string("write error: ") + std::strerror(errno);
    }
    if (cancel_requested()) fail(LoaderErrc::cancelled, fmu, "extraction interrupted");
    if (ok && total != size) {
        ok = false;
        cause = "size mismatch (" + std::to_string(total) + " of " + std::to_string(size) + " bytes)";
    }
    if (!ok) fail(LoaderErrc::extract_io, fmu, "entry '" + name + "': " + cause);
}

}  // namespace

FmuArchive::FmuArchive(const fs::path& fmu_path, const Limits& limits) : fmu_path_(fmu_path) {
    int code = 0;
    std::unique_ptr<zip_t, ZipCloser> archive(zip_open(fmu_path.c_str(), ZIP_RDONLY, &code));
    if (!archive) fail(LoaderErrc::archive_open, fmu_path, zip_error_text(code));

    std::string pattern = (fs::temp_directory_path() / "fmi_loader_XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr)
        fail(LoaderErrc::extract_io, fmu_path, std::string("mkdtemp failed: ") + std::strerror(errno));
    directory_ = pattern;

    try {
        const zip_int64_t count = zip_get_num_entries(archive.get(), 0);
        if (count > 0 && static_cast<std::uint64_t>(count) > limits.max_entries)
            fail_limit(fmu_path, "the archive has", static_cast<std::uint64_t>(count), limits.max_entries, " entries",
                       "max_entries");
        std::uint64_t total = 0;
        for (zip_int64_t i = 0; i < count; ++i) {
            check_cancel(fmu_path);
            const auto index = static_cast<zip_uint64_t>(i);
            zip_stat_t st;
            zip_stat_init(&st);
            if (zip_stat_index(archive.get(), index, 0, &st) != 0 || !(st.valid & ZIP_STAT_NAME))
                fail(LoaderErrc::extract_io, fmu_path, "cannot stat entry " + std::to_string(i));
            const std::string name = st.name;
            if (const std::string why = unsafe_reason(name); !why.empty())
                fail(LoaderErrc::unsafe_entry, fmu_path, "entry '" + name + "' refused: " + why);

            zip_uint8_t opsys = 0;
            zip_uint32_t attributes = 0;
            if (zip_file_get_external_attributes(archive.get(), index, 0, &opsys, &attributes) == 0 &&
                opsys == ZIP_OPSYS_UNIX) {
                // Unix zips keep st_mode in the high 16 bits of the external attributes.
                const auto mode = static_cast<mode_t>(attributes >> 16);
                if (S_ISLNK(mode))
                    fail(LoaderErrc::unsafe_entry, fmu_path, "entry '" + name + "' refused: symbolic link");
                if ((mode & S_IFMT) != 0 && !S_ISREG(mode) && !S_ISDIR(mode))
                    fail(LoaderErrc::unsafe_entry, fmu_path,
                         "entry '" + name + "' refused: not a regular file or directory");
            }

            check_declared(st, name, total, limits, fmu_path);

            const fs::path target = directory_ / fs::path(name).relative_path();
            std::error_code ec;
            if (name.back() == '/') {
                fs::create_directories(target, ec);
                if (ec)
                    fail(LoaderErrc::extract_io, fmu_path, "cannot create '" + target.string() + "': " + ec.message());
                continue;
            }
            fs::create_directories(target.parent_path(), ec);
            if (ec)
                fail(LoaderErrc::extract_io, fmu_path,
                     "cannot create '" + target.parent_path().string() + "': " + ec.message());
            extract_entry(archive.get(), index, name, (st.valid & ZIP_STAT_SIZE) ? st.size : 0, target, fmu_path);
        }
    } catch (...) {
        remove_directory();
        throw;
    }
}

FmuArchive::~FmuArchive() {
    remove_directory();
}

FmuArchive::FmuArchive(FmuArchive&& other) noexcept
    : fmu_path_(std::move(other.fmu_path_)), directory_(std::move(other.directory_)) {
    other.directory_.clear();
}

FmuArchive& FmuArchive::operator=(FmuArchive&& other) noexcept {
    if (this != &other) {
        remove_directory();
        fmu_path_ = std::move(other.fmu_path_);
        directory_ = std::move(other.directory_);
        other.directory_.clear();
    }
    return *this;
}

void FmuArchive::remove_directory() noexcept {
    if (directory_.empty()) return;
    std::error_code ec;  // best effort: a destructor must not throw
    fs::remove_all(directory_, ec);
    directory_.clear();
}

std::string FmuArchive::resource_uri() const {
    // RFC 3986 percent-encoding of everything but unreserved characters and '/'.
    const std::string path = (directory_ / "resources").string() + "/";
    std::string uri = "file://";
    static constexpr char hex[] = "0123456789ABCDEF";
    for (const unsigned char c : path) {
        if (std::isalnum(c) || c == '/' || c == '-' || c == '.' || c == '_' || c == '~') {
            uri += static_cast<char>(c);
        } else {
            uri += '%';
            uri += hex[c >> 4];
            uri += hex[c & 0xF];
        }
    }
    return uri;
}

}  // namespace fmi_loader
