// Spin frequencies of a tumbling box from the spectrum of its acquired sun vector (000 §4: "the attitude
// motion (angular frequencies of the satellite) can be evaluated from the Fast Fourier Transform (FFT) of
// the acquired data").
//
// Seed scenario: s = (sin φ sin θ, cos φ sin θ, cos θ) in body axes with φ = φ̇ t, θ = θ̇ t. By the
// product-to-sum identities
//   s_z = cos θ̇t                                   → one line at θ̇
//   s_x = ½ [cos (θ̇ − φ̇)t − cos (θ̇ + φ̇)t]          → lines at θ̇ − φ̇ and θ̇ + φ̇, amplitude ½ each
//   s_y = ½ [sin (θ̇ + φ̇)t + sin (θ̇ − φ̇)t]          → the same pair
// so the z line gives θ̇ and half the distance of the x/y pair gives φ̇ (docs/rates.md for the whole logic).
//
// Not part of the heap-free core (attitude_estimator_core): this is library attitude_estimator_rates, built
// on FFTW3. Every buffer and the FFTW plan are allocated ONCE, in the constructor. push() and analyze() do
// not allocate (tested by counting malloc calls) and do not throw. Only the constructor throws
// (std::invalid_argument on bad arguments, std::bad_alloc when FFTW cannot plan).
#pragma once

#include <array>
#include <cstddef>
#include <span>

#include "attitude_estimator/types.hpp"

namespace attitude_estimator {

struct SpinSpectrumConfig {
    double sample_period = 0.05;        // s between pushed samples (the estimator's 20 Hz)
    std::size_t window = 512;           // N samples per analysis (any N >= 16; FFTW needs no power of two)
    std::size_t analysis_interval = 0;  // M: push() runs analyze() every M samples once the window is full;
                                        // 0 = only when analyze() is called
    // A line counts when BOTH hold: its amplitude (the component's sinusoid amplitude, a unit vector has
    // components in [-1, 1]) is at least min_line_amplitude, and its magnitude is at least min_snr times the
    // component's noise floor (the median magnitude of the spectrum).
    double min_line_amplitude = 0.05;
    double min_snr = 10.0;
    // The x/y pair must be centred on the z line to within this many bins (consistency check).
    double max_center_mismatch_bins = 1.0;
    // The two x/y lines have equal amplitude in the seed's form (½ each in s_x and in s_y); a pair whose
    // weaker line is below this fraction of the stronger one is not that form (status inconsistent).
    double min_pair_amplitude_ratio = 0.25;
};

enum class SpinStatus {
    ok,               // θ̇ and φ̇ identified
    window_not_full,  // fewer than N samples since construction, reset() or the last invalid sample
    no_z_line,        // no line in s_z above the floor (static sun, or a motion not of the seed's form)
    no_xy_pair,       // fewer than two lines in s_x/s_y: weak, or merged (φ̇ below about two bins)
    inconsistent,     // the x/y pair is not centred on the z line (neither θ̇ ± φ̇ nor φ̇ ± θ̇), or its two
                      // amplitudes differ by more than min_pair_amplitude_ratio
};

const char* to_string(SpinStatus s) noexcept;

struct SpectralLine {
    double frequency = 0.0;  // rad/s, interpolated between bins
    double amplitude = 0.0;  // sinusoid amplitude (Hann-window coherent gain removed), unit of the input
    double snr = 0.0;        // magnitude / noise floor of the component
    bool found = false;
};

struct SpinRates {
    double theta_dot = 0.0;       // rad/s, θ̇ (the z line)
    double phi_dot = 0.0;         // rad/s, φ̇ (half the x/y pair's distance)
    SpectralLine z_line;          // the s_z line
    SpectralLine xy_lower;        // the lower line of the s_x/s_y pair (|θ̇ − φ̇|)
    SpectralLine xy_upper;        // the upper line (θ̇ + φ̇); with no_xy_pair, the single x/y line if one was found
    double bin_width = 0.0;       // rad/s, 2π / (N T)
    double window_seconds = 0.0;  // N T
    std::size_t samples = 0;      // samples in the window when analysed (N when valid)
    bool valid = false;
    SpinStatus status = SpinStatus::window_not_full;
};

class SpinSpectrum {
public:
    // Throws std::invalid_argument unless sample_period > 0 and finite, window >= 16, min_snr >= 0,
    // min_line_amplitude >= 0, max_center_mismatch_bins > 0, 0 <= min_pair_amplitude_ratio <= 1.
    explicit SpinSpectrum(const SpinSpectrumConfig& config);
    SpinSpectrum(double sample_period, std::size_t window, std::size_t analysis_interval = 0);
    ~SpinSpectrum();
    SpinSpectrum(const SpinSpectrum&) = delete;
    SpinSpectrum& operator=(const SpinSpectrum&) = delete;
    SpinSpectrum(SpinSpectrum&& other) noexcept;
    SpinSpectrum& operator=(SpinSpectrum&& other) noexcept;

    // One sun vector per sample period, body axes (unit length expected, not normalized here). A sample that
    // is invalid (valid == false, e.g. eclipse) or not finite restarts the window: the FFT needs uniformly
    // spaced samples. Returns true when this push ran an automatic analysis (analysis_interval > 0).
    bool push(const Vec3<double>& sun, bool valid = true) noexcept;
    bool push(const Vec3<float>& sun, bool valid = true) noexcept;

    // Hann-windowed, mean-removed magnitude spectra of the last N samples, peaks, identification. The
    // result is also kept (latest()). Invalid (window_not_full) until N samples are in.
    const SpinRates& analyze() noexcept;
    const SpinRates& latest() const noexcept { return result_; }
    void reset() noexcept;

    // The last analysed magnitude spectrum of component axis (0 = x, 1 = y, 2 = z): bins 0 … N/2, bin k at
    // k · bin_width() rad/s. Empty for an axis outside 0..2.
    std::span<const double> magnitude(int axis) const noexcept;

    double sample_period() const noexcept { return config_.sample_period; }
    std::size_t window() const noexcept { return config_.window; }
    double bin_width() const noexcept;       // rad/s
    double window_seconds() const noexcept;  // s
    std::size_t filled() const noexcept { return filled_; }
    const SpinSpectrumConfig& config() const noexcept { return config_; }

private:
    void release() noexcept;

    SpinSpectrumConfig config_;
    std::size_t bins_ = 0;       // N/2 + 1
    double* ring_ = nullptr;     // 3N, sample i at [3i, 3i+3)
    double* hann_ = nullptr;     // N
    double* in_ = nullptr;       // 3 × N, component-major (FFTW input)
    void* out_ = nullptr;        // 3 × bins complex (FFTW output)
    double* mag_ = nullptr;      // 3 × bins
    double* scratch_ = nullptr;  // bins (median)
    void* plan_ = nullptr;       // fftw_plan
    double hann_sum_ = 0.0;
    std::size_t head_ = 0;    // next write position
    std::size_t filled_ = 0;  // samples in the ring (≤ N)
    std::size_t since_analysis_ = 0;
    SpinRates result_;
};

}  // namespace attitude_estimator
