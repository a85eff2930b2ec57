// What a command writes never destroys what it reads, nor an existing file before the work is known
// to start: every output is checked against every input (same_file), and written under a temporary name
// in its own folder that replaces the output only when committed.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace cosim {

// Same file: by device and inode where both exist, by their canonical paths otherwise.
bool same_file(const std::filesystem::path& a, const std::filesystem::path& b);

// Throws CosimError naming `option`, the output and the input when `output` is one of `inputs`.
void refuse_overwriting_inputs(const std::string& option, const std::filesystem::path& output,
                               const std::vector<std::filesystem::path>& inputs);

// A new file `.<name>.XXXXXX` beside `target`, renamed over it by commit(); removed if never committed.
// A target that exists and is not a regular file (a device, a pipe) is written in place.
class PendingFile {
public:
    explicit PendingFile(const std::filesystem::path& target);
    ~PendingFile();
    PendingFile(const PendingFile&) = delete;
    PendingFile& operator=(const PendingFile&) = delete;
    const std::filesystem::path& path() const { return temporary_; }
    const std::filesystem::path& target() const { return target_; }
    bool committed() const { return committed_; }
    // Renames the temporary file to the target (atomic on one file system); CosimError on failure.
    void commit();  // a no-op once committed

private:
    std::filesystem::path target_, temporary_;
    bool committed_ = false;
};

}  // namespace cosim
