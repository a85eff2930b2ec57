#include "fmi_loader/fmu.hpp"

#include <algorithm>

#include "fmi_loader/loader_error.hpp"

namespace fmi_loader {

Fmu::Fmu(const std::filesystem::path& fmu_path, const Limits& limits)
    : archive_(fmu_path, limits), description_(read_model_description(archive_.model_description_path(), limits)) {}

namespace {

// The binary must be a regular file inside the unpacked FMU once every link is resolved: the
// modelIdentifier is already a C identifier, and this holds even if the platform folders were links.
std::filesystem::path binary_inside(const FmuArchive& archive, const std::string& id, bool fmi3) {
    namespace fs = std::filesystem;
    const fs::path path =
        fmi3 ? Fmi3Library::binary_path(archive.directory(), id) : Fmi2Library::binary_path(archive.directory(), id);
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

// One library per modelIdentifier: ME and CS share it when their identifiers agree.
template <class Library>
const Library& load(const FmuArchive& archive, const ModelDescription& md, FmuKind kind,
                    std::shared_ptr<Library>& me_slot, std::shared_ptr<Library>& cs_slot) {
    const auto& me = md.model_exchange;
    const auto& cs = md.co_simulation;
    const bool want_me = kind == FmuKind::model_exchange;
    if (want_me ? !me : !cs)
        throw LoaderError(LoaderErrc::missing_symbol, "'" + archive.fmu_path().string() + "' declares no " +
                                                          (want_me ? "ModelExchange" : "CoSimulation"));
    auto& slot = want_me ? me_slot : cs_slot;
    if (slot) return *slot;
    const bool shared = me && cs && me->model_identifier == cs->model_identifier;
    const std::string& id = want_me ? me->model_identifier : cs->model_identifier;
    slot = std::make_shared<Library>(binary_inside(archive, id, md.is_fmi3()), want_me || shared, !want_me || shared);
    if (shared) (want_me ? cs_slot : me_slot) = slot;
    return *slot;
}

void require_version(const FmuArchive& archive, const ModelDescription& md, bool fmi3) {
    if (md.is_fmi3() != fmi3)
        throw LoaderError(LoaderErrc::xml_invalid, "'" + archive.fmu_path().string() + "' is an FMI " + md.fmi_version +
                                                       " FMU, asked for as FMI " + (fmi3 ? "3.0" : "2.0"));
}

}  // namespace

bool Fmu::supports(FmuKind kind) const noexcept {
    return kind == FmuKind::model_exchange ? description_.model_exchange.has_value()
                                           : description_.co_simulation.has_value();
}

const Fmi2Library& Fmu::library(FmuKind kind) {
    require_version(archive_, description_, false);
    return load(archive_, description_, kind, me_, cs_);
}

const Fmi3Library& Fmu::library3(FmuKind kind) {
    require_version(archive_, description_, true);
    return load(archive_, description_, kind, me3_, cs3_);
}

}  // namespace fmi_loader
