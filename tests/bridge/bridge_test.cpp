// The master's HardwareBridge against the board emulator, in this process on a thread, over UDP on
// 127.0.0.1 (a free port picked by the kernel) and over a pseudo-terminal. The block is the small
// sampler (y = k u latched every sample_period), fed by an integrator whose output is 1 + t / tau,
// so every expected value is a hand calculation; the all-FMU run of the same system is the reference
// for "identical results".
#include <gtest/gtest.h>

#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <thread>

#include "emulator/board_emulator.hpp"
#include "engine/cosim_error.hpp"
#include "engine/execution.hpp"
#include "engine/hardware_bridge.hpp"
#include "engine/interrupt.hpp"
#include "engine/system.hpp"
#include "engine/system_description.hpp"

namespace {

using namespace cosim;

const std::filesystem::path test_fmu_dir = BRIDGE_TEST_FMU_DIR;

struct SsdFile {
    std::filesystem::path path;
    explicit SsdFile(const std::string& sampler_annotation) {
        path = std::filesystem::temp_directory_path() /
               ("bridge_test_" + std::to_string(::getpid()) + "_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".ssd");
        std::ofstream(path) << R"(<?xml version="1.0" encoding="UTF-8"?>
<ssd:SystemStructureDescription xmlns:ssd="http://ssp-standard.org/SSP1/SystemStructureDescription"
    xmlns:ssc="http://ssp-standard.org/SSP1/SystemStructureCommon"
    xmlns:ssv="http://ssp-standard.org/SSP1/SystemStructureParameterValues" version="1.0" name="t">
  <ssd:System name="t">
    <ssd:Elements>
      <ssd:Component name="gain" source="test_gain.fmu"/>
      <ssd:Component name="int" source="test_integrator.fmu"/>
      <ssd:Component name="s" source="test_sampler.fmu">)"
                            << sampler_annotation << R"(</ssd:Component>
    </ssd:Elements>
    <ssd:Connections>
      <ssd:Connection startElement="gain" startConnector="y" endElement="int" endConnector="u"/>
      <ssd:Connection startElement="int" startConnector="y" endElement="s" endConnector="u[1]"/>
      <ssd:Connection startElement="gain" startConnector="y" endElement="s" endConnector="u[2]"/>
    </ssd:Connections>
  </ssd:System>
  <ssd:DefaultExperiment startTime="0" stopTime="0.5"/>
</ssd:SystemStructureDescription>
)";
    }
    ~SsdFile() { std::filesystem::remove(path); }
};

std::string annotation(const std::string& attributes) {
    return R"(<ssd:Annotations><ssc:Annotation type="org.pvatt.hardware-bridge"><hw:Bridge xmlns:hw="urn:pvatt:hardware-bridge" )" +
           attributes + "/></ssc:Annotation></ssd:Annotations>";
}

// Every output of the sampler at every output point.
struct Recorder : Observer {
    std::vector<std::vector<double>> rows;
    void sample(double t, System& system) override {
        auto& c = system.components()[system.component_index("s")];
        const auto& md = c.description();
        rows.push_back({t, c.instance->get_real(md.find_variable("y[1]")->value_reference),
                        c.instance->get_real(md.find_variable("y[2]")->value_reference),
                        static_cast<double>(c.instance->get_integer(md.find_variable("samples")->value_reference)),
                        c.instance->get_boolean(md.find_variable("valid")->value_reference) ? 1.0 : 0.0});
    }
};

struct Result {
    Recorder recorder;
    RunStatistics stats;
    LinkStatistics link;
};

Result run(const std::string& sampler_annotation, std::optional<int> port = std::nullopt, bool realtime = false,
           std::vector<std::string> settings = {}) {
    SsdFile ssd(sampler_annotation);
    SystemOptions options;
    options.settings = std::move(settings);
    options.fmu_dirs = {test_fmu_dir};
    options.bridge_port = port;
    System system(read_system_description(ssd.path), options);
    ExecutionOptions ex;
    ex.stop_time = 0.5;
    ex.output_interval = 0.025;
    ex.relative_tolerance = 1e-9;
    ex.realtime = realtime;
    Result r;
    r.stats = Execution(system, ex).run({&r.recorder});
    for (const auto& c : r.stats.components)
        if (c.link) r.link = *c.link;
    return r;
}

