#include "attitude_estimator/spin_spectrum.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <new>
#include <numbers>
#include <stdexcept>
#include <utility>

namespace attitude_estimator {
namespace {

// FFTW's planner is not thread-safe (FFTW manual §5.4: only fftw_execute is); several estimator instances
// may be constructed from different threads by a co-simulation host.
std::mutex& planner_mutex() {
    static std::mutex m;
    return m;
}

// Plans alive, guarded by planner_mutex. FFTW keeps planner tables of its own (allocated on the first plan,
// freed only by fftw_cleanup); when the last plan goes, they are freed, so a host that unloads the FMU (or a
// leak checker at exit) finds nothing left behind. fftw_cleanup is only legal with no plan alive.
std::size_t live_plans = 0;

// First bin searched for lines: mean removal empties bin 0 and the Hann main lobe is ±2 bins wide, so a
// line below two bins cannot be told from the window's own leakage of a trend.
constexpr std::size_t kFirstBin = 2;

// Interpolated peak at bin k of magnitude m: Gaussian (log-parabolic) fit through k−1, k, k+1, which is
// close to exact for the Hann main lobe. Returns the fractional offset δ ∈ [−½, ½] and the peak magnitude.
struct Peak {
    double bin = 0.0;
    double magnitude = 0.0;
};

Peak interpolate(const double* m, std::size_t k) noexcept {
    const double a = m[k - 1], b = m[k], c = m[k + 1];
    Peak p{static_cast<double>(k), b};
    if (!(a > 0.0) || !(b > 0.0) || !(c > 0.0)) return p;
    const double la = std::log(a), lb = std::log(b), lc = std::log(c);
    const double den = la - 2.0 * lb + lc;
    if (!(den < 0.0)) return p;  // not a strict maximum of the log-parabola
    const double delta = std::clamp(0.5 * (la - lc) / den, -0.5, 0.5);
    p.bin += delta;
    p.magnitude = std::exp(lb - 0.25 * (la - lc) * delta);
    return p;
}

// Median of m[0..n) through scratch (nth_element does not allocate).
double median(const double* m, std::size_t n, double* scratch) noexcept {
    if (n == 0) return 0.0;
    std::copy(m, m + n, scratch);
    std::nth_element(scratch, scratch + n / 2, scratch + n);
    return scratch[n / 2];
}

}  // namespace

const char* to_string(SpinStatus s) noexcept {
    switch (s) {
        case SpinStatus::ok:
            return "ok";
        case SpinStatus::window_not_full:
            return "window_not_full";
        case SpinStatus::no_z_line:
            return "no_z_line";
        case SpinStatus::no_xy_pair:
            return "no_xy_pair";
        case SpinStatus::inconsistent:
            return "inconsistent";
    }
    return "unknown";
}

SpinSpectrum::SpinSpectrum(double sample_period, std::size_t window, std::size_t analysis_interval)
    : SpinSpectrum(SpinSpectrumConfig{
          .sample_period = sample_period, .window = window, .analysis_interval = analysis_interval}) {}

SpinSpectrum::SpinSpectrum(const SpinSpectrumConfig& config) : config_(config) {
    if (!(config_.sample_period > 0.0) || !std::isfinite(config_.sample_period))
        throw std::invalid_argument("SpinSpectrum: sample_period must be positive and finite");
    if (config_.window < 16) throw std::invalid_argument("SpinSpectrum: window must be at least 16 samples");
    if (!(config_.min_snr >= 0.0) || !(config_.min_line_amplitude >= 0.0) ||
        !(config_.max_center_mismatch_bins > 0.0) || !(config_.min_pair_amplitude_ratio >= 0.0) ||
        !(config_.min_pair_amplitude_ratio <= 1.0))
        throw std::invalid_argument("SpinSpectrum: thresholds must be non-negative (mismatch positive)");
    const std::size_t n = config_.window;
    bins_ = n / 2 + 1;
    ring_ = static_cast<double*>(fftw_malloc(sizeof(double) * 3 * n));
    hann_ = static_cast<double*>(fftw_malloc(sizeof(double) * n));
    in_ = static_cast<double*>(fftw_malloc(sizeof(double) * 3 * n));
    out_ = fftw_malloc(sizeof(fftw_complex) * 3 * bins_);
    mag_ = static_cast<double*>(fftw_malloc(sizeof(double) * 3 * bins_));
    scratch_ = static_cast<double*>(fftw_malloc(sizeof(double) * bins_));
    if (!ring_ || !hann_ || !in_ || !out_ || !mag_ || !scratch_) {
        release();
        throw std::bad_alloc();
    }
    {
        // Three real transforms of length N in one plan (component-major input, N apart; outputs bins apart).
        // FFTW_ESTIMATE: planning does not overwrite the arrays and takes microseconds.
        const std::lock_guard lock(planner_mutex());
        const int len = static_cast<int>(n);
        plan_ = fftw_plan_many_dft_r2c(1, &len, 3, in_, nullptr, 1, len, static_cast<fftw_complex*>(out_), nullptr, 1,
                                       static_cast<int>(bins_), FFTW_ESTIMATE);
        if (plan_) ++live_plans;
    }
    if (!plan_) {
        release();
        throw std::bad_alloc();
    }
    // Periodic Hann window w[i] = ½ (1 − cos 2πi/N) (the DFT-even form: its coherent gain is exactly ½).
    hann_sum_ = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        hann_[i] = 0.5 * (1.0 - std::cos(2.0 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(n)));
        hann_sum_ += hann_[i];
    }
    std::fill(ring_, ring_ + 3 * n, 0.0);
    std::fill(mag_, mag_ + 3 * bins_, 0.0);
    reset();
}

