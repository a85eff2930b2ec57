// FmuArchive: extraction of a well-formed FMU and refusal of every entry that could escape the
// extraction directory. The zips are made here with libzip so each hostile entry is exactly known.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <zip.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "fmi_loader/fmu_archive.hpp"
#include "fmi_loader/loader_error.hpp"

namespace fs = std::filesystem;
using fmi_loader::FmuArchive;
using fmi_loader::LoaderErrc;
using fmi_loader::LoaderError;

namespace {

struct Entry {
    std::string name;
    std::string content;
    bool symlink = false;
};

// Points TMPDIR at a private directory for the test, so "nothing left behind" can be checked.
class LoaderArchive : public ::testing::Test {
protected:
    void SetUp() override {
        std::string pattern = (fs::temp_directory_path() / "loader_archive_test_XXXXXX").string();
        ASSERT_NE(mkdtemp(pattern.data()), nullptr);
        root_ = pattern;
        const char* old = std::getenv("TMPDIR");
        old_tmpdir_ = old ? old : "";
        had_tmpdir_ = old != nullptr;
        fs::create_directory(root_ / "tmp");
        setenv("TMPDIR", (root_ / "tmp").c_str(), 1);
    }
    void TearDown() override {
        if (had_tmpdir_)
            setenv("TMPDIR", old_tmpdir_.c_str(), 1);
        else
            unsetenv("TMPDIR");
        fs::remove_all(root_);
    }

    fs::path make_zip(const std::vector<Entry>& entries) {
        const fs::path path = root_ / "test.fmu";
        fs::remove(path);
        int err = 0;
        zip_t* z = zip_open(path.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &err);
        EXPECT_NE(z, nullptr);
        for (const auto& e : entries) {
            zip_source_t* src = zip_source_buffer(z, e.content.data(), e.content.size(), 0);
            const zip_int64_t index = zip_file_add(z, e.name.c_str(), src, ZIP_FL_ENC_UTF_8);
            EXPECT_GE(index, 0) << "libzip refused to write entry " << e.name;
            if (e.symlink) {
                // Unix symlink: st_mode in the upper 16 bits, as Info-ZIP writes it.
                const zip_uint32_t mode = S_IFLNK | 0777;
                zip_file_set_external_attributes(z, static_cast<zip_uint64_t>(index), 0, ZIP_OPSYS_UNIX, mode << 16);
            }
        }
        EXPECT_EQ(zip_close(z), 0);
        return path;
    }

    bool tmp_is_empty() const { return fs::is_empty(root_ / "tmp"); }

    void expect_refused(const std::vector<Entry>& entries, const std::string& offending,
                        LoaderErrc code = LoaderErrc::unsafe_entry, const fmi_loader::Limits& limits = {}) {
        const fs::path fmu = make_zip(entries);
        try {
            FmuArchive archive(fmu, limits);
            ADD_FAILURE() << "entry '" << offending << "' was accepted";
        } catch (const LoaderError& e) {
            EXPECT_EQ(e.code(), code) << e.what();
            const std::string what = e.what();
            EXPECT_NE(what.find(fmu.string()), std::string::npos) << what;
            EXPECT_NE(what.find(offending), std::string::npos) << what;
        }
        EXPECT_TRUE(tmp_is_empty()) << "a refused archive left its extraction directory behind";
    }

    fs::path root_;
    std::string old_tmpdir_;
    bool had_tmpdir_ = false;
};

std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

}  // namespace

TEST_F(LoaderArchive, ExtractsFilesAndRemovesDirectoryOnDestruction) {
    const fs::path fmu = make_zip({{"modelDescription.xml", "<x/>"},
                                   {"binaries/", ""},
                                   {"binaries/linux64/m.so", std::string("\0\1\2bin", 6)},
                                   {"resources/data/table.csv", "1,2\n"}});
    fs::path dir;
    {
        FmuArchive archive(fmu);
        dir = archive.directory();
        EXPECT_EQ(dir.parent_path(), root_ / "tmp");
        EXPECT_EQ(slurp(archive.model_description_path()), "<x/>");
        EXPECT_EQ(slurp(dir / "binaries/linux64/m.so"), std::string("\0\1\2bin", 6));
        EXPECT_EQ(slurp(dir / "resources/data/table.csv"), "1,2\n");
        EXPECT_EQ(archive.resource_uri(), "file://" + (dir / "resources").string() + "/");
        FmuArchive moved(std::move(archive));
        EXPECT_EQ(moved.directory(), dir);
        EXPECT_TRUE(fs::exists(dir));
    }
    EXPECT_FALSE(fs::exists(dir));
    EXPECT_TRUE(tmp_is_empty());
}

