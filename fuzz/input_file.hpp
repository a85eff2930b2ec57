// A fuzz input handed to a reader that takes a path: the bytes written to one file per process, removed
// when the fuzzer exits. Shared by the .ssd and .ssp fuzzers.
#pragma once

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

namespace fuzz {

class InputFile {
public:
    // <temporary folder>/<stem>_<pid><extension>
    InputFile(const std::string& stem, const std::string& extension)
        : path_(std::filesystem::temp_directory_path() / (stem + "_" + std::to_string(::getpid()) + extension)) {}
    ~InputFile() { std::filesystem::remove(path_); }
    InputFile(const InputFile&) = delete;
    InputFile& operator=(const InputFile&) = delete;

    // Replaces the file's content with the input; returns its path.
    const std::filesystem::path& write(const std::uint8_t* data, std::size_t size) const {
        std::ofstream out(path_, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
        return path_;
    }

private:
    std::filesystem::path path_;
};

}  // namespace fuzz
