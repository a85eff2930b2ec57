// The master against requests and files that used to do nothing, lose data or leave files behind
// (issue 14 cases 4, 5, 6, 7, 9): every one is refused with a reason, or done as asked.
#include <gtest/gtest.h>

#include <cmath>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "engine/cosim_error.hpp"
#include "engine/csv_table.hpp"
#include "engine/interrupt.hpp"
#include "engine/ssp_archive.hpp"
#include "engine/system_description.hpp"
#include "run_command.hpp"

extern char** environ;

namespace cosim {
namespace {

namespace fs = std::filesystem;
const fs::path fmu_dir = COSIM_TEST_FMU_DIR;
const fs::path cosim_exe = COSIM_EXE;

// A private folder per test, used as TMPDIR so that "no extraction directory left" can be checked.
struct Scratch {
    fs::path root;
    Scratch() {
        std::string pattern = (fs::temp_directory_path() / "cosim_hostile_XXXXXX").string();
        root = ::mkdtemp(pattern.data());
        fs::create_directory(root / "tmp");
    }
    ~Scratch() { fs::remove_all(root); }
    fs::path ssd(const std::string& elements, const std::string& name = "system.ssd") const {
        const fs::path path = root / name;
        std::ofstream(path) << R"(<?xml version="1.0" encoding="UTF-8"?>
<ssd:SystemStructureDescription xmlns:ssd="http://ssp-standard.org/SSP1/SystemStructureDescription"
    xmlns:ssc="http://ssp-standard.org/SSP1/SystemStructureCommon" version="1.0" name="test">
  <ssd:System name="test"><ssd:Elements>)"
                            << elements << R"(</ssd:Elements></ssd:System>
  <ssd:DefaultExperiment startTime="0" stopTime="1"/>
</ssd:SystemStructureDescription>
)";
        return path;
    }
};

const std::string ball = R"(<ssd:Component name="ball" source="test_ball.fmu"/>)";
const std::string gain = R"(<ssd:Component name="gain" source="test_gain.fmu"/>)";

RunOptions options_for(const fs::path& ssd) {
    RunOptions o;
    o.ssd = ssd;
    o.system.fmu_dirs = {fmu_dir};
    o.progress = false;
    return o;
}

void expect_refused(const RunOptions& o, const std::string& says) {
    std::ostringstream report;
    try {
        run_system(o, report);
        ADD_FAILURE() << "accepted; report: " << report.str();
    } catch (const CosimError& e) {
        EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
    }
}

TEST(CosimHostile, RunsThatDoNothingAreRefused) {
    Scratch s;
    auto o = options_for(s.ssd(ball));
    o.stop_time = std::numeric_limits<double>::infinity();
    expect_refused(o, "must be finite");
    o = options_for(s.ssd(ball));
    o.stop_time = 1e300;
    o.output_interval = 1e-300;
    expect_refused(o, "more than the limit of");
    o = options_for(s.ssd(ball));
    o.stop_time = 0.01;
    o.output_interval = 5.0;
    expect_refused(o, "longer than the run");
    o = options_for(s.ssd(ball));
    o.system.co_simulation = {"ghost"};
    expect_refused(o, "--cs ghost");
    o = options_for(s.ssd(ball));
    o.output_interval = -1.0;
    expect_refused(o, "positive");
}

TEST(CosimHostile, HugeOutputIsRefusedWithoutForce) {
    // --stop-time 1e9 --output-interval 1e-6: 1e15 rows, refused before a row is written.
    Scratch s;
    auto o = options_for(s.ssd(ball));
    o.stop_time = 1e9;
    o.output_interval = 1e-6;
    o.csv = s.root / "out.csv";
    expect_refused(o, "--force");
    EXPECT_FALSE(fs::exists(s.root / "out.csv") && fs::file_size(s.root / "out.csv") > 0);
}

TEST(CosimHostile, AFullDiskIsAnErrorNamingTheFile) {
    Scratch s;
    auto o = options_for(s.ssd(ball));
    o.csv = "/dev/full";
    o.force = true;  // /dev reports little free space; the write itself must fail and say so
    expect_refused(o, "/dev/full");
}