// The emulator serving the sampler block on a thread until the test ends (at most 20 s).
struct Board {
    std::unique_ptr<bridge::Link> link;
    bridge::BoardEmulator emulator;
    std::atomic<bool> stop{false};
    bridge::ServeStatistics stats;
    std::thread thread;
    Board(std::unique_ptr<bridge::Link> l, bridge::ServeOptions options, const std::vector<std::string>& settings = {})
        : link(std::move(l)), emulator(fmu::make_model(), settings) {
        options.stop = &stop;
        options.idle_timeout_s = 20.0;
        thread = std::thread([this, options] { stats = bridge::serve(emulator, *link, options); });
    }
    ~Board() {
        stop = true;
        thread.join();
    }
};

std::unique_ptr<bridge::UdpLink> free_udp() {
    return bridge::UdpLink::bind("127.0.0.1", 0);
}

void expect_identical(const Recorder& a, const Recorder& b) {
    ASSERT_EQ(a.rows.size(), b.rows.size());
    for (std::size_t i = 0; i < a.rows.size(); ++i)
        EXPECT_EQ(a.rows[i], b.rows[i]) << "row " << i << " t = " << a.rows[i][0];
}

// Hand calculation: gain.y = k u = 2 * 1 (its defaults: k = 2, u starts at 1); int.y = 1 + 2 t / tau
// with tau = 1 and x(0) = 1; the sampler latches y1 = 2 (1 + 2 t_k), y2 = 4 at t_k = 0.05 k. At t = 0.25 the last sample is the
// sixth (t_k = 0.25 itself, processed at that instant).
TEST(Udp, BridgedBlockGivesTheFmusResults) {
    const Result fmu = run("");
    auto link = free_udp();
    const int port = link->port();
    Board board(std::move(link), {});
    const Result hw = run(annotation(R"(transport="udp" host="127.0.0.1" port="1" timeout_ms="2000")"), port);
    expect_identical(fmu.recorder, hw.recorder);
    const auto& row = hw.recorder.rows[10];
    ASSERT_NEAR(row[0], 0.25, 1e-12);
    EXPECT_NEAR(row[1], 2.0 * 1.5, 1e-7);
    EXPECT_EQ(row[2], 4.0);
    EXPECT_EQ(row[3], 6.0);
    EXPECT_EQ(row[4], 1.0);
    // Samples at 0, 0.05, ..., 0.5: eleven frames, all answered.
    EXPECT_EQ(hw.link.exchanges, 11);
    EXPECT_EQ(hw.link.answered, 11);
    EXPECT_EQ(hw.link.misses, 0);
    EXPECT_EQ(hw.stats.time_events, fmu.stats.time_events);
    EXPECT_LE(hw.link.latency_min, hw.link.latency_median);
    EXPECT_LE(hw.link.latency_median, hw.link.latency_p95);
    EXPECT_LE(hw.link.latency_p95, hw.link.latency_max);
}

TEST(Pty, BridgedBlockGivesTheFmusResultsOverSerialFrames) {
    const Result fmu = run("");
    auto link = bridge::StreamLink::open_pty();
    const std::string path = link->path();
    Board board(std::move(link), {});
    const Result hw = run(annotation(R"(transport="serial" device=")" + path + R"(" baud="115200" timeout_ms="2000")"));
    expect_identical(fmu.recorder, hw.recorder);
    EXPECT_EQ(hw.link.answered, 11);
    EXPECT_EQ(hw.link.malformed, 0);
}

