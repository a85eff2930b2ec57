#include "fmi_loader/fmu.hpp"

#include <algorithm>

#include "fmi_loader/loader_error.hpp"

namespace fmi_loader {

Fmu::Fmu(const std::filesystem::path& fmu_path, const Limits& limits)
    : archive_(fmu_path, limits), description_(read_model_description(archive_.model_description_path(), limits)) {}

namespace {

// The binary must be a regular file inside the unpacked FMU once every link is resolved: the
// modelIdentifier is already a C identifier, and this holds even if the platform folders were links.
std::filesystem::path binary_inside(const FmuArchive& archive, const std::string& id) {
    namespace fs = std::filesystem;
    const fs::path path = Fmi2Library::binary_path(archive.directory(), id);
    std::error_code ec, ec_root;
    const fs::path real = fs::canonical(path, ec);
    const fs::path root = fs::canonical(archive.directory(), ec_root);
    if (ec || ec_root)
        throw LoaderError(LoaderErrc::dl_open, "'" + path.string() + "': " + (ec ? ec : ec_root).message());
    const auto [end, _] = std::mismatch(root.begin(), root.end(), real.begin(), real.end());
    if (end != root.end() || !fs::is_regular_file(real))
        throw LoaderError(LoaderErrc::dl_open, "'" + path.string() + "' resolves to '" + real.string() +
                                                   "', not a file inside the unpacked FMU");
    return real;
}

}  // namespace

bool Fmu::supports(FmuKind kind) const noexcept {
    return kind == FmuKind::model_exchange ? description_.model_exchange.has_value()
                                           : description_.co_simulation.has_value();
}

const Fmi2Library& Fmu::library(FmuKind kind) {
    const auto& me = description_.model_exchange;
    const auto& cs = description_.co_simulation;
    if (!supports(kind))
        throw LoaderError(LoaderErrc::missing_symbol,
                          "'" + archive_.fmu_path().string() + "' declares no " +
                              (kind == FmuKind::model_exchange ? "ModelExchange" : "CoSimulation"));
    auto& slot = kind == FmuKind::model_exchange ? me_ : cs_;
    if (slot) return *slot;
    const bool shared = me && cs && me->model_identifier == cs->model_identifier;
    const std::string& id = kind == FmuKind::model_exchange ? me->model_identifier : cs->model_identifier;
    slot = std::make_shared<Fmi2Library>(binary_inside(archive_, id), kind == FmuKind::model_exchange || shared,
                                         kind == FmuKind::co_simulation || shared);
    if (shared) (kind == FmuKind::model_exchange ? cs_ : me_) = slot;
    return *slot;
}

}  // namespace fmi_loader
