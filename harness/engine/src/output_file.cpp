#include "engine/output_file.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "engine/cosim_error.hpp"

namespace cosim {

namespace fs = std::filesystem;

bool same_file(const fs::path& a, const fs::path& b) {
    struct stat sa {
    }, sb{};
    if (::stat(a.c_str(), &sa) == 0 && ::stat(b.c_str(), &sb) == 0)
        return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
    std::error_code ea, eb;
    const auto ca = fs::weakly_canonical(fs::absolute(a), ea), cb = fs::weakly_canonical(fs::absolute(b), eb);
    return !ea && !eb && ca == cb;
}

void refuse_overwriting_inputs(const std::string& option, const fs::path& output, const std::vector<fs::path>& inputs) {
    for (const auto& input : inputs)
        if (same_file(output, input))
            throw CosimError(option + " " + output.string() + " is the same file as the input " + input.string() +
                             ": refusing to overwrite an input");
}

PendingFile::PendingFile(const fs::path& target) : target_(target) {
    // A device, pipe or other non-regular file (/dev/stdout, /dev/full) is written in place: renaming a
    // file over it would replace the device.
    std::error_code ec;
    if (fs::exists(target, ec) && !fs::is_regular_file(target, ec)) {
        temporary_ = target;
        committed_ = true;
        return;
    }
    const fs::path folder = fs::absolute(target).parent_path();
    std::string pattern = (folder / ("." + target.filename().string() + ".XXXXXX")).string();
    const int fd = ::mkstemp(pattern.data());
    if (fd < 0) throw CosimError("cannot write " + target.string() + ": " + std::strerror(errno));
    ::fchmod(
        fd, 0644 & ~[] {
            const mode_t m = ::umask(0);
            ::umask(m);
            return m;
        }());
    ::close(fd);
    temporary_ = pattern;
}

PendingFile::~PendingFile() {
    std::error_code ec;
    if (!committed_) fs::remove(temporary_, ec);
}

void PendingFile::commit() {
    if (committed_) return;
    std::error_code ec;
    fs::rename(temporary_, target_, ec);
    if (ec) throw CosimError("cannot move " + temporary_.string() + " to " + target_.string() + ": " + ec.message());
    committed_ = true;
}

}  // namespace cosim
