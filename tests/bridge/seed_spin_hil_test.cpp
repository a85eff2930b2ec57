// The bundled hardware-in-the-loop system: seed_spin with the estimator behind the bridge, the board
// being the attitude_board_emulator executable (a separate process, UDP on 127.0.0.1, a free port)
// running the estimator block itself. With pacing off every estimator output at every output point
// must equal the all-FMU run of seed_spin.ssd. Skipped when the estimator FMU or emulator is not built;
// without ssr_plant.fmu both systems run without the plant (est's shunt-current inputs at their start
// values), which changes the scenario but not the comparison.
#include <gtest/gtest.h>

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "engine/execution.hpp"
#include "engine/system.hpp"
#include "engine/system_description.hpp"

extern char** environ;

namespace {

using namespace cosim;

const std::filesystem::path fmu_dir = PVATT_FMU_DIR;
const std::filesystem::path systems_dir = BRIDGE_SYSTEMS_DIR;
const std::filesystem::path emulator = BRIDGE_BOARD_EMULATOR;

// The emulator as a child process; it prints "udp 127.0.0.1:PORT" first and exits by itself after
// 20 s without a frame, or when the test ends (SIGTERM).
struct EmulatorProcess {
    pid_t pid = -1;
    int port = -1;
    EmulatorProcess() {
        int out[2];
        if (::pipe(out) != 0) return;
        posix_spawn_file_actions_t actions;
        posix_spawn_file_actions_init(&actions);
        posix_spawn_file_actions_adddup2(&actions, out[1], STDOUT_FILENO);
        posix_spawn_file_actions_addclose(&actions, out[0]);
        const std::string exe = emulator.string();
        // The board's own setting says "fast"; the .ssd binds est.solver = qmethod, which the master sends in its
        // configuration frames: the estimates equal the all-FMU run's only if the board applied them.
        std::vector<std::string> args = {exe, "--udp", "127.0.0.1:0", "--set", "solver=fast", "--idle-timeout", "20"};
        std::vector<char*> argv;
        for (auto& a : args) argv.push_back(a.data());
        argv.push_back(nullptr);
        const int rc = posix_spawn(&pid, exe.c_str(), &actions, nullptr, argv.data(), environ);
        posix_spawn_file_actions_destroy(&actions);
        ::close(out[1]);
        if (rc != 0) {
            pid = -1;
            ::close(out[0]);
            return;
        }
        FILE* f = ::fdopen(out[0], "r");
        char line[128] = {};
        if (f && std::fgets(line, sizeof line, f)) {
            const std::string s = line;
            if (const auto colon = s.rfind(':'); s.starts_with("udp ") && colon != std::string::npos)
                port = std::stoi(s.substr(colon + 1));
        }
        if (f) std::fclose(f);
    }
    ~EmulatorProcess() {
        if (pid <= 0) return;
        ::kill(pid, SIGTERM);
        int status = 0;
        ::waitpid(pid, &status, 0);
    }
};

struct EstimatorRecorder : Observer {
    std::vector<std::vector<std::string>> rows;
    void sample(double t, System& system) override {
        auto& c = system.components()[system.component_index("est")];
        std::vector<std::string> row{std::to_string(t)};
        for (const auto& v : c.description().model_variables)
            if (v.causality == fmi_loader::Causality::output) row.push_back(v.name + "=" + c.instance->get_as_text(v));
        rows.push_back(std::move(row));
    }
};

// The bundled system, or a copy without the plant component and its connections.
std::filesystem::path system_file(const std::string& ssd, bool with_plant) {
    if (with_plant) return systems_dir / ssd;
    std::ifstream in(systems_dir / ssd);
    std::stringstream buffer;
    buffer << in.rdbuf();
    std::string text = buffer.str();
    const auto begin = text.find("<ssd:Component name=\"plant\"");
    const std::string close = "</ssd:Component>";
    const auto end = text.find(close, begin);
    if (begin == std::string::npos || end == std::string::npos) throw std::runtime_error(ssd + ": no plant component");
    text.erase(begin, end + close.size() - begin);
    std::istringstream lines(text);
    std::string out, line;
    while (std::getline(lines, line))
        if (line.find("<ssd:Connection ") == std::string::npos || line.find("\"plant\"") == std::string::npos)
            out += line + "\n";
    const auto path = std::filesystem::temp_directory_path() / ("no_plant_" + std::to_string(::getpid()) + "_" + ssd);
    std::ofstream(path) << out;
    return path;
}

std::pair<EstimatorRecorder, RunStatistics> run(const std::string& ssd, std::optional<int> port,
                                                std::vector<std::string> settings = {}) {
    SystemOptions options;
    options.fmu_dirs = {fmu_dir};
    options.bridge_port = port;
    options.settings = std::move(settings);
    const bool with_plant = std::filesystem::exists(fmu_dir / "ssr_plant.fmu");
    const auto file = system_file(ssd, with_plant);
    System system(read_system_description(file), options);
    if (!with_plant) std::filesystem::remove(file);
    ExecutionOptions ex;
    ex.stop_time = 0.5;
    ex.output_interval = 0.01;
    EstimatorRecorder recorder;
    const auto stats = Execution(system, ex).run({&recorder});
    return {std::move(recorder), stats};
}

TEST(SeedSpinHil, EstimatesEqualTheAllFmuRun) {
    if (!std::filesystem::exists(fmu_dir / "attitude_estimator.fmu") || !std::filesystem::exists(emulator))
        GTEST_SKIP() << "attitude_estimator.fmu or attitude_board_emulator not built";
    for (const char* f : {"environment.fmu", "magnetometer.fmu"})
        if (!std::filesystem::exists(fmu_dir / f)) GTEST_SKIP() << f << " not built";
    // The all-FMU run first: the board is started only when the bridged run needs it, so its idle timeout
    // cannot expire while a slow (sanitized, loaded) machine runs the reference.
    // The bridged system has no set/reset pulses (the board is not wired to the magnetometer's strap):
    // the all-FMU run of the same system without them.
    const auto [fmu, fmu_stats] = run("seed_spin.ssd", std::nullopt, {"est.mag_set_reset_samples=0"});
    EmulatorProcess board;
    ASSERT_GT(board.port, 0) << "the emulator did not report its port";
    const auto [hw, hw_stats] = run("seed_spin_hil.ssd", board.port);
    ASSERT_EQ(fmu.rows.size(), hw.rows.size());
    for (std::size_t i = 0; i < fmu.rows.size(); ++i) EXPECT_EQ(fmu.rows[i], hw.rows[i]) << "row " << i;
    const auto& est = hw_stats.components.back();  // est is the last component
    ASSERT_EQ(est.name, "est");
    ASSERT_TRUE(est.link);
    // 20 Hz over 0.5 s: samples at 0, 0.05, ..., 0.5.
    EXPECT_EQ(est.link->exchanges, 11);
    EXPECT_EQ(est.link->answered, 11);
    EXPECT_EQ(est.link->misses, 0);
    std::printf("seed_spin_hil latency ms: min %.3f median %.3f p95 %.3f max %.3f\n", est.link->latency_min * 1e3,
                est.link->latency_median * 1e3, est.link->latency_p95 * 1e3, est.link->latency_max * 1e3);
}

}  // namespace
