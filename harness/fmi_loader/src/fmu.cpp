#include "fmi_loader/fmu.hpp"

#include "fmi_loader/loader_error.hpp"

namespace fmi_loader {

Fmu::Fmu(const std::filesystem::path& fmu_path)
    : archive_(fmu_path), description_(read_model_description(archive_.model_description_path())) {}

bool Fmu::supports(FmuKind kind) const noexcept {
    return kind == FmuKind::model_exchange ? description_.model_exchange.has_value()
                                           : description_.co_simulation.has_value();
}

const Fmi2Library& Fmu::library(FmuKind kind) {
    const auto& me = description_.model_exchange;
    const auto& cs = description_.co_simulation;
    if (!supports(kind))
        throw LoaderError(LoaderErrc::missing_symbol, "'" + archive_.fmu_path().string() + "' declares no " +
                                                          (kind == FmuKind::model_exchange ? "ModelExchange" : "CoSimulation"));
    auto& slot = kind == FmuKind::model_exchange ? me_ : cs_;
    if (slot) return *slot;
    const bool shared = me && cs && me->model_identifier == cs->model_identifier;
    const std::string& id = kind == FmuKind::model_exchange ? me->model_identifier : cs->model_identifier;
    slot = std::make_shared<Fmi2Library>(Fmi2Library::binary_path(archive_.directory(), id),
                                         kind == FmuKind::model_exchange || shared,
                                         kind == FmuKind::co_simulation || shared);
    if (shared) (kind == FmuKind::model_exchange ? cs_ : me_) = slot;
    return *slot;
}

}  // namespace fmi_loader
