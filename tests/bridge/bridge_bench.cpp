// What one exchange costs: the codec alone (encode + decode of an estimator-sized frame, 13 inputs /
// 25 outputs) and a whole request/reply over UDP on 127.0.0.1 to the emulator serving the test block
// on another thread (the latency a bridged run adds per sample when the board is instant).
#include <benchmark/benchmark.h>

#include <atomic>
#include <thread>

#include "emulator/board_emulator.hpp"
#include "protocol/frame.hpp"

namespace {

void codec_round_trip(benchmark::State& state) {
    bridge::Frame f;
    f.values.assign(static_cast<std::size_t>(state.range(0)), 0.125);
    for (auto _ : state) {
        ++f.sequence;
        auto bytes = bridge::encode(f);
        benchmark::DoNotOptimize(bridge::decode(bytes));
    }
}
BENCHMARK(codec_round_trip)->Arg(13)->Arg(25)->Arg(64);

void udp_exchange_with_emulator(benchmark::State& state) {
    auto server = bridge::UdpLink::bind("127.0.0.1", 0);
    auto client = bridge::UdpLink::connect("127.0.0.1", server->port());
    bridge::BoardEmulator board(fmu::make_model());
    std::atomic<bool> stop{false};
    bridge::ServeOptions options;
    options.stop = &stop;
    options.idle_timeout_s = 30.0;
    std::thread serving([&] { bridge::serve(board, *server, options); });
    bridge::Frame request;
    request.values = {1.0, 2.0};
    for (auto _ : state) {
        ++request.sequence;
        request.time += 0.05;
        client->send(bridge::encode(request));
        auto reply = client->receive(bridge::Clock::now() + std::chrono::seconds(1));
        if (!reply) {
            state.SkipWithError("no reply");
            break;
        }
        benchmark::DoNotOptimize(bridge::decode(*reply));
    }
    stop = true;
    serving.join();
}
BENCHMARK(udp_exchange_with_emulator)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