SpinSpectrum::~SpinSpectrum() {
    release();
}

void SpinSpectrum::release() noexcept {
    if (plan_) {
        const std::lock_guard lock(planner_mutex());  // fftw_destroy_plan is not thread-safe either
        fftw_destroy_plan(static_cast<fftw_plan>(plan_));
        if (--live_plans == 0) fftw_cleanup();
    }
    fftw_free(ring_);
    fftw_free(hann_);
    fftw_free(in_);
    fftw_free(out_);
    fftw_free(mag_);
    fftw_free(scratch_);
    plan_ = nullptr;
    ring_ = hann_ = in_ = mag_ = scratch_ = nullptr;
    out_ = nullptr;
}

SpinSpectrum::SpinSpectrum(SpinSpectrum&& other) noexcept
    : config_(other.config_),
      bins_(other.bins_),
      ring_(std::exchange(other.ring_, nullptr)),
      hann_(std::exchange(other.hann_, nullptr)),
      in_(std::exchange(other.in_, nullptr)),
      out_(std::exchange(other.out_, nullptr)),
      mag_(std::exchange(other.mag_, nullptr)),
      scratch_(std::exchange(other.scratch_, nullptr)),
      plan_(std::exchange(other.plan_, nullptr)),
      hann_sum_(other.hann_sum_),
      head_(other.head_),
      filled_(std::exchange(other.filled_, 0)),
      since_analysis_(other.since_analysis_),
      result_(other.result_) {
    other.bins_ = 0;
}

SpinSpectrum& SpinSpectrum::operator=(SpinSpectrum&& other) noexcept {
    if (this != &other) {
        release();
        config_ = other.config_;
        bins_ = std::exchange(other.bins_, 0);
        ring_ = std::exchange(other.ring_, nullptr);
        hann_ = std::exchange(other.hann_, nullptr);
        in_ = std::exchange(other.in_, nullptr);
        out_ = std::exchange(other.out_, nullptr);
        mag_ = std::exchange(other.mag_, nullptr);
        scratch_ = std::exchange(other.scratch_, nullptr);
        plan_ = std::exchange(other.plan_, nullptr);
        hann_sum_ = other.hann_sum_;
        head_ = other.head_;
        filled_ = std::exchange(other.filled_, 0);
        since_analysis_ = other.since_analysis_;
        result_ = other.result_;
    }
    return *this;
}

double SpinSpectrum::window_seconds() const noexcept {
    return static_cast<double>(config_.window) * config_.sample_period;
}

