// A .fmu unpacked into a private temporary directory that lives as long as the object.
#pragma once

#include <filesystem>

#include "fmi_loader/limits.hpp"

namespace fmi_loader {

class FmuArchive {
public:
    // Extracts every entry of `fmu_path` below a fresh mkdtemp directory, within `limits` (entry
    // count, entry and total size, compression ratio). Throws LoaderError (archive_open,
    // unsafe_entry, extract_io, limit, cancelled); on error nothing is left on disk.
    explicit FmuArchive(const std::filesystem::path& fmu_path, const Limits& limits = {});
    ~FmuArchive();
    FmuArchive(const FmuArchive&) = delete;
    FmuArchive& operator=(const FmuArchive&) = delete;
    FmuArchive(FmuArchive&& other) noexcept;
    FmuArchive& operator=(FmuArchive&& other) noexcept;

    const std::filesystem::path& fmu_path() const noexcept { return fmu_path_; }
    // The unpacked root: modelDescription.xml, binaries/, resources/ live here.
    const std::filesystem::path& directory() const noexcept { return directory_; }
    std::filesystem::path model_description_path() const { return directory_ / "modelDescription.xml"; }
    // file:// URI of resources/ as fmi2Instantiate expects it (the folder may be absent).
    std::string resource_uri() const;

private:
    void remove_directory() noexcept;

    std::filesystem::path fmu_path_;
    std::filesystem::path directory_;
};

}  // namespace fmi_loader
