// One .fmu opened for use: unpacked, described, and its binary loaded.
#pragma once

#include <filesystem>
#include <memory>

#include "fmi_loader/fmi2_library.hpp"
#include "fmi_loader/fmi3_library.hpp"
#include "fmi_loader/fmu_archive.hpp"
#include "fmi_loader/model_description.hpp"

namespace fmi_loader {

enum class FmuKind { model_exchange, co_simulation };

class Fmu {
public:
    // Unpacks and parses; the binaries are loaded lazily by library() so a description-only user
    // (a validator on another platform) needs no .so. Throws LoaderError.
    explicit Fmu(const std::filesystem::path& fmu_path, const Limits& limits = {});

    const FmuArchive& archive() const noexcept { return archive_; }
    const ModelDescription& description() const noexcept { return description_; }
    bool supports(FmuKind kind) const noexcept;
    // The library implementing `kind`; ME and CS share one when their modelIdentifiers agree.
    // Throws LoaderError if the kind is not declared or the library cannot be loaded.
    const Fmi2Library& library(FmuKind kind);
    // The same for an FMI 3.0 FMU (description().is_fmi3()): binaries/x86_64-linux/<id>.so. Throws
    // LoaderError also when the description is not FMI 3.0 (and library() when it is).
    const Fmi3Library& library3(FmuKind kind);

private:
    FmuArchive archive_;
    ModelDescription description_;
    std::shared_ptr<Fmi2Library> me_, cs_;
    std::shared_ptr<Fmi3Library> me3_, cs3_;
};

}  // namespace fmi_loader