TEST(CosimHostile, DoctypeInAnSsdIsRefused) {
    Scratch s;
    const fs::path path = s.root / "doctype.ssd";
    std::ofstream(path) << R"(<?xml version="1.0"?>
<!DOCTYPE x [<!ENTITY e "entity">]>
<ssd:SystemStructureDescription xmlns:ssd="http://ssp-standard.org/SSP1/SystemStructureDescription" version="1.0" name="x">
<ssd:System name="&e;"/></ssd:SystemStructureDescription>)";
    try {
        read_system_description(path);
        ADD_FAILURE() << "a DOCTYPE was accepted";
    } catch (const CosimError& e) {
        EXPECT_NE(std::string(e.what()).find("DOCTYPE"), std::string::npos) << e.what();
    }
}

TEST(CosimHostile, CsvFieldsAreQuotedPerRfc4180AndReadBack) {
    EXPECT_EQ(csv_field("plain.name"), "plain.name");
    EXPECT_EQ(csv_field("a,b"), "\"a,b\"");
    EXPECT_EQ(csv_field("say \"hi\""), "\"say \"\"hi\"\"\"");
    EXPECT_EQ(csv_field("two\nlines"), "\"two\nlines\"");
    Scratch s;
    const fs::path file = s.root / "q.csv";
    std::ofstream(file) << "time," << csv_field("c.x,y") << "," << csv_field("c.\"q\"") << "\n0,1,2\n0.5,3,4\n";
    const CsvTable t = read_csv(file);
    ASSERT_EQ(t.names.size(), 3u);
    EXPECT_EQ(t.names[1], "c.x,y");
    EXPECT_EQ(t.names[2], "c.\"q\"");
    EXPECT_EQ(t.columns[2][1], 4.0);
    // Cells padded with blanks (OMSimulator's CSV) read as their number; text reads as NaN.
    std::ofstream(file) << "time,a,b\n0, 13 ,x\n";
    const CsvTable padded = read_csv(file);
    EXPECT_EQ(padded.columns[1][0], 13.0);
    EXPECT_TRUE(std::isnan(padded.columns[2][0]));
}

// The cosim executable as a child with stdout and stderr in files and TMPDIR pointed at `tmp`.
struct Child {
    pid_t pid = -1;
    Child(const std::vector<std::string>& args, const fs::path& out, const fs::path& err, const fs::path& tmp) {
        posix_spawn_file_actions_t actions;
        posix_spawn_file_actions_init(&actions);
        posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
        posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
        std::vector<std::string> env_strings = {"TMPDIR=" + tmp.string()};
        for (char** e = environ; *e; ++e)
            if (std::string(*e).rfind("TMPDIR=", 0) != 0) env_strings.emplace_back(*e);
        std::vector<char*> env;
        for (auto& e : env_strings) env.push_back(e.data());
        env.push_back(nullptr);
        std::vector<std::string> all = {cosim_exe.string()};
        all.insert(all.end(), args.begin(), args.end());
        std::vector<char*> argv;
        for (auto& a : all) argv.push_back(a.data());
        argv.push_back(nullptr);
        if (posix_spawn(&pid, cosim_exe.c_str(), &actions, nullptr, argv.data(), env.data()) != 0) pid = -1;
        posix_spawn_file_actions_destroy(&actions);
    }
    int wait_status() {
        int status = 0;
        ::waitpid(pid, &status, 0);
        return status;
    }
};

std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

TEST(CosimHostile, StdoutOnAFullDiskIsAnError) {
    Scratch s;
    // `cosim info` prints the interface to stdout: to /dev/full it must fail, not exit 0.
    Child child({"info", (fmu_dir / "test_ball.fmu").string()}, "/dev/full", s.root / "err", s.root / "tmp");
    ASSERT_GT(child.pid, 0);
    const int status = child.wait_status();
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_NE(WEXITSTATUS(status), 0);
    EXPECT_NE(slurp(s.root / "err").find("standard output"), std::string::npos) << slurp(s.root / "err");
}

