// SIGINT and SIGTERM end a run gracefully: the handler only records the signal (and asks the loader
// to stop extracting); the run notices at its next output point, closes the CSV with what was
// computed, prints its statistics and unwinds, which removes every extraction directory. A second
// signal kills at once (the handlers are one-shot).
#pragma once

#include <stdexcept>

namespace cosim {

// Thrown at the first output point after a signal; main() turns it into exit code 128 + signal.
class Interrupted : public std::runtime_error {
public:
    explicit Interrupted(int signal);
    int signal() const noexcept { return signal_; }

private:
    int signal_;
};

void install_interrupt_handlers();
int interrupt_signal() noexcept;  // 0 until a signal arrived
void throw_if_interrupted();
// For tests: forget an earlier signal.
void clear_interrupt() noexcept;

}  // namespace cosim
