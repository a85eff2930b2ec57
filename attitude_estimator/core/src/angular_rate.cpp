#include "attitude_estimator/angular_rate.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "attitude_estimator/vec3_math.hpp"

namespace attitude_estimator {
namespace {

template <class T>
bool finite3(const Vec3<T>& v) noexcept {
    return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}

template <class T>
T clamp_unit(T c) noexcept {
    return std::clamp(c, T(-1), T(1));
}

}  // namespace

template <class T>
T relative_rotation_angle(const Quaternion<T>& a, const Quaternion<T>& b) noexcept {
    const Vec3<T> av{a.x, a.y, a.z}, bv{b.x, b.y, b.z};
    if (!finite3(av) || !finite3(bv) || !std::isfinite(a.w) || !std::isfinite(b.w)) return T(0);
    const T na = std::sqrt(squared_norm(av) + a.w * a.w), nb = std::sqrt(squared_norm(bv) + b.w * b.w);
    if (!(na > T(0)) || !(nb > T(0))) return T(0);
    // δq = b ⊗ a⁻¹: scalar a·b, vector a_w b_v − b_w a_v ∓ a_v × b_v (the cross term is orthogonal to the
    // rest, so |δQ| is the same in either multiplication convention). atan2 keeps small angles accurate.
    const T s = dot(av, bv) + a.w * b.w;
    const Vec3<T> c = cross(av, bv);
    const Vec3<T> v{a.w * bv[0] - b.w * av[0] - c[0], a.w * bv[1] - b.w * av[1] - c[1],
                    a.w * bv[2] - b.w * av[2] - c[2]};
    return T(2) * std::atan2(std::sqrt(squared_norm(v)), std::fabs(s));  // |s|: q and −q are one attitude
}

template <class T>
T vector_angle(const Vec3<T>& a, const Vec3<T>& b) noexcept {
    if (!finite3(a) || !finite3(b) || !(squared_norm(a) > T(0)) || !(squared_norm(b) > T(0))) return T(0);
    return std::atan2(std::sqrt(squared_norm(cross(a, b))), dot(a, b));
}

template <class T>
T direction_angle_distance(const Vec3<T>& a, const Vec3<T>& b) noexcept {
    if (!finite3(a) || !finite3(b)) return T(0);
    const T na = std::sqrt(squared_norm(a)), nb = std::sqrt(squared_norm(b));
    if (!(na > T(0)) || !(nb > T(0))) return T(0);
    T sum = T(0);
    for (int k = 0; k < 3; ++k) {
        // K, L, M of 004 eq. 5: arccos(B_k,i/|B_i|) − arccos(B_k,i−1/|B_i−1|)
        const T d = std::acos(clamp_unit(b[k] / nb)) - std::acos(clamp_unit(a[k] / na));
        sum += d * d;
    }
    return std::sqrt(sum);
}

template <class T>
T angle_triple_distance(const Vec3<T>& a, const Vec3<T>& b) noexcept {
    if (!finite3(a) || !finite3(b)) return T(0);
    const Vec3<T> d{a[0] - b[0], a[1] - b[1], a[2] - b[2]};  // ε10 − ε11, ε20 − ε21, ε30 − ε31   (004 eq. 4)
    return std::sqrt(squared_norm(d));
}

template <class T>
MeanAngularRate<T>::MeanAngularRate(const MeanAngularRateConfig<T>& config) noexcept : config_(config) {
    config_.window = std::clamp<std::size_t>(config_.window, 1, kMaxRateWindow);
    if (!(config_.min_interval >= T(0)) || !std::isfinite(config_.min_interval)) config_.min_interval = T(0);
    if (!(config_.max_interval > T(0))) config_.max_interval = std::numeric_limits<T>::infinity();
}

template <class T>
bool MeanAngularRate<T>::consistent() const noexcept {
    unsigned char flag = 0;
    std::memcpy(&flag, &have_last_, 1);  // read as a byte: a bool holding 2 is undefined behaviour
    const auto measure = static_cast<int>(config_.measure);
    bool ok = flag <= 1 && measure >= 0 && measure <= static_cast<int>(RateMeasure::angle_triple) &&
              config_.window >= 1 && config_.window <= kMaxRateWindow && head_ < config_.window &&
              count_ <= config_.window && config_.min_interval >= T(0) && config_.max_interval > T(0) &&
              std::isfinite(last_t_);
    for (std::size_t i = 0; i < kMaxRateWindow; ++i) ok = ok && std::isfinite(rate_[i]) && std::isfinite(dt_[i]);
    for (const T x : last_) ok = ok && std::isfinite(x);
    return ok;
}

template <class T>
void MeanAngularRate<T>::reset() noexcept {
    head_ = 0;
    count_ = 0;
    have_last_ = false;
}

template <class T>
bool MeanAngularRate<T>::push(T t, const Quaternion<T>& q, bool valid) noexcept {
    if (config_.measure != RateMeasure::attitude_angle) return false;
    return accept(t, {q.x, q.y, q.z, q.w}, valid);
}

template <class T>
bool MeanAngularRate<T>::push(T t, const Vec3<T>& v, bool valid) noexcept {
    if (config_.measure == RateMeasure::attitude_angle) return false;
    return accept(t, {v[0], v[1], v[2], T(0)}, valid);
}

template <class T>
bool MeanAngularRate<T>::accept(T t, const std::array<T, 4>& x, bool valid) noexcept {
    bool finite = std::isfinite(t);
    for (T c : x) finite = finite && std::isfinite(c);
    if (!valid || !finite) {
        have_last_ = false;  // chain broken
        return false;
    }
    if (!have_last_) {
        have_last_ = true;
        last_t_ = t;
        last_ = x;
        return false;
    }
    const T dt = t - last_t_;
    if (!(dt > T(0)) || dt < config_.min_interval) return false;  // not after the last one, or decimated
    if (dt > config_.max_interval) {                              // too long a gap: start a new chain here
        last_t_ = t;
        last_ = x;
        return false;
    }
    T angle;
    if (config_.measure == RateMeasure::attitude_angle) {
        angle = relative_rotation_angle(Quaternion<T>{last_[0], last_[1], last_[2], last_[3]},
                                        Quaternion<T>{x[0], x[1], x[2], x[3]});
    } else {
        const Vec3<T> a{last_[0], last_[1], last_[2]}, b{x[0], x[1], x[2]};
        switch (config_.measure) {
            case RateMeasure::vector_angle:
                angle = vector_angle(a, b);
                break;
            case RateMeasure::direction_angles:
                angle = direction_angle_distance(a, b);
                break;
            default:
                angle = angle_triple_distance(a, b);
                break;
        }
    }
    rate_[head_] = angle / dt;  // one increment of 004 eq. 4 (|ω̄_i| of eq. 5)
    dt_[head_] = dt;
    head_ = (head_ + 1) % config_.window;
    if (count_ < config_.window) ++count_;
    last_t_ = t;
    last_ = x;
    return true;
}

template <class T>
MeanRate<T> MeanAngularRate<T>::result() const noexcept {
    MeanRate<T> r;
    r.increments = count_;
    if (count_ == 0) return r;
    T sum = T(0), span = T(0);
    for (std::size_t i = 0; i < count_; ++i) {
        sum += rate_[i];
        span += dt_[i];
    }
    r.rate = sum / static_cast<T>(count_);  // 004 eq. 5: (1/n) Σ |ω̄_i|
    r.window_seconds = span;
    r.valid = count_ == config_.window;
    return r;
}

template float relative_rotation_angle(const Quaternion<float>&, const Quaternion<float>&) noexcept;
template double relative_rotation_angle(const Quaternion<double>&, const Quaternion<double>&) noexcept;
template float vector_angle(const Vec3<float>&, const Vec3<float>&) noexcept;
template double vector_angle(const Vec3<double>&, const Vec3<double>&) noexcept;
template float direction_angle_distance(const Vec3<float>&, const Vec3<float>&) noexcept;
template double direction_angle_distance(const Vec3<double>&, const Vec3<double>&) noexcept;
template float angle_triple_distance(const Vec3<float>&, const Vec3<float>&) noexcept;
template double angle_triple_distance(const Vec3<double>&, const Vec3<double>&) noexcept;
template class MeanAngularRate<float>;
template class MeanAngularRate<double>;

}  // namespace attitude_estimator