TEST_F(LoaderArchive, RefusesParentDirectoryEntries) {
    expect_refused({{"modelDescription.xml", "<x/>"}, {"../evil", "x"}}, "../evil");
    EXPECT_FALSE(fs::exists(root_ / "evil"));
    expect_refused({{"resources/../../evil", "x"}}, "resources/../../evil");
    expect_refused({{"a/..", "x"}}, "a/..");
}

TEST_F(LoaderArchive, RefusesAbsolutePaths) {
    const fs::path target = root_ / "absolute_evil";
    expect_refused({{target.string(), "x"}}, target.string());
    EXPECT_FALSE(fs::exists(target));
    expect_refused({{"C:\\evil", "x"}}, "C:\\evil");
}

TEST_F(LoaderArchive, RefusesSymlinkEntries) {
    expect_refused({{"resources/link", "/etc", true}, {"resources/link/passwd", "x"}}, "resources/link");
}

TEST_F(LoaderArchive, MissingFileNamesFileAndCause) {
    const fs::path missing = root_ / "no_such.fmu";
    try {
        FmuArchive archive(missing);
        FAIL() << "opened a missing file";
    } catch (const LoaderError& e) {
        EXPECT_EQ(e.code(), LoaderErrc::archive_open);
        EXPECT_NE(std::string(e.what()).find(missing.string()), std::string::npos) << e.what();
    }
}

TEST_F(LoaderArchive, NotAZipIsRefused) {
    const fs::path bogus = root_ / "bogus.fmu";
    std::ofstream(bogus) << "this is not a zip archive";
    try {
        FmuArchive archive(bogus);
        FAIL() << "opened a non-zip";
    } catch (const LoaderError& e) {
        EXPECT_EQ(e.code(), LoaderErrc::archive_open);
    }
    EXPECT_TRUE(tmp_is_empty());
}

// Issue 14 case 3: bounded extraction. Limits are set low here so that no test writes more than a few
// megabytes; the message must name the limit that was hit.
TEST_F(LoaderArchive, TooManyEntriesAreRefusedBeforeExtracting) {
    fmi_loader::Limits limits;
    limits.max_entries = 3;
    expect_refused({{"a", "1"}, {"b", "2"}, {"c", "3"}, {"d", "4"}}, "max_entries", LoaderErrc::limit, limits);
}

TEST_F(LoaderArchive, OversizedEntryIsRefused) {
    fmi_loader::Limits limits;
    limits.max_entry_bytes = 100;
    expect_refused({{"modelDescription.xml", "<x/>"}, {"resources/big", std::string(200, 'x')}}, "max_entry_bytes",
                   LoaderErrc::limit, limits);
}

TEST_F(LoaderArchive, TotalSizeIsBounded) {
    fmi_loader::Limits limits;
    limits.max_total_bytes = 150;
    expect_refused({{"resources/a", std::string(100, 'x')}, {"resources/b", std::string(100, 'y')}}, "max_total_bytes",
                   LoaderErrc::limit, limits);
}

TEST_F(LoaderArchive, HighlyCompressibleEntryIsRefusedAtTheDefaultRatio) {
    // 2 MiB of zeros deflate to about 2 KiB (ratio ~1000, deflate's ceiling): the shape of a zip bomb,
    // at a size that costs nothing. The default limits apply (ratio 200 for entries of 1 MiB or more).
    expect_refused({{"modelDescription.xml", "<x/>"}, {"resources/zeros", std::string(std::size_t{2} << 20, '\0')}},
                   "max_compression_ratio", LoaderErrc::limit);
    // The same content below ratio_min_bytes is an ordinary small file.
    const fs::path fmu = make_zip({{"resources/zeros", std::string(std::size_t{512} << 10, '\0')}});
    EXPECT_NO_THROW(FmuArchive archive(fmu));
}

// Issue 14 case 4: a signal during extraction (request_cancel from the handler) stops it and removes
// what was written.
TEST_F(LoaderArchive, CancelledExtractionLeavesNothingBehind) {
    const fs::path fmu = make_zip({{"modelDescription.xml", "<x/>"}, {"resources/a", "1"}});
    fmi_loader::request_cancel();
    try {
        FmuArchive archive(fmu);
        ADD_FAILURE() << "extracted although cancelled";
    } catch (const LoaderError& e) {
        EXPECT_EQ(e.code(), LoaderErrc::cancelled) << e.what();
    }
    fmi_loader::clear_cancel();
    EXPECT_TRUE(tmp_is_empty());
    EXPECT_NO_THROW(FmuArchive archive(fmu));
}