double SpinSpectrum::bin_width() const noexcept {
    return 2.0 * std::numbers::pi / window_seconds();
}

void SpinSpectrum::reset() noexcept {
    head_ = 0;
    filled_ = 0;
    since_analysis_ = 0;
    result_ = SpinRates{};
    result_.bin_width = bin_width();
    result_.window_seconds = window_seconds();
}

bool SpinSpectrum::push(const Vec3<float>& sun, bool valid) noexcept {
    return push(Vec3<double>{sun[0], sun[1], sun[2]}, valid);
}

bool SpinSpectrum::push(const Vec3<double>& sun, bool valid) noexcept {
    if (!ring_) return false;  // moved-from
    if (!valid || !std::isfinite(sun[0]) || !std::isfinite(sun[1]) || !std::isfinite(sun[2])) {
        // A gap: the samples before it cannot be joined to the ones after it in one uniformly sampled window.
        reset();
        result_.status = SpinStatus::window_not_full;
        return false;
    }
    double* slot = ring_ + 3 * head_;
    slot[0] = sun[0];
    slot[1] = sun[1];
    slot[2] = sun[2];
    head_ = (head_ + 1) % config_.window;
    if (filled_ < config_.window) ++filled_;
    if (config_.analysis_interval == 0 || filled_ < config_.window) return false;
    if (++since_analysis_ < config_.analysis_interval) return false;
    since_analysis_ = 0;
    analyze();
    return true;
}

std::span<const double> SpinSpectrum::magnitude(int axis) const noexcept {
    if (axis < 0 || axis > 2 || !mag_) return {};
    return {mag_ + static_cast<std::size_t>(axis) * bins_, bins_};
}

