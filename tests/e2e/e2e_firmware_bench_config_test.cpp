// The firmware bench's leo_orbit case (attitude_estimator/firmware/target/leo_orbit_as_bundled.hpp), from which
// the firmware README states the instructions per sample of leo_orbit's on-board computer "as bundled", held
// against harness/systems/leo_orbit.ssd read at test time: every parameter the master gives `est` (the .ssd's
// bindings and the system parameters wired to it) has the bench's value. A retuned system fails it until the
// bench is retuned too and its figures measured again.
#include <gtest/gtest.h>

#include <span>
#include <sstream>
#include <string>
#include <vector>

#include "attitude_estimator/estimator_block.hpp"
#include "engine/execution.hpp"
#include "engine/system.hpp"
#include "engine/system_description.hpp"
#include "fmu/value_access.hpp"
#include "leo_orbit_as_bundled.hpp"
#include "recorder.hpp"

namespace {

using attitude_estimator::EstimatorData;

TEST(E2eFirmwareBench, TheLeoOrbitCaseIsTheBundledSystemsComputer) {
    EstimatorData bench;
    firmware::bench_case_start(bench);
    firmware::leo_orbit_3u(bench, true, false);
    const auto bench_bytes = std::as_bytes(std::span(&bench, 1));

    const attitude_estimator::EstimatorBlock block;
    std::vector<const fmu::Variable*> parameters;
    std::vector<std::string> columns;
    for (const auto& v : block.table().variables()) {
        if (v.causality != fmu::Causality::parameter || v.type == fmu::ValueType::String) continue;
        parameters.push_back(&v);
        columns.push_back("est." + std::string(v.name));
    }
    ASSERT_GT(parameters.size(), 50u);

    cosim::SystemOptions options;
    options.fmu_dirs = {PVATT_FMU_DIR};
    cosim::System system(cosim::read_system_description(PVATT_SYSTEMS_DIR "/leo_orbit.ssd"), options);
    cosim::ExecutionOptions ex;
    ex.stop_time = 1.0;
    ex.output_interval = 1.0;
    e2e::Recorder rec(system, columns);
    cosim::Execution(system, ex).run({&rec});

    std::ostringstream differ;
    differ.precision(17);
    for (std::size_t i = 0; i < parameters.size(); ++i) {
        const fmu::Variable& v = *parameters[i];
        // The FMU in the system computes in double, the firmware in float by design (the float FMU is checked
        // bit for bit against the board in Firmware.Pil and BoardVsEmulator).
        if (v.name == "precision") continue;
        const double in_bench = fmu::read_number(bench_bytes, v);
        const double in_system = rec[columns[i]].front();
        if (in_bench != in_system) differ << "\n  " << columns[i] << ": system " << in_system << ", bench " << in_bench;
    }
    EXPECT_TRUE(differ.str().empty()) << "leo_orbit_as_bundled.hpp differs from leo_orbit.ssd:" << differ.str();
}

}  // namespace
