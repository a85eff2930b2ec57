// A board emulator: the block this executable was linked with (fmu::make_model) served over UDP or
// a pseudo-terminal with the hardware-bridge codec, as firmware would. Prints where it listens on
// the first line of stdout ("udp 127.0.0.1:PORT" or "pty /dev/pts/N") and serves until stopped,
// --max-frames requests or --idle-timeout seconds without a frame.
#include <CLI/CLI.hpp>

#include <charconv>
#include <iostream>

#include "emulator/board_emulator.hpp"

int main(int argc, char** argv) {
    CLI::App app{"Board emulator: one block behind the hardware-bridge wire format"};
    std::string udp;
    bool pty = false;
    std::vector<std::string> settings;
    bridge::ServeOptions options;
    app.add_option("--udp", udp, "Listen on HOST:PORT (PORT 0: any free port, printed)");
    app.add_flag("--pty", pty, "Create a pseudo-terminal (SLIP frames) and print its path");
    app.add_option("--set", settings, "parameter=value of the block (repeatable)");
    app.add_option("--drop-every", options.drop_every, "Leave every N-th request unanswered");
    app.add_option("--delay-ms", options.delay_ms, "Delay each reply by this many milliseconds");
    app.add_option("--max-frames", options.max_frames, "Exit after this many requests");
    app.add_option("--idle-timeout", options.idle_timeout_s, "Exit after this many seconds without a frame");
    CLI11_PARSE(app, argc, argv);
    options.log = &std::cerr;
    try {
        if (udp.empty() == !pty) throw std::runtime_error("give exactly one of --udp HOST:PORT and --pty");
        bridge::BoardEmulator board(fmu::make_model(), settings);
        std::unique_ptr<bridge::Link> link;
        if (pty) {
            auto stream = bridge::StreamLink::open_pty();
            std::cout << "pty " << stream->path() << std::endl;
            link = std::move(stream);
        } else {
            const auto colon = udp.rfind(':');
            int port = -1;
            if (colon != std::string::npos) std::from_chars(udp.data() + colon + 1, udp.data() + udp.size(), port);
            if (port < 0 || port > 65535) throw std::runtime_error("--udp expects HOST:PORT, got '" + udp + "'");
            auto socket = bridge::UdpLink::bind(udp.substr(0, colon), static_cast<std::uint16_t>(port));
            std::cout << "udp " << udp.substr(0, colon) << ":" << socket->port() << std::endl;
            link = std::move(socket);
        }
        const auto s = bridge::serve(board, *link, options);
        std::cerr << "board: " << s.requests << " requests, " << s.replies << " replies, " << s.dropped << " dropped, "
                  << s.rejected << " rejected\n";
        return 0;
    } catch (const std::exception& e) {
        std::cerr << "board: " << e.what() << "\n";
        return 1;
    }
}