const SpinRates& SpinSpectrum::analyze() noexcept {
    SpinRates r;
    r.bin_width = bin_width();
    r.window_seconds = window_seconds();
    r.samples = filled_;
    const std::size_t n = config_.window;
    if (!plan_ || filled_ < n) {
        r.status = SpinStatus::window_not_full;
        result_ = r;
        return result_;
    }

    // Unroll the ring oldest-first (the window must follow time), remove each component's mean, apply Hann.
    double mean[3] = {0.0, 0.0, 0.0};
    for (std::size_t i = 0; i < n; ++i) {
        const double* s = ring_ + 3 * ((head_ + i) % n);
        for (int c = 0; c < 3; ++c) {
            in_[c * n + i] = s[c];
            mean[c] += s[c];
        }
    }
    for (int c = 0; c < 3; ++c) {
        mean[c] /= static_cast<double>(n);
        for (std::size_t i = 0; i < n; ++i) in_[c * n + i] = (in_[c * n + i] - mean[c]) * hann_[i];
    }
    fftw_execute(static_cast<fftw_plan>(plan_));  // new-array execute not needed: the plan owns in_/out_

    const auto* out = static_cast<const fftw_complex*>(out_);
    for (std::size_t c = 0; c < 3; ++c)
        for (std::size_t k = 0; k < bins_; ++k) {
            const fftw_complex& x = out[c * bins_ + k];
            mag_[c * bins_ + k] = std::hypot(x[0], x[1]);
        }

    // A line of amplitude A gives |X| = A · Σw / 2 at its bin (Hann coherent gain).
    const double to_amplitude = 2.0 / hann_sum_;
    const std::size_t last = bins_ - 2;  // a peak needs a neighbour on each side
    auto make_line = [&](const double* m, std::size_t k, double floor) {
        const Peak p = interpolate(m, k);
        SpectralLine l;
        l.frequency = p.bin * r.bin_width;
        l.amplitude = p.magnitude * to_amplitude;
        l.snr = floor > 0.0 ? p.magnitude / floor : (p.magnitude > 0.0 ? INFINITY : 0.0);
        l.found = l.amplitude >= config_.min_line_amplitude && l.snr >= config_.min_snr && l.amplitude > 0.0;
        return l;
    };
    auto is_local_max = [](const double* m, std::size_t k) { return m[k] > m[k - 1] && m[k] >= m[k + 1]; };

    // z: the strongest local maximum of |S_z| → θ̇.
    const double* mz = mag_ + 2 * bins_;
    const double floor_z = median(mz, bins_, scratch_);
    std::size_t kz = 0;
    for (std::size_t k = kFirstBin; k <= last; ++k)
        if (is_local_max(mz, k) && (kz == 0 || mz[k] > mz[kz])) kz = k;
    if (kz != 0) r.z_line = make_line(mz, kz, floor_z);
    if (!r.z_line.found) {
        r.status = SpinStatus::no_z_line;
        result_ = r;
        return result_;
    }

    // x/y: the two strongest local maxima of sqrt(|S_x|² + |S_y|²) (in the seed the lines sit in both
    // components, in quadrature). The sum is formed in scratch_ (free again once the z floor is known).
    double* mxy = scratch_;
    const double* mx = mag_;
    const double* my = mag_ + bins_;
    for (std::size_t k = 0; k < bins_; ++k) mxy[k] = std::hypot(mx[k], my[k]);
    std::size_t k1 = 0, k2 = 0;  // strongest, second strongest
    for (std::size_t k = kFirstBin; k <= last; ++k) {
        if (!is_local_max(mxy, k)) continue;
        if (k1 == 0 || mxy[k] > mxy[k1]) {
            k2 = k1;
            k1 = k;
        } else if (k2 == 0 || mxy[k] > mxy[k2]) {
            k2 = k;
        }
    }
    // Lines first (they read mxy in bin order), then the floor: nth_element reorders mxy in place.
    SpectralLine l1, l2;
    if (k1 != 0) l1 = make_line(mxy, k1, 1.0);
    if (k2 != 0) l2 = make_line(mxy, k2, 1.0);
    // Noise floor of the x/y sum: median of hypot(|X|, |Y|), recomputed in place (nth_element on scratch).
    const double floor_xy = [&] {
        std::nth_element(mxy, mxy + bins_ / 2, mxy + bins_);
        return mxy[bins_ / 2];
    }();
    for (SpectralLine* l : {&l1, &l2}) {
        if (l->amplitude == 0.0) continue;
        const double magnitude = l->amplitude / to_amplitude;
        l->snr = floor_xy > 0.0 ? magnitude / floor_xy : INFINITY;
        l->found = l->amplitude >= config_.min_line_amplitude && l->snr >= config_.min_snr;
    }
    if (!l1.found || !l2.found) {
        if (l1.found) r.xy_upper = l1;
        r.status = SpinStatus::no_xy_pair;
        result_ = r;
        return result_;
    }
    if (l1.frequency > l2.frequency) std::swap(l1, l2);
    r.xy_lower = l1;
    r.xy_upper = l2;

    // Identification: lines at θ̇ − φ̇ and θ̇ + φ̇ (φ̇ < θ̇): centre = θ̇, half distance = φ̇. When φ̇ > θ̇ the
    // lower line folds to φ̇ − θ̇: then the half distance is θ̇ and the centre is φ̇.
    const double centre = 0.5 * (l1.frequency + l2.frequency);
    const double half = 0.5 * (l2.frequency - l1.frequency);
    const double tol = config_.max_center_mismatch_bins * r.bin_width;
    const double ratio = std::min(l1.amplitude, l2.amplitude) / std::max(l1.amplitude, l2.amplitude);
    if (ratio < config_.min_pair_amplitude_ratio) {
        r.status = SpinStatus::inconsistent;
    } else if (std::fabs(centre - r.z_line.frequency) <= tol) {
        r.theta_dot = r.z_line.frequency;
        r.phi_dot = half;
    } else if (std::fabs(half - r.z_line.frequency) <= tol) {
        r.theta_dot = r.z_line.frequency;
        r.phi_dot = centre;
    } else {
        r.status = SpinStatus::inconsistent;
    }
    if (r.status == SpinStatus::inconsistent) {
        result_ = r;
        return result_;
    }
    r.valid = true;
    r.status = SpinStatus::ok;
    result_ = r;
    return result_;
}

}  // namespace attitude_estimator