// Every third request goes unanswered (requests 3, 6, 9: t = 0.10, 0.25, 0.40). With policy hold the
// outputs keep the previous reply's: at t = 0.25 that of t = 0.20, y1 = 2 * 1.4 and 5 samples.
TEST(Udp, LostFramesAreHeldAndCounted) {
    auto link = free_udp();
    const int port = link->port();
    bridge::ServeOptions options;
    options.drop_every = 3;
    Board board(std::move(link), options);
    const Result hw = run(annotation(R"(port="1" timeout_ms="150" policy="hold")"), port);
    EXPECT_EQ(hw.link.exchanges, 11);
    EXPECT_EQ(hw.link.misses, 3);
    EXPECT_EQ(hw.link.answered, 8);
    const auto& row = hw.recorder.rows[10];
    EXPECT_NEAR(row[1], 2.0 * 1.4, 1e-7);
    EXPECT_EQ(row[3], 5.0);
    EXPECT_NEAR(hw.recorder.rows.back()[1], 2.0 * 2.0, 1e-7);  // t = 0.5 answered again
}

// Replies 60 ms late against a 30 ms timeout: every frame is missed, the late answers are counted
// when they arrive (never applied to a later frame), and hold keeps the start values to the end.
TEST(Udp, LateFramesAreCountedNotApplied) {
    auto link = free_udp();
    const int port = link->port();
    bridge::ServeOptions options;
    options.delay_ms = 60;
    Board board(std::move(link), options);
    const Result hw = run(annotation(R"(port="1" timeout_ms="30" policy="hold")"), port);
    EXPECT_EQ(hw.link.misses, 11);
    EXPECT_EQ(hw.link.answered, 0);
    EXPECT_GE(hw.link.late, 1);
    EXPECT_EQ(hw.recorder.rows.back()[3], 0.0);  // samples' start value: nothing applied
}

// A slow but timely board: each latency at least the board's 20 ms delay.
TEST(Udp, LatencyIncludesTheBoardsDelay) {
    auto link = free_udp();
    const int port = link->port();
    bridge::ServeOptions options;
    options.delay_ms = 20;
    Board board(std::move(link), options);
    const Result hw = run(annotation(R"(port="1" timeout_ms="2000")"), port);
    EXPECT_EQ(hw.link.answered, 11);
    EXPECT_GE(hw.link.latency_min, 0.020);
}

// The sample instants come from the component's sample_period as set for the run (here 0.1 s instead
// of the block's 0.05 s): frames at 0, 0.1, ..., 0.5, and the board, told the same, samples at each.
TEST(Udp, SamplePeriodSettingDrivesTheExchanges) {
    auto link = free_udp();
    const int port = link->port();
    Board board(std::move(link), {}, {"sample_period=0.1"});
    const Result hw = run(annotation(R"(port="1" timeout_ms="2000")"), port, false, {"s.sample_period=0.1"});
    EXPECT_EQ(hw.link.exchanges, 6);
    EXPECT_EQ(hw.link.answered, 6);
    // At t = 0.25 the last frame was at 0.2: y1 = 2 (1 + 2 * 0.2), after samples at 0, 0.1 and 0.2.
    EXPECT_NEAR(hw.recorder.rows[10][1], 2.0 * 1.4, 1e-7);
    EXPECT_EQ(hw.recorder.rows[10][3], 3.0);
}

// Issue 38: a value the board cannot receive is refused by name before the run, not stored and never
// sent (the run went on with the board's own value, or failed later for another reason): a String
// parameter (frames carry numbers) and an output (the board's to give). Nobody serves the port, so a
// set that got through would end in the unacknowledged configuration instead.
TEST(Udp, ValuesTheBoardCannotReceiveAreRefusedByName) {
    auto silent = free_udp();
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"s.label=abc", "s.label: a String parameter cannot cross the hardware link"},
        {"s.samples=3", "s.samples is output: only a hardware-bridged block's inputs and parameters are sent"},
    };
    for (const auto& [setting, expected] : cases) {
        try {
            run(annotation(R"(port="1" timeout_ms="20")"), silent->port(), false, {setting});
            ADD_FAILURE() << setting << " should have been refused";
        } catch (const CosimError& e) {
            EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << setting << ": " << e.what();
        }
    }
}

