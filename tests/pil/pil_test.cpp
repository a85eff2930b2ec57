// Processor in the loop: seed_spin_pil.ssd with the estimator firmware on QEMU's mps2-an386 (Cortex-M4F),
// reached over its UART on a pseudo-terminal, against seed_spin.ssd with attitude_estimator.fmu computing
// in float (est.precision=float, est.spin_window=0), both through cosim for 2 s (40 samples), compared
// at every output row. Where the float arithmetic is the same on both — additions, multiplications,
// divisions and square roots are IEEE 754 single on the Cortex-M4F's FPU and on x86-64's SSE, and the
// firmware is compiled without fused multiply-add contraction — the outputs agree bit for bit: the seed's
// difference method with the Q-method, the response inversion with the fast solver. Where the computer
// calls the C library's float functions (acosf, asinf, atan2f, sinf, cosf: newlib's on the board, glibc's
// on the host, each within an ulp or two but not the same), the results differ by what those ulps become:
// the cones method's albedo fit (up to 2e-5 on q_est measured) and the filter's propagation (3e-7 on q_filt).
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "engine/csv_table.hpp"

extern char** environ;

namespace {

namespace fs = std::filesystem;

// QEMU running the firmware with UART0 on a new pseudo-terminal; killed on destruction.
class Qemu {
public:
    explicit Qemu(const fs::path& log) {
        const std::vector<std::string> args = {PVATT_QEMU, "-M",      "mps2-an386", "-nographic", "-monitor",
                                               "none",     "-serial", "pty",        "-kernel",    PVATT_FIRMWARE_ELF};
        std::vector<char*> argv;
        for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        posix_spawn_file_actions_t actions;
        posix_spawn_file_actions_init(&actions);
        posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
        posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
        posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
        if (posix_spawn(&pid_, argv[0], &actions, nullptr, argv.data(), environ) != 0) pid_ = -1;
        posix_spawn_file_actions_destroy(&actions);
        // QEMU names the terminal on its output: "char device redirected to /dev/pts/N (label serial0)".
        // (A plain search: <regex> trips GCC 12's -Wmaybe-uninitialized under the sanitizers.)
        const std::string prefix = "/dev/pts/";
        for (int i = 0; i < 100 && pid_ > 0 && pty_.empty(); ++i) {
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
            std::ifstream in(log);
            std::stringstream s;
            s << in.rdbuf();
            const std::string text = s.str();
            const auto at = text.find(prefix);
            if (at == std::string::npos) continue;
            auto end = at + prefix.size();
            while (end < text.size() && text[end] >= '0' && text[end] <= '9') ++end;
            if (end > at + prefix.size()) pty_ = text.substr(at, end - at);
        }
    }
    ~Qemu() {
        if (pid_ > 0) {
            kill(pid_, SIGTERM);
            waitpid(pid_, nullptr, 0);
        }
    }
    const std::string& pty() const { return pty_; }

private:
    pid_t pid_ = -1;
    std::string pty_;
};

class Pil : public ::testing::Test {
protected:
    void SetUp() override {
        if (std::string(PVATT_QEMU).empty())
            GTEST_SKIP() << "qemu-system-arm not found (scripts/install_deps.sh --firmware)";
        if (!fs::exists(PVATT_FIRMWARE_ELF)) GTEST_SKIP() << "no firmware image at " << PVATT_FIRMWARE_ELF;
        dir_ = fs::temp_directory_path() / ("pvatt_pil_" + std::to_string(getpid()) + "_" +
                                            ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::create_directories(dir_);
    }
    void TearDown() override {
        if (!dir_.empty() && !HasFailure()) fs::remove_all(dir_);
    }

    // The PIL run and the all-FMU float run of the seed scenario with `settings` (--set ...) on both.
    std::pair<cosim::CsvTable, cosim::CsvTable> run_both(const std::string& settings, double stop) {
        Qemu qemu(dir_ / "qemu.log");
        EXPECT_FALSE(qemu.pty().empty()) << "QEMU named no pseudo-terminal (see " << dir_ / "qemu.log"
                                         << ")";
        const std::string common = " --stop-time " + std::to_string(stop) + " --output-interval 0.025 " + settings;
        const fs::path pil = dir_ / "pil.csv", fmu = dir_ / "fmu.csv";
        const std::string pil_run = std::string("'") + PVATT_COSIM + "' run '" + PVATT_SYSTEMS_DIR +
                                    "/seed_spin_pil.ssd' --bridge-device " + qemu.pty() + common + " --output '" +
                                    pil.string() + "' > '" + (dir_ / "pil.log").string() + "' 2>&1";
        const std::string fmu_run = std::string("'") + PVATT_COSIM + "' run '" + PVATT_SYSTEMS_DIR +
                                    "/seed_spin.ssd' --set est.precision=float --set est.spin_window=0" + common +
                                    " --output '" + fmu.string() + "' > '" + (dir_ / "fmu.log").string() + "' 2>&1";
        EXPECT_EQ(std::system(pil_run.c_str()), 0) << pil_run;
        EXPECT_EQ(std::system(fmu_run.c_str()), 0) << fmu_run;
        std::ifstream log(dir_ / "pil.log");
        std::stringstream s;
        s << log.rdbuf();
        // Every sample answered by the board: 1 + 20 per second.
        const std::string answered = std::to_string(1 + static_cast<int>(std::lround(20 * stop)));
        EXPECT_NE(s.str().find(answered + " frames, " + answered + " answered, 0 missed"), std::string::npos)
            << s.str();
        return {cosim::read_csv(pil), cosim::read_csv(fmu)};
    }

    fs::path dir_;
};

struct Difference {
    double max = 0.0;
    std::size_t differing_rows = 0, rows = 0;
};

// Over the estimator's columns named (all "est." columns when `names` is empty).
Difference compare(const cosim::CsvTable& a, const cosim::CsvTable& b, const std::vector<std::string>& names = {}) {
    Difference d;
    EXPECT_EQ(a.rows(), b.rows());
    d.rows = std::min(a.rows(), b.rows());
    std::vector<bool> differs(d.rows, false);
    for (std::size_t c = 0; c < a.names.size(); ++c) {
        const std::string& name = a.names[c];
        if (names.empty() ? !name.starts_with("est.") : std::find(names.begin(), names.end(), name) == names.end())
            continue;
        const auto other = b.find(name);
        EXPECT_TRUE(other.has_value()) << name;
        if (!other) continue;
        for (std::size_t r = 0; r < d.rows; ++r) {
            const double x = a.columns[c][r], y = b.columns[*other][r];
            if (x == y || (std::isnan(x) && std::isnan(y))) continue;
            differs[r] = true;
            d.max = std::max(d.max, std::abs(x - y));
        }
    }
    for (bool x : differs) d.differing_rows += x;
    return d;
}

const std::vector<std::string> q_est = {"est.q_est[1]", "est.q_est[2]", "est.q_est[3]", "est.q_est[4]"};
const std::vector<std::string> q_filt = {"est.q_filt[1]", "est.q_filt[2]", "est.q_filt[3]", "est.q_filt[4]"};

TEST_F(Pil, SeedScenarioIsBitForBitTheFloatFmu) {
    const auto [pil, fmu] = run_both("", 2.0);
    const Difference d = compare(pil, fmu);
    EXPECT_EQ(d.differing_rows, 0u) << "largest difference " << d.max;
    EXPECT_GT(d.rows, 80u);
    // The board did the work: valid estimates, counted samples.
    const auto valid = pil.find("est.valid"), samples = pil.find("est.samples");
    ASSERT_TRUE(valid && samples);
    EXPECT_EQ(pil.columns[*samples].back(), 41.0);
    EXPECT_EQ(pil.columns[*valid].back(), 1.0);
}

TEST_F(Pil, ResponseInversionAndFastSolverAreBitForBit) {
    const auto [pil, fmu] = run_both("--set est.sun_method=inverse_response --set est.solver=fast", 2.0);
    const Difference d = compare(pil, fmu);
    EXPECT_EQ(d.differing_rows, 0u) << "largest difference " << d.max;
}

TEST_F(Pil, ConesAndFilterAgreeWithinTheLibmDifference) {
    {
        const auto [pil, fmu] = run_both("--set est.sun_method=cones", 4.0);
        const Difference d = compare(pil, fmu, q_est);
        std::cout << "cones: q_est differs in " << d.differing_rows << " of " << d.rows << " rows, by at most " << d.max
                  << "\n";
        EXPECT_LT(d.max, 1e-4);
        EXPECT_LT(d.differing_rows, d.rows / 2);  // most samples never call a function whose result differs
    }
    {
        const auto [pil, fmu] = run_both("--set est.filter=mekf", 4.0);
        EXPECT_EQ(compare(pil, fmu, q_est).differing_rows, 0u);  // the single-frame estimate: no libm call
        const Difference d = compare(pil, fmu, q_filt);
        std::cout << "mekf: q_filt differs in " << d.differing_rows << " of " << d.rows << " rows, by at most " << d.max
                  << "\n";
        EXPECT_LT(d.max, 1e-5);
    }
}

}  // namespace