TEST(CosimHostile, SigtermClosesTheCsvPrintsStatisticsAndRemovesExtractionDirectories) {
    Scratch s;
    const fs::path csv = s.root / "out.csv";
    // Paced to the wall clock (--realtime): 60 s of simulated time, so the signal comes mid-run.
    Child child({"run", s.ssd(ball).string(), "--fmu-dir", fmu_dir.string(), "--stop-time", "60", "--output-interval",
                 "0.01", "--realtime", "--output", csv.string()},
                s.root / "out", s.root / "err", s.root / "tmp");
    ASSERT_GT(child.pid, 0);
    // The CSV exists once the system is loaded (at most 30 s on a loaded machine); a few rows later
    // (they sit in the stream's buffer), interrupt.
    for (int i = 0; i < 300 && !fs::exists(csv); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(100));
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    ::kill(child.pid, SIGTERM);
    const int status = child.wait_status();
    ASSERT_TRUE(WIFEXITED(status)) << "killed by the signal instead of stopping";
    EXPECT_EQ(WEXITSTATUS(status), 128 + SIGTERM);
    EXPECT_NE(slurp(s.root / "out").find("interrupted"), std::string::npos) << slurp(s.root / "out");
    const std::string text = slurp(csv);
    ASSERT_FALSE(text.empty());
    EXPECT_EQ(text.back(), '\n') << "the CSV ends in the middle of a row";
    const CsvTable table = read_csv(csv);
    EXPECT_GE(table.rows(), 1u);
    EXPECT_TRUE(fs::is_empty(s.root / "tmp")) << "an extraction directory was left behind";
}

// --- issue 24: outputs never destroy inputs, and signals act at once ---

// The file's bytes, to compare before and after a refused command.
void expect_unchanged(const fs::path& file, const std::string& before) {
    EXPECT_TRUE(fs::is_regular_file(file)) << file;
    EXPECT_EQ(slurp(file), before) << file << " was changed";
}

TEST(CosimHostile, RunOutputOverAnInputIsRefused) {
    Scratch s;
    const fs::path ssd = s.ssd(ball);
    const std::string system = slurp(ssd);
    auto o = options_for(ssd);
    o.csv = ssd;  // cosim run sys.ssd --output sys.ssd
    expect_refused(o, "same file as the input");
    expect_unchanged(ssd, system);
    // Through another name of the same file (a hard link): compared by device and inode.
    fs::create_hard_link(ssd, s.root / "alias.csv");
    o.csv = s.root / "alias.csv";
    expect_refused(o, "same file as the input");
    expect_unchanged(ssd, system);
    // One of its FMUs, found beside the .ssd.
    fs::copy_file(fmu_dir / "test_ball.fmu", s.root / "test_ball.fmu");
    const std::string fmu = slurp(s.root / "test_ball.fmu");
    o.csv = s.root / "test_ball.fmu";
    expect_refused(o, "same file as the input");
    expect_unchanged(s.root / "test_ball.fmu", fmu);
}

TEST(CosimHostile, SimulateOutputOverItsFmuIsRefused) {
    Scratch s;
    fs::copy_file(fmu_dir / "test_ball.fmu", s.root / "ball.fmu");
    const std::string fmu = slurp(s.root / "ball.fmu");
    Child child({"simulate", (s.root / "ball.fmu").string(), "--output", (s.root / "ball.fmu").string()},
                s.root / "out", s.root / "err", s.root / "tmp");
    ASSERT_GT(child.pid, 0);
    const int status = child.wait_status();
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_NE(WEXITSTATUS(status), 0);
    EXPECT_NE(slurp(s.root / "err").find("same file as the input"), std::string::npos) << slurp(s.root / "err");
    expect_unchanged(s.root / "ball.fmu", fmu);
}

TEST(CosimHostile, ARefusedRunLeavesAnExistingCsvAlone) {
    Scratch s;
    const fs::path csv = s.root / "results.csv";
    std::ofstream(csv) << "time,ball.h\n0,1\n";
    const std::string before = slurp(csv);
    auto o = options_for(s.ssd(ball));
    o.csv = csv;
    o.columns = {"ball.hh"};  // a typo
    expect_refused(o, "no variable named 'hh'");
    expect_unchanged(csv, before);
    EXPECT_EQ(std::distance(fs::directory_iterator(s.root), fs::directory_iterator()), 3)
        << "a temporary file was left beside the CSV";  // system.ssd, results.csv, tmp/
}