// A silent board (a bound socket nobody answers on): policy stop gives up after max_misses.
TEST(Udp, StopPolicyErrorsAfterConsecutiveMisses) {
    // A board that takes its configuration but answers no request.
    auto link = free_udp();
    const int port = link->port();
    bridge::ServeOptions deaf;
    deaf.drop_every = 1;
    Board board(std::move(link), deaf);
    try {
        run(annotation(R"(port="1" timeout_ms="20" max_misses="3" policy="stop")"), port);
        FAIL() << "the run should have stopped";
    } catch (const CosimError& e) {
        EXPECT_NE(std::string(e.what()).find("3 consecutive misses"), std::string::npos) << e.what();
    }
}

// A board that never answers is not run with parameters it may not have: the configuration frames the
// master sends first go unacknowledged, and the run stops before its first sample, naming the timeout.
TEST(Udp, UnacknowledgedConfigurationRefusesTheRun) {
    auto silent = free_udp();
    try {
        run(annotation(R"(port="1" timeout_ms="20")"), silent->port());
        FAIL() << "the run should have been refused";
    } catch (const CosimError& e) {
        EXPECT_NE(std::string(e.what()).find("did not acknowledge its configuration"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("timeout_ms"), std::string::npos) << e.what();
    }
}

// A board that answers garbage: a reply with a broken CRC, then an oversized datagram. Both are
// rejected with the codec's reason, counted, and with policy stop the run ends naming the last one.
TEST(Udp, MalformedRepliesAreRejected) {
    auto board = free_udp();
    const int port = board->port();
    std::atomic<bool> stop{false};
    std::thread fake([&] {
        for (int i = 0; i < 2 && !stop;) {
            const auto request = board->receive(bridge::Clock::now() + std::chrono::seconds(5));
            if (!request) return;
            bridge::Frame reply = bridge::decode(*request);
            if (reply.type == bridge::FrameType::configure) {  // take the configuration, as a board does
                reply.type = bridge::FrameType::configured;
                reply.values.clear();
                board->send(bridge::encode(reply));
                continue;
            }
            ++i;
            reply.type = bridge::FrameType::reply;
            reply.values.assign(3, 0.0);
            auto bytes = bridge::encode(reply);
            if (i == 0)
                bytes[bridge::header_size] ^= 0x01;
            else
                bytes.resize(bridge::max_frame_size + 100, 0x42);
            board->send(bytes);
        }
    });
    try {
        run(annotation(R"(port="1" timeout_ms="200" max_misses="2" policy="stop")"), port);
        ADD_FAILURE() << "the run should have stopped";
    } catch (const CosimError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("2 consecutive misses"), std::string::npos) << what;
        EXPECT_NE(what.find("exceeds the maximum"), std::string::npos) << what;
    }
    stop = true;
    fake.join();
}

// The emulator answering on a thread and noting when each request arrives, until `requests` have, and
// when it acknowledged its configuration (after `configure_delay`: a slow board, QEMU booting firmware).
struct TimedBoard {
    std::unique_ptr<bridge::UdpLink> server = free_udp();
    bridge::BoardEmulator emulator{fmu::make_model()};
    std::vector<bridge::Clock::time_point> arrivals;
    bridge::Clock::time_point acknowledged{};
    std::thread thread;
    TimedBoard(std::size_t requests, std::chrono::milliseconds configure_delay) {
        thread = std::thread([this, requests, configure_delay] {
            while (arrivals.size() < requests) {
                const auto bytes = server->receive(bridge::Clock::now() + std::chrono::seconds(5));
                if (!bytes) return;
                const bridge::Frame frame = bridge::decode(*bytes);
                if (frame.type == bridge::FrameType::configure) {
                    std::this_thread::sleep_for(configure_delay);
                    acknowledged = bridge::Clock::now();
                } else if (frame.type == bridge::FrameType::request) {
                    arrivals.push_back(bridge::Clock::now());
                }
                server->send(bridge::encode(emulator.answer(frame)));
            }
        });
    }
    void join() { thread.join(); }
    ~TimedBoard() {
        if (thread.joinable()) thread.join();
    }
};

