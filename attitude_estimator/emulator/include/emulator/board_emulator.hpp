// A board in software: one block (an fmu::Model) driven through fmu::ModelRunner and answering
// request frames exactly as firmware on the DSP would: inputs from the frame (value-reference
// order), the block advanced to the frame's time with its time event processed, outputs replied.
#pragma once

#include <atomic>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "fmu/model_runner.hpp"
#include "protocol/frame.hpp"
#include "protocol/link.hpp"

namespace bridge {

class BoardEmulator {
public:
    // `settings` are "parameter=value" applied before the block initializes (the board's own
    // configuration); parameter values the master sends in configure frames are applied after them.
    explicit BoardEmulator(std::unique_ptr<fmu::Model> model, const std::vector<std::string>& settings = {});

    std::size_t input_count() const { return inputs_.size(); }
    std::size_t output_count() const { return outputs_.size(); }
    std::size_t parameter_count() const { return parameters_.size(); }
    // A request gets its reply, a configure frame its configured frame. Throws FrameError for a request
    // whose value count is not the block's input count or a configuration that is not the block's, and
    // fmu::Error when the block refuses its inputs or parameters.
    Frame answer(const Frame& request);

private:
    void set_inputs(const std::vector<double>& values);
    void apply_settings();
    void apply_configuration();
    Frame configure(const Frame& frame);

    fmu::ModelRunner runner_;
    std::vector<std::string> settings_;
    std::vector<const fmu::Variable*> inputs_, outputs_;
    std::vector<const fmu::Variable*> parameters_;  // non-String parameters, value-reference order
    std::vector<double> configuration_;             // from configure frames, applied at each run's start
    std::vector<bool> configured_;
    bool initialized_ = false;
};

struct ServeOptions {
    long drop_every = 0;                      // leave every N-th request unanswered (0: none)
    int delay_ms = 0;                         // wait this long before each reply
    long max_frames = 0;                      // return after this many requests (0: no limit)
    double idle_timeout_s = 0.0;              // return when no frame arrives for this long (0: never)
    const std::atomic<bool>* stop = nullptr;  // return when it becomes true (checked every 50 ms)
    std::ostream* log = nullptr;              // one line per rejected frame
};

struct ServeStatistics {
    long requests = 0, replies = 0, dropped = 0, rejected = 0;
    long configure_frames = 0;  // answered always: drop_every and max_frames count requests only
};

ServeStatistics serve(BoardEmulator& board, Link& link, const ServeOptions& options);

}  // namespace bridge
