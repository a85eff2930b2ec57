#include "interrupt.hpp"

#include <signal.h>

#include <atomic>
#include <cstring>
#include <string>

#include "fmi_loader/limits.hpp"

namespace cosim {

namespace {

std::atomic<int> received{0};
static_assert(std::atomic<int>::is_always_lock_free, "the handler must be async-signal-safe");

extern "C" void on_signal(int signal) {
    received.store(signal, std::memory_order_relaxed);
    fmi_loader::request_cancel();
}

}  // namespace

Interrupted::Interrupted(int signal)
    : std::runtime_error(std::string("interrupted by ") + (signal == SIGINT    ? "SIGINT"
                                                           : signal == SIGTERM ? "SIGTERM"
                                                                               : "a signal")),
      signal_(signal) {}

void install_interrupt_handlers() {
    struct sigaction action;
    std::memset(&action, 0, sizeof action);
    action.sa_handler = on_signal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESETHAND;  // one-shot: a second Ctrl-C ends the process at once
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
}

int interrupt_signal() noexcept {
    return received.load(std::memory_order_relaxed);
}

void throw_if_interrupted() {
    if (const int s = interrupt_signal()) throw Interrupted(s);
}

void clear_interrupt() noexcept {
    received.store(0, std::memory_order_relaxed);
    fmi_loader::clear_cancel();
}

}  // namespace cosim