// --realtime: each request leaves at its sample instant's wall time, so the board sees frame k no
// earlier than k * sample_period after the run began (which is after `before`). A lower bound only:
// a late wall clock (a loaded machine) is not a fault.
TEST(Udp, RealtimePacesEachExchange) {
    TimedBoard board(11, std::chrono::milliseconds(0));
    const auto before = bridge::Clock::now();
    const Result hw = run(annotation(R"(port="1" timeout_ms="2000")"), board.server->port(), true);
    board.join();
    ASSERT_EQ(board.arrivals.size(), 11u);
    for (std::size_t k = 1; k < board.arrivals.size(); ++k)
        EXPECT_GE(std::chrono::duration<double>(board.arrivals[k] - before).count(), 0.05 * static_cast<double>(k))
            << "frame " << k;
    EXPECT_EQ(hw.link.answered, 11);
}

// A board slow to take its configuration delays the run's start, not its samples: --realtime's wall clock
// starts once the board has acknowledged, so frame k still leaves k sample periods after that
// acknowledgement (a lower bound again; the old clock started before the configuration and sent the first
// frames at once to catch up).
TEST(Udp, RealtimeClockStartsAfterTheBoardIsConfigured) {
    TimedBoard board(11, std::chrono::milliseconds(300));
    const Result hw = run(annotation(R"(port="1" timeout_ms="2000")"), board.server->port(), true);
    board.join();
    ASSERT_EQ(board.arrivals.size(), 11u);
    for (std::size_t k = 0; k < board.arrivals.size(); ++k)
        EXPECT_GE(std::chrono::duration<double>(board.arrivals[k] - board.acknowledged).count(),
                  0.05 * static_cast<double>(k))
            << "frame " << k;
    EXPECT_EQ(hw.link.answered, 11);
}

// A sample period that the instants' tolerance cannot resolve, told to a board that takes it (issue 24):
// the master used to count its instants one at a time, for ever. It is refused before the board is
// configured, naming the limit of the count.
// A board that acknowledges any configuration (the sampler's emulator would refuse a period below its
// declared minimum) and answers requests with zeros.
struct AcknowledgingBoard {
    std::unique_ptr<bridge::UdpLink> server = free_udp();
    std::atomic<bool> stop{false};
    std::thread thread;
    AcknowledgingBoard() {
        thread = std::thread([this] {
            while (!stop) {
                const auto bytes = server->receive(bridge::Clock::now() + std::chrono::milliseconds(100));
                if (!bytes) continue;
                bridge::Frame frame = bridge::decode(*bytes);
                frame.type = frame.type == bridge::FrameType::configure ? bridge::FrameType::configured
                                                                        : bridge::FrameType::reply;
                if (frame.type == bridge::FrameType::reply) frame.values.assign(4, 0.0);
                if (frame.type == bridge::FrameType::configured) frame.values.clear();
                server->send(bridge::encode(frame));
            }
        });
    }
    ~AcknowledgingBoard() {
        stop = true;
        thread.join();
    }
};

TEST(Udp, UnresolvableSamplePeriodIsRefusedNotCounted) {
    AcknowledgingBoard board;
    const int port = board.server->port();
    for (const char* period : {"s.sample_period=1e-300", "s.sample_period=1e-13"}) {
        try {
            run(annotation(R"(port="1" timeout_ms="2000")"), port, false, {period});
            ADD_FAILURE() << period << " was run";
        } catch (const CosimError& e) {
            EXPECT_NE(std::string(e.what()).find("max_sample_index"), std::string::npos) << e.what();
        }
    }
    // The limit is the blocks' own (fmu::max_instant_index): a period it allows over the run still runs.
    EXPECT_EQ(max_sample_index, 1e11);
}

