// SIGINT, SIGTERM and SIGHUP end a command gracefully. A thread of its own takes the signals (they are
// blocked in every other thread), records the first and asks the loader to stop extracting; the
// execution checks between integrator steps and at every event (and every right-hand side), every wait
// (bridge frames, real-time pacing, campaign workers) checks at least every wait_slice, and the
// command unwinds: the CSV keeps every row computed, statistics are printed, every extraction
// directory is removed, and the exit code is 128 + signal (130, 143, 129). A second signal aborts at
// once without unwinding: the signal thread removes the process's private temporary folder (every
// extraction directory lives below it) and exits with aborted_exit_code.
#pragma once

#include <chrono>
#include <stdexcept>

namespace cosim {

// Thrown at the next check after a signal; main() turns it into exit code 128 + signal.
class Interrupted : public std::runtime_error {
public:
    explicit Interrupted(int signal);
    int signal() const noexcept { return signal_; }

private:
    int signal_;
};

// The exit code of a command aborted by a second signal (told apart from a clean stop's 128 + signal).
inline constexpr int aborted_exit_code = 125;
// The longest a wait goes without checking for a signal.
inline constexpr std::chrono::milliseconds wait_slice{50};

// Blocks SIGINT, SIGTERM and SIGHUP in the calling thread (and the threads it starts later) and takes
// them on a thread of its own. Call it before any other thread is started. Idempotent.
void install_interrupt_handlers();
// Makes a private folder below the temporary directory the process's TMPDIR (so every extraction
// directory, the master's and the FMUs', lives below it); it is removed at exit and on a second signal.
// Named cosim_<host>_<pid>_XXXXXX: first it removes the folders of this host and user whose process is gone
// (killed with SIGKILL, which no process can clean up after).
void use_private_temp_directory();
int interrupt_signal() noexcept;  // 0 until a signal arrived
void throw_if_interrupted();
// Sleeps until `due`, throwing Interrupted within wait_slice of a signal.
void sleep_until_or_interrupted(std::chrono::steady_clock::time_point due);
// For tests: forget an earlier signal; record one as the signal thread does.
void clear_interrupt() noexcept;
void record_interrupt(int signal) noexcept;

}  // namespace cosim
