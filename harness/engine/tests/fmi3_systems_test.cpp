// The bundled systems built from the blocks' FMI 3.0 archives (build/fmus3) give the results of their
// FMI 2.0 archives (build/fmus), value for value in every output of every component: the FMI 3.0
// instance runs over the same equations, and the master sees the arrays as the 2.0 elements.
// seed_spin as bundled is left out: its plant runs in Co-Simulation with its inputs interpolated through
// fmi2SetRealInputDerivatives, which FMI 3.0 no longer has (docs/design.md, "FMI 3.0 import").
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "engine/execution.hpp"
#include "engine/system.hpp"
#include "engine/system_description.hpp"

namespace cosim {
namespace {

// Every output of every component as text (17 significant digits for a Real) at every sample.
struct Outputs : Observer {
    std::vector<std::string> rows;
    void sample(double t, System& s) override {
        std::string row = std::to_string(t);
        for (auto& c : s.components())
            for (const auto& v : c.description().model_variables)
                if (v.causality == fmi_loader::Causality::output) row += "," + c.instance->get_as_text(v);
        rows.push_back(std::move(row));
    }
};

std::vector<std::string> run(const std::string& ssd, const std::string& fmu_dir, double stop, bool model_exchange) {
    SystemOptions o;
    o.fmu_dirs = {fmu_dir};
    o.model_exchange_only = model_exchange;
    System system(read_system_description(std::string(PVATT_SYSTEMS_DIR) + "/" + ssd), o);
    ExecutionOptions ex;
    ex.stop_time = stop;
    ex.output_interval = stop / 20;
    Outputs out;
    Execution(system, ex).run({&out});
    return out.rows;
}

TEST(CosimFmi3Systems, LeoOrbitFromFmi3ArchivesEqualsFmi2) {
    const auto fmi2 = run("leo_orbit.ssd", PVATT_FMU_DIR, 200.0, false);
    const auto fmi3 = run("leo_orbit.ssd", PVATT_FMU3_DIR, 200.0, false);
    ASSERT_EQ(fmi2.size(), 21u);
    EXPECT_EQ(fmi3, fmi2);
}

TEST(CosimFmi3Systems, SeedSpinAllModelExchangeFromFmi3ArchivesEqualsFmi2) {
    const auto fmi2 = run("seed_spin.ssd", PVATT_FMU_DIR, 0.5, true);
    const auto fmi3 = run("seed_spin.ssd", PVATT_FMU3_DIR, 0.5, true);
    ASSERT_EQ(fmi2.size(), 21u);
    EXPECT_EQ(fmi3, fmi2);
}

}  // namespace
}  // namespace cosim