// Waiting for a board is interruptible (issue 24): a signal during a long timeout_ms ends the wait at
// once with Interrupted, not after the timeout with a link error.
TEST(Udp, SignalEndsTheWaitForASilentBoard) {
    install_interrupt_handlers();
    clear_interrupt();
    auto silent = free_udp();
    std::thread signaller([] {
        std::this_thread::sleep_for(std::chrono::milliseconds(300));
        ::kill(::getpid(), SIGINT);
    });
    try {
        run(annotation(R"(port="1" timeout_ms="60000")"), silent->port());
        ADD_FAILURE() << "the run should have been interrupted";
    } catch (const Interrupted& e) {
        EXPECT_EQ(e.signal(), SIGINT);
    } catch (const std::exception& e) {
        ADD_FAILURE() << "not an interruption: " << e.what();
    }
    signaller.join();
    clear_interrupt();
}

// The emulator's side: a bad frame is refused with a reason and the next good one still answered.
TEST(Emulator, RejectsMalformedRequestsAndGoesOn) {
    bridge::BoardEmulator board(fmu::make_model());
    EXPECT_EQ(board.input_count(), 2u);
    EXPECT_EQ(board.output_count(), 4u);
    bridge::Frame wrong;
    wrong.values = {1.0};
    try {
        board.answer(wrong);
        FAIL();
    } catch (const bridge::FrameError& e) {
        EXPECT_NE(std::string(e.what()).find("2 inputs"), std::string::npos) << e.what();
    }
    bridge::Frame good;
    good.sequence = 7;
    good.values = {1.5, -2.0};
    const auto reply = board.answer(good);
    EXPECT_EQ(reply.sequence, 7u);
    EXPECT_EQ(reply.type, bridge::FrameType::reply);
    // The first frame initializes and samples at its time: y = 2 u, one sample, valid.
    EXPECT_EQ(reply.values, (std::vector<double>{3.0, -4.0, 1.0, 1.0}));

    auto server = free_udp();
    auto client = bridge::UdpLink::connect("127.0.0.1", server->port());
    const std::vector<std::uint8_t> garbage = {'P', 'V', 1, 1, 0, 0};
    client->send(garbage);
    good.time = 0.05;
    client->send(bridge::encode(good));
    std::ostringstream log;
    bridge::ServeOptions options;
    options.max_frames = 1;
    options.idle_timeout_s = 5.0;
    options.log = &log;
    const auto stats = bridge::serve(board, *server, options);
    EXPECT_EQ(stats.rejected, 1);
    EXPECT_EQ(stats.replies, 1);
    EXPECT_NE(log.str().find("shorter"), std::string::npos) << log.str();
    const auto answer = client->receive(bridge::Clock::now() + std::chrono::seconds(5));
    ASSERT_TRUE(answer);
    EXPECT_EQ(bridge::decode(*answer).values[2], 2.0);  // the second sample, at t = 0.05

    // Sequence 1 again: a new run; the board starts over (one sample, y = 2 u) instead of going on.
    bridge::Frame restart;
    restart.sequence = 1;
    restart.values = {0.5, 0.25};
    EXPECT_EQ(board.answer(restart).values, (std::vector<double>{1.0, 0.5, 1.0, 1.0}));
}

TEST(Ssd, BridgeAnnotationIsReadAndChecked) {
    {
        SsdFile ssd(annotation(
            R"(transport="serial" device="/dev/ttyUSB0" baud="57600" timeout_ms="50" max_misses="7" policy="stop")"));
        const auto d = read_system_description(ssd.path);
        ASSERT_TRUE(d.components[2].bridge);
        EXPECT_EQ(d.components[2].bridge->transport, "serial");
        EXPECT_EQ(d.components[2].bridge->device, "/dev/ttyUSB0");
        EXPECT_EQ(d.components[2].bridge->baud, 57600);
        EXPECT_EQ(d.components[2].bridge->timeout_ms, 50);
        EXPECT_EQ(d.components[2].bridge->max_misses, 7);
        EXPECT_EQ(d.components[2].bridge->policy, "stop");
        EXPECT_FALSE(d.components[0].bridge);
    }
    {
        SsdFile ssd(annotation(R"(policy="retry")"));
        EXPECT_THROW(read_system_description(ssd.path), CosimError);
    }
    {
        SsdFile ssd(annotation(R"(port="70000")"));
        EXPECT_THROW(read_system_description(ssd.path), CosimError);
    }
}

}  // namespace
