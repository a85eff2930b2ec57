// Mean angular-velocity magnitude from successive attitude (or vector) estimates (004 §5, eq. 4 and 5).
//
// 004 eq. 4:  |ω̄| = sqrt((ε10 − ε11)² + (ε20 − ε21)² + (ε30 − ε31)²) / Δt
//   the distance between two triples of attitude angles ε (004 eq. 2) taken Δt apart, over Δt;
// 004 eq. 5:  |ω̄| = (1/n) Σ |ω̄_i|,  |ω̄_i| = sqrt(K² + L² + M²) / Δt1,
//   K = arccos(B_x,i/|B_i|) − arccos(B_x,i−1/|B_i−1|), L and M the same for y and z
//   (the direction angles of the measured field, n increments averaged).
//
// What is measured per increment (RateMeasure, see docs/rates.md for the interpretation):
//   attitude_angle   — the rotation angle between two successive attitudes, 2 atan2(|δQ|, |δw|) with
//                      δq = q_i ⊗ q_{i−1}⁻¹: the angle "between the coupled systems" that eq. 4 divides by
//                      Δt, free of any Euler-angle singularity. The form to use with Q-method attitudes.
//   vector_angle     — the angle between two successive measured vectors (sun or field), atan2(|a×b|, a·b):
//                      it sees only the rate component perpendicular to the vector.
//   direction_angles — eq. 5 as printed: sqrt(K² + L² + M²) from the direction angles of the vector.
//   angle_triple     — eq. 4 as printed: the pushed Vec3 IS a triple of angles (rad), e.g. 004 eq. 2's
//                      ε1, ε2, ε3 (sun_methods' three_faces printed_epsilon) or any Euler-angle set; the
//                      increment is the Euclidean distance of the two triples.
// The increments' rates are averaged as eq. 5 prints it: the arithmetic mean of angle_i / Δt_i over the
// last `window` increments (window = 1 is eq. 4 exactly).
//
// Core style: templated on float/double, no heap (fixed capacity kMaxRateWindow), noexcept, no state
// outside the object. Built into attitude_estimator_angular_rate with -fno-exceptions.
#pragma once

#include <array>
#include <cstddef>
#include <limits>

#include "attitude_estimator/types.hpp"

namespace attitude_estimator {

inline constexpr std::size_t kMaxRateWindow = 64;

enum class RateMeasure { attitude_angle, vector_angle, direction_angles, angle_triple };

template <class T>
struct MeanAngularRateConfig {
    RateMeasure measure = RateMeasure::attitude_angle;
    std::size_t window = 1;  // increments averaged, 1 … kMaxRateWindow (clamped); 1 = eq. 4
    // Decimation: a sample closer than min_interval (s) to the last used one is ignored, so 20 Hz estimates
    // can feed increments of e.g. 2 s or 60 s (004: "no less than once in two seconds"; telemetry: 1 min).
    T min_interval = T(0);
    // A sample more than max_interval (s) after the last used one starts a new chain (no increment across
    // a long gap, where the rotation could exceed π and alias).
    T max_interval = std::numeric_limits<T>::infinity();
};

template <class T>
struct MeanRate {
    T rate = T(0);               // rad/s, mean |ω| over the window (0 when no increment yet)
    T window_seconds = T(0);     // s, Σ Δt_i of the increments averaged
    std::size_t increments = 0;  // increments averaged (≤ window)
    bool valid = false;          // window full (increments == window)
};

// Rotation angle (rad, 0 … π) between two attitudes; the quaternions need not be exactly unit length.
// Returns 0 if either is zero or not finite.
template <class T>
T relative_rotation_angle(const Quaternion<T>& a, const Quaternion<T>& b) noexcept;

// Angle (rad, 0 … π) between two vectors of any non-zero length; 0 if either is zero or not finite.
template <class T>
T vector_angle(const Vec3<T>& a, const Vec3<T>& b) noexcept;

// sqrt(K² + L² + M²) of 004 eq. 5 (the numerator of eq. 4 with direction angles as the ε triple).
template <class T>
T direction_angle_distance(const Vec3<T>& a, const Vec3<T>& b) noexcept;

// sqrt((a1 − b1)² + (a2 − b2)² + (a3 − b3)²): the numerator of 004 eq. 4 for two angle triples (rad);
// 0 if either is not finite.
template <class T>
T angle_triple_distance(const Vec3<T>& a, const Vec3<T>& b) noexcept;

template <class T>
class MeanAngularRate {
public:
    explicit MeanAngularRate(const MeanAngularRateConfig<T>& config = {}) noexcept;

    // One estimate at time t (s). A sample with valid == false or not finite breaks the chain (the next
    // valid sample starts a new pair; increments already taken stay in the window). A time not after the
    // last used sample is ignored. Returns true when the sample completed an increment.
    // push(q) needs measure == attitude_angle; push(v) one of the others (a vector, or an angle triple for
    // angle_triple); the wrong kind is ignored (returns false).
    bool push(T t, const Quaternion<T>& q, bool valid = true) noexcept;
    bool push(T t, const Vec3<T>& v, bool valid = true) noexcept;

    MeanRate<T> result() const noexcept;
    void reset() noexcept;
    // What the constructor and push() guarantee, for a copy that came in as bytes (an FMU state):
    // window and ring indices in range, a known measure, a 0/1 flag, no NaN in the rings.
    bool consistent() const noexcept;
    const MeanAngularRateConfig<T>& config() const noexcept { return config_; }

private:
    bool accept(T t, const std::array<T, 4>& x, bool valid) noexcept;

    MeanAngularRateConfig<T> config_;
    std::array<T, kMaxRateWindow> rate_{};  // ring of increment rates angle_i / Δt_i
    std::array<T, kMaxRateWindow> dt_{};    // ring of Δt_i
    std::size_t head_ = 0;
    std::size_t count_ = 0;
    bool have_last_ = false;
    T last_t_ = T(0);
    std::array<T, 4> last_{};  // quaternion x, y, z, w or vector x, y, z, 0
};

extern template float relative_rotation_angle(const Quaternion<float>&, const Quaternion<float>&) noexcept;
extern template double relative_rotation_angle(const Quaternion<double>&, const Quaternion<double>&) noexcept;
extern template float vector_angle(const Vec3<float>&, const Vec3<float>&) noexcept;
extern template double vector_angle(const Vec3<double>&, const Vec3<double>&) noexcept;
extern template float direction_angle_distance(const Vec3<float>&, const Vec3<float>&) noexcept;
extern template double direction_angle_distance(const Vec3<double>&, const Vec3<double>&) noexcept;
extern template float angle_triple_distance(const Vec3<float>&, const Vec3<float>&) noexcept;
extern template double angle_triple_distance(const Vec3<double>&, const Vec3<double>&) noexcept;
extern template class MeanAngularRate<float>;
extern template class MeanAngularRate<double>;

}  // namespace attitude_estimator