TEST(CosimHostile, PackNeverReplacesItsInputs) {
    Scratch s;
    fs::copy_file(fmu_dir / "test_ball.fmu", s.root / "test_ball.fmu");
    const fs::path ssd = s.ssd(ball);
    const std::string system = slurp(ssd), fmu = slurp(s.root / "test_ball.fmu");
    PackOptions options;
    options.oms_step = 0.01;
    for (const fs::path& target : {ssd, s.root / "test_ball.fmu"}) {
        std::ostringstream out;
        try {
            pack_system(ssd, target, options, out);
            ADD_FAILURE() << "-o " << target << " was accepted";
        } catch (const CosimError& e) {
            EXPECT_NE(std::string(e.what()).find("same file as the input"), std::string::npos) << e.what();
        }
    }
    expect_unchanged(ssd, system);
    expect_unchanged(s.root / "test_ball.fmu", fmu);
}

// A run whose only output point after the start is its end, with many events before it (the ball's
// 0.25 s ticks and its bounces): a signal used to wait for that output point.
std::vector<std::string> long_run(const Scratch& s, const fs::path& csv) {
    return {"run",   s.ssd(ball).string(),       "--fmu-dir", fmu_dir.string(), "--stop-time",
            "1e6",   "--output-interval",        "1e6",       "--set",          "ball.e=1",
            "--set", "ball.max_bounces=1000000", "--output",  csv.string()};
}

void wait_for_rows(const fs::path& csv) {
    // The CSV takes its name at its first row; flushed within about a second after.
    for (int i = 0; i < 600 && (!fs::exists(csv) || fs::file_size(csv) == 0); ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
}

TEST(CosimHostile, SignalsActBetweenOutputPoints) {
    for (const int sig : {SIGTERM, SIGHUP, SIGINT}) {
        Scratch s;
        const fs::path csv = s.root / "out.csv";
        Child child(long_run(s, csv), s.root / "out", s.root / "err", s.root / "tmp");
        ASSERT_GT(child.pid, 0);
        wait_for_rows(csv);
        ::kill(child.pid, sig);
        const int status = child.wait_status();
        ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << sig << " instead of stopping";
        EXPECT_EQ(WEXITSTATUS(status), 128 + sig) << slurp(s.root / "err");
        EXPECT_NE(slurp(s.root / "out").find("interrupted"), std::string::npos) << slurp(s.root / "out");
        const CsvTable table = read_csv(csv);
        EXPECT_EQ(table.rows(), 1u);  // the start; the next output point is the end
        EXPECT_TRUE(fs::is_empty(s.root / "tmp")) << "an extraction directory was left behind";
    }
}

TEST(CosimHostile, ASecondSignalAbortsWithItsOwnCodeAndRemovesTheFolders) {
    Scratch s;
    const fs::path csv = s.root / "out.csv";
    Child child(long_run(s, csv), s.root / "out", s.root / "err", s.root / "tmp");
    ASSERT_GT(child.pid, 0);
    wait_for_rows(csv);
    // Two signals at once: the second may come before the run has unwound from the first.
    ::kill(child.pid, SIGINT);
    ::kill(child.pid, SIGHUP);
    const int status = child.wait_status();
    ASSERT_TRUE(WIFEXITED(status)) << "killed by the signal";
    // Either one was noticed and the run stopped cleanly before the other came (pending signals arrive
    // in either order), or the second aborted it.
    const int code = WEXITSTATUS(status);
    EXPECT_TRUE(code == 128 + SIGINT || code == 128 + SIGHUP || code == aborted_exit_code)
        << code << "; " << slurp(s.root / "err");
    EXPECT_TRUE(fs::is_empty(s.root / "tmp")) << "an extraction directory was left behind";
    EXPECT_EQ(read_csv(csv).rows(), 1u) << "the row flushed before the signal was lost";
}

TEST(CosimHostile, RowsAreOnDiskBeforeASigkill) {
    Scratch s;
    const fs::path csv = s.root / "out.csv";
    Child child(long_run(s, csv), s.root / "out", s.root / "err", s.root / "tmp");
    ASSERT_GT(child.pid, 0);
    wait_for_rows(csv);  // without the flush the first row stays in the stream's buffer until the end
    ::kill(child.pid, SIGKILL);
    child.wait_status();
    const CsvTable table = read_csv(csv);
    EXPECT_EQ(table.rows(), 1u);
}

}  // namespace
}  // namespace cosim
