#pragma once
// A quantity that varies over minutes, evaluated at the rate its physics needs: exactly at the nodes
// t_k = k·interval and interpolated between them, linearly (the two nodes around t) or by the cubic
// Catmull-Rom spline (the four nodes around t: continuous in value and slope, so an integrator fed by it
// meets no kink at the nodes). The value at t depends on t alone, not on the order of the calls, so a host
// that goes back in time (CVODE's interpolation, an FMU state restored) sees the very numbers it saw
// before; the nodes kept are only a memo, their storage allocated once, in the constructor.
//
// Errors: linear at most interval^2/8 max |f''|, cubic of order interval^4 max |f''''| (f the exact
// function): each user states its own bound where it chooses the interval.
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

namespace environment {

class NodeInterpolator {
public:
    enum class Order { linear, cubic };

    NodeInterpolator(double interval, std::size_t size, Order order = Order::linear)
        : interval_(interval), size_(size), order_(order), values_(kSlots * size) {
        if (!(interval > 0.0) || !std::isfinite(interval))
            throw std::invalid_argument("NodeInterpolator: interval must be positive and finite");
        index_.fill(kNone);
    }

    double interval() const { return interval_; }
    std::size_t size() const { return size_; }

    /// out[0 … size) = the interpolated value at t; compute(t_k, double* node) writes the exact value at a node.
    template <class Compute>
    void evaluate(double t, Compute&& compute, double* out) {
        const double x = t / interval_;
        const double kf = std::floor(x);
        if (!(std::abs(kf) < 9.0e15)) throw std::invalid_argument("NodeInterpolator: time out of range");
        const auto k = static_cast<std::int64_t>(kf);
        const double s = x - kf;
        const double* a = node(k, compute, k);
        if (s == 0.0) {
            for (std::size_t i = 0; i < size_; ++i) out[i] = a[i];
            return;
        }
        const double* b = node(k + 1, compute, k);
        if (order_ == Order::linear) {
            for (std::size_t i = 0; i < size_; ++i) out[i] = a[i] + s * (b[i] - a[i]);
            return;
        }
        const double* before = node(k - 1, compute, k);
        const double* after = node(k + 2, compute, k);
        // Catmull-Rom: the slope at a node is the central difference of its neighbours.
        const double s2 = s * s, s3 = s2 * s;
        const double w0 = 0.5 * (-s3 + 2.0 * s2 - s), w1 = 0.5 * (3.0 * s3 - 5.0 * s2 + 2.0),
                     w2 = 0.5 * (-3.0 * s3 + 4.0 * s2 + s), w3 = 0.5 * (s3 - s2);
        for (std::size_t i = 0; i < size_; ++i) out[i] = w0 * before[i] + w1 * a[i] + w2 * b[i] + w3 * after[i];
    }

private:
    static constexpr std::int64_t kNone = std::numeric_limits<std::int64_t>::min();
    // Six slots: the four nodes one value needs (k-1 … k+2) and two more. A node is computed into the slot
    // farthest from the middle of the interval [k, k+1] being served: never one of its four (they lie
    // within 1.5 of the middle, any other node 2.5 or more).
    static constexpr std::size_t kSlots = 6;

    template <class Compute>
    const double* node(std::int64_t i, Compute& compute, std::int64_t k) {
        std::size_t victim = 0;
        std::uint64_t farthest = 0;
        for (std::size_t slot = 0; slot < kSlots; ++slot) {
            if (index_[slot] == i) return &values_[slot * size_];
            // twice the distance from the middle k + 1/2
            const std::uint64_t d = index_[slot] == kNone
                                        ? std::numeric_limits<std::uint64_t>::max()
                                        : static_cast<std::uint64_t>(std::abs(2 * (index_[slot] - k) - 1));
            if (d >= farthest) {
                farthest = d;
                victim = slot;
            }
        }
        double* v = &values_[victim * size_];
        index_[victim] = kNone;  // not valid until compute returns (it may throw)
        compute(static_cast<double>(i) * interval_, v);
        index_[victim] = i;
        return v;
    }

    double interval_;
    std::size_t size_;
    Order order_;
    std::array<std::int64_t, kSlots> index_{};
    std::vector<double> values_;
};

}  // namespace environment
