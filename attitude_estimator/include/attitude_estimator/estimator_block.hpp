// The on-board attitude computer as an FMU block (attitude_estimator.fmu): a sampled-data system. At each
// sample instant t_k = t_start + k·sample_period it runs one `estimate_sample` of the core on the inputs
// present at that instant and holds the results as discrete outputs until the next instant, as the DSP's
// timer interrupt does (000 §7, fig. 11). No continuous states, no state events.
#pragma once

#include <array>
#include <cstdint>
#include <memory>

#include "attitude_estimator/estimator_data.hpp"
#include "attitude_estimator/spin_spectrum.hpp"
#include "fmu/block.hpp"

namespace attitude_estimator {

// The FFTW workspace of the spin-rate analysis, derived from two parameters and so built by the block's
// configure(). Not part of the FMU state (the history it analyses is): a copy of the block (FMU state,
// clone) keeps its own workspace, and the runtime configures a restored block before its next equation.
class SpinWorkspace {
public:
    SpinWorkspace() = default;
    SpinWorkspace(const SpinWorkspace&) {}
    SpinWorkspace& operator=(const SpinWorkspace&) { return *this; }
    ~SpinWorkspace();
    // The analyser for this window and sample period (window 0: none), built anew only when either changed.
    void configure(double sample_period, std::int32_t window);
    // The analyser configure() built; the block calls it only with a window configured.
    SpinSpectrum& spectrum() { return *spectrum_; }

private:
    std::unique_ptr<SpinSpectrum> spectrum_;
};

// The fault detection's parameters and outputs (fault_table.cpp).
void declare_fault_variables(fmu::Table<EstimatorData>& t);

class EstimatorBlock : public fmu::Block<EstimatorBlock, EstimatorData> {
public:
    static void declare(fmu::Table<EstimatorData>& t);
    static fmu::ModelInfo describe();

    void initialize(double t) override;
    fmu::EventUpdate event_update(double t, bool time_event_due) override;
    double next_time_event() const override;
    void validate() const override;
    void check_state() const override;
    // The core's configurations from the parameters (the per-sample sun-distance scaling aside).
    void configure() override;

private:
    void take_sample(double t);
    void update_spin();

    SpinWorkspace spin_;
    OnboardSettings<double> settings_{};       // (configure())
    OnboardSettings<float> settings_float_{};  // (configure())
};

}  // namespace attitude_estimator
