// The multiplicative EKF of mekf.hpp. Eigen's fixed-size matrices only (no dynamic size: nothing here
// can allocate); the state crosses the public interface as plain arrays.
#include "attitude_estimator/mekf.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "attitude_estimator/attitude_matrix.hpp"
#include "attitude_estimator/vec3_math.hpp"
#include "ground/atmosphere_table.hpp"

namespace attitude_estimator {

namespace {

template <class T>
using Mat3 = Eigen::Matrix<T, 3, 3>;
template <class T>
using V3 = Eigen::Matrix<T, 3, 1>;
template <class T>
using MatN = Eigen::Matrix<T, kMekfStates, kMekfStates, Eigen::RowMajor>;
template <class T>
using VecN = Eigen::Matrix<T, kMekfStates, 1>;

template <class T>
V3<T> v3(const Vec3<T>& v) {
    return V3<T>(v[0], v[1], v[2]);
}

template <class T>
Mat3<T> skew(const V3<T>& v) {
    Mat3<T> m;
    m << T(0), -v.z(), v.y(), v.z(), T(0), -v.x(), -v.y(), v.x(), T(0);
    return m;
}

template <class T>
Mat3<T> matrix_of(const Quaternion<T>& q) {
    const Matrix3RowMajor<T> a = attitude_matrix(q);
    return Eigen::Map<const Eigen::Matrix<T, 3, 3, Eigen::RowMajor>>(a.data());
}

// The quaternion product in Shuster's order, A(p ⊗ q) = A(p) A(q) for the attitude matrix of
// attitude_matrix.hpp: p ⊗ q = [p_w Q + q_w P − P × Q; p_w q_w − P·Q].
template <class T>
Quaternion<T> compose(const Quaternion<T>& p, const Quaternion<T>& q) {
    return {p.w * q.x + q.w * p.x - (p.y * q.z - p.z * q.y), p.w * q.y + q.w * p.y - (p.z * q.x - p.x * q.z),
            p.w * q.z + q.w * p.z - (p.x * q.y - p.y * q.x), p.w * q.w - (p.x * q.x + p.y * q.y + p.z * q.z)};
}

template <class T>
Quaternion<T> normalized(const Quaternion<T>& q) {
    const T n = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
    const T s = (q.w < T(0) ? T(-1) : T(1)) / n;
    return {q.x * s, q.y * s, q.z * s, q.w * s};
}

// The quaternion of the rotation vector φ: A(rotation(φ)) = exp(−[φ×]), the turn of the body frame by φ.
template <class T>
Quaternion<T> rotation(const V3<T>& phi) {
    const T angle = phi.norm();
    const T half = angle / T(2);
    // sin(half)/angle, by its series near 0 (relative error below 1e-16 at these sizes).
    const T k = angle < T(1e-4) ? T(0.5) - angle * angle / T(48) : std::sin(half) / angle;
    return {phi.x() * k, phi.y() * k, phi.z() * k, std::cos(half)};
}

// The rotation vector φ of q (the inverse of rotation()), angle in [0, π].
template <class T>
V3<T> rotation_vector(const Quaternion<T>& q) {
    const T sign = q.w < T(0) ? T(-1) : T(1);
    const V3<T> v(q.x * sign, q.y * sign, q.z * sign);
    const T s = v.norm();
    if (s < T(1e-12)) return T(2) * v;
    return v * (T(2) * std::atan2(s, q.w * sign) / s);
}

// ∫₀ʰ exp(−[ω u×]) du: how a rate error turns into attitude error over one step of a turning body.
template <class T>
Mat3<T> rate_to_attitude(const V3<T>& omega, T h) {
    const Mat3<T> w = skew(omega);
    const T n = omega.norm();
    const T theta = n * h;
    if (theta < T(1e-3)) return h * Mat3<T>::Identity() - h * h / T(2) * w + h * h * h / T(6) * w * w;
    return h * Mat3<T>::Identity() - (T(1) - std::cos(theta)) / (n * n) * w +
           (h - std::sin(theta) / n) / (n * n) * w * w;
}

template <class T>
bool has_inertia(const MekfConfig<T>& c) {
    for (T v : c.inertia)
        if (v != T(0)) return true;
    return false;
}

template <class T>
struct Euler {
    Mat3<T> j;
    Mat3<T> j_inv;
    V3<T> torque = V3<T>::Zero();  // N m, body: the modelled disturbance torques of this substep
    V3<T> rate(const V3<T>& w) const { return j_inv * (torque - w.cross(j * w)); }
    // ∂ω̇/∂ω = J⁻¹ ([(Jω)×] − [ω×] J)
    Mat3<T> jacobian(const V3<T>& w) const { return j_inv * (skew<T>(j * w) - skew(w) * j); }
};

inline constexpr double kEarthMu = 3.986004418e14;  // m³/s², WGS-84

template <class T>
bool has_torques(const MekfConfig<T>& c) {
    return c.gravity_gradient || c.dipole[0] != T(0) || c.dipole[1] != T(0) || c.dipole[2] != T(0) || has_drag(c.drag);
}

// The drag torque at attitude a and its derivative by the wind in body axes (drag_torque.hpp); zero when the
// model or its surroundings are missing.
template <class T>
V3<T> drag_at(const MekfState<T>& s, const MekfConfig<T>& c, const Mat3<T>& a, Mat3<T>* d_by_wind) {
    if (d_by_wind != nullptr) d_by_wind->setZero();
    if (!has_drag(c.drag) || !(s.torque_air_density > T(0))) return V3<T>::Zero();
    const V3<T> wind = a * v3(s.torque_air_velocity);
    if (!wind.allFinite()) return V3<T>::Zero();
    Matrix3RowMajor<T> d{};
    const Vec3<T> tau = drag_torque(c.drag, c.drag_density_scale * s.torque_air_density,
                                    Vec3<T>{wind.x(), wind.y(), wind.z()}, d_by_wind != nullptr ? &d : nullptr);
    if (d_by_wind != nullptr) *d_by_wind = Eigen::Map<const Eigen::Matrix<T, 3, 3, Eigen::RowMajor>>(d.data());
    return v3(tau);
}

// The modelled torques at attitude a (inertial to body) and their derivative by the attitude error δθ
// (A_true = (I − [δθ×]) Â turns an inertial vector's body image v into v + [v×] δθ):
//   m × B_b:            ∂/∂δθ = [m×][B_b×];
//   k n × J n (k = 3μ/r³, n the unit position in the body): ∂/∂δθ = k ([n×] J − [(J n)×]) [n×];
//   drag τ(v_b), v_b the wind in the body:       ∂/∂δθ = ∂τ/∂v [v_b×].
template <class T>
void model_torques(const MekfState<T>& s, const MekfConfig<T>& c, const Mat3<T>& j, const Mat3<T>& a, V3<T>& torque,
                   Mat3<T>& d_torque) {
    torque.setZero();
    d_torque.setZero();
    const V3<T> m = v3(c.dipole);
    const V3<T> field = a * v3(s.torque_field);
    if (m.squaredNorm() > T(0) && field.allFinite()) {
        torque += m.cross(field);
        d_torque += skew(m) * skew(field);
    }
    const V3<T> r = v3(s.torque_position);
    const T radius = r.norm();
    if (c.gravity_gradient && radius > T(0) && std::isfinite(radius)) {
        const V3<T> n = a * (r / radius);
        const T k = T(3) * static_cast<T>(kEarthMu / static_cast<double>(radius)) / (radius * radius);
        const V3<T> jn = j * n;
        torque += k * n.cross(jn);
        d_torque += k * (skew(n) * j - skew(jn)) * skew(n);
    }
    Mat3<T> d_by_wind;
    const V3<T> drag = drag_at(s, c, a, &d_by_wind);
    if (drag.squaredNorm() > T(0)) {
        torque += drag;
        d_torque += d_by_wind * skew(V3<T>(a * v3(s.torque_air_velocity)));
    }
}

// P in place (no copy: a 10 × 10 on the firmware's stack is 400 B), and a copy of it to work on.
template <class T>
Eigen::Map<const MatN<T>> view_p(const MekfState<T>& s) {
    return Eigen::Map<const MatN<T>>(s.p.data());
}

template <class T>
MatN<T> map_p(const MekfState<T>& s) {
    return view_p(s);
}

template <class T>
void store_p(MekfState<T>& s, const MatN<T>& p) {
    const MatN<T> sym = T(0.5) * (p + p.transpose());
    Eigen::Map<MatN<T>>(s.p.data()) = sym;
}

// Applies an error-state correction to the estimate (the multiplicative reset of the attitude).
template <class T>
void apply(MekfState<T>& s, const VecN<T>& dx) {
    s.q = normalized(compose(rotation<T>(dx.template segment<3>(kMekfAttitude)), s.q));
    for (int i = 0; i < 3; ++i) {
        s.omega[i] += dx(kMekfRate + i);
        s.mag_offset[i] += dx(kMekfOffset + i);
    }
    s.panel_scale += dx(kMekfScale);
}

// One linear update with measurement residual y (M components), Jacobian H and noise covariance R,
// gated by the normalized innovation squared; Joseph form for the covariance.
template <class T, int M>
MekfUpdate<T> linear_update(MekfState<T>& s, const Eigen::Matrix<T, M, 1>& y, const Eigen::Matrix<T, M, kMekfStates>& h,
                            const Eigen::Matrix<T, M, M>& r, T gate) {
    MekfUpdate<T> u;
    if (!y.allFinite() || !h.allFinite()) return u;
    const MatN<T> p = map_p(s);
    const Eigen::Matrix<T, kMekfStates, M> pht = p.lazyProduct(h.transpose());
    const Eigen::Matrix<T, M, M> sm = h.lazyProduct(pht) + r;
    // S is 3 × 3 or 1 × 1: Eigen's closed-form inverse (a matrix-valued LLT solve would pull in its blocked,
    // allocating triangular solver). Positive definiteness is checked by the Cholesky factorization.
    if (Eigen::LLT<Eigen::Matrix<T, M, M>>(sm).info() != Eigen::Success) return u;
    const Eigen::Matrix<T, M, M> s_inv = sm.inverse();
    u.nis = y.dot(s_inv.lazyProduct(y));
    if (!(u.nis <= gate)) return u;
    const Eigen::Matrix<T, kMekfStates, M> k = pht.lazyProduct(s_inv);
    const MatN<T> ikh = MatN<T>::Identity() - k.lazyProduct(h);
    const MatN<T> ikh_p = ikh.lazyProduct(p);
    store_p<T>(s, MatN<T>(ikh_p.lazyProduct(ikh.transpose()) + k.lazyProduct(r).lazyProduct(k.transpose())));
    apply<T>(s, k.lazyProduct(y));
    u.accepted = true;
    return u;
}

template <class T>
bool finite(const MekfState<T>& s) {
    if (!std::isfinite(s.q.x + s.q.y + s.q.z + s.q.w + s.panel_scale)) return false;
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(s.omega[i] + s.mag_offset[i])) return false;
    for (T v : s.p)
        if (!std::isfinite(v)) return false;
    return true;
}

// Whether the offset state holds the spacecraft's own field, fixed in body axes (MekfConfig::
// mag_hard_iron_sigma: before the in-flight calibration applies), rather than the sensor's offset left by
// the set/reset estimate, whose sign follows the polarity.
template <class T>
bool holds_hard_iron(const MekfState<T>& s, const MekfConfig<T>& c) noexcept {
    return c.mag_hard_iron_sigma > T(0) && s.mag_calibrated == 0;
}

// The offset state's initial 1σ per axis: the hard iron's prior while it holds the hard iron.
template <class T>
T offset_prior_sigma(const MekfState<T>& s, const MekfConfig<T>& c) noexcept {
    return holds_hard_iron(s, c) ? c.mag_hard_iron_sigma : c.init_offset_sigma;
}

// The field's correction changed (the in-flight calibration started or stopped applying): the offset state
// holds what the old field needed, which may be the hard iron the calibration now takes out (a constant
// field the polarity-following state can only hold by refusing the other polarity's readings). It starts
// again from zero with its initial uncertainty and no correlation to the other states.
template <class T>
void restart_offset(MekfState<T>& s, const MekfConfig<T>& c) noexcept {
    MatN<T> p = map_p(s);
    for (int i = 0; i < 3; ++i) {
        s.mag_offset[static_cast<std::size_t>(i)] = T(0);
        p.row(kMekfOffset + i).setZero();
        p.col(kMekfOffset + i).setZero();
        const T sigma = offset_prior_sigma(s, c);
        p(kMekfOffset + i, kMekfOffset + i) = sigma * sigma;
    }
    store_p<T>(s, p);
}

// The single-frame attitude the filter starts from was solved (Wahba, weights w_s and w_f) from this sample's
// sun and field, and the field carries the offset the offset state stands for: before the calibration applies,
// the spacecraft's own field, several µT in a 20–50 µT field (up to 17° of its direction). To first order the
// start attitude errs by δθ = G δb with G = w_f p W⁻¹ [u×] / |B| and W = w_s (I − s sᵀ) + w_f (I − u uᵀ)
// (s, u the measured unit vectors, |B| the field's size, p the sign of the offset in this reading): the
// Wahba solution turns the attitude to meet the offset-shifted field halfway. The start covariance adds
// G P_bb Gᵀ to P_θθ and G P_bb to P_θb: the attitude is as uncertain as the offset makes it, and the two
// errors are one (docs/filter.md, "The start"). Without it a start 21° off was held with a 2.9° σ.
template <class T>
void add_offset_to_start(MekfState<T>& s, const MekfSampleInputs<T>& in, const MekfConfig<T>& c) noexcept {
    // A single-frame attitude not made from the field (weight 0) carries none of its offset.
    if (!c.estimate_offset || !in.sun_valid || !in.mag_valid || !(in.mag_weight > T(0))) return;
    const V3<T> sun = v3(in.sun_body).normalized();
    const V3<T> field = v3(in.mag_body);
    const T size = field.norm();
    if (!(size > T(0)) || !sun.allFinite()) return;
    const V3<T> u = field / size;
    const Mat3<T> w = in.sun_weight * (Mat3<T>::Identity() - sun * sun.transpose()) +
                      in.mag_weight * (Mat3<T>::Identity() - u * u.transpose());
    // Parallel vectors leave W singular (the single-frame solution refuses them: no start then).
    if (!(std::abs(w.determinant()) > T(1e-6))) return;
    const T polarity = holds_hard_iron(s, c) ? T(1) : in.polarity;
    const Mat3<T> g = (in.mag_weight * polarity / size) * w.inverse() * skew(u);
    MatN<T> p = map_p(s);
    const Mat3<T> p_bb = p.template block<3, 3>(kMekfOffset, kMekfOffset);
    const Mat3<T> g_pbb = g * p_bb;
    p.template block<3, 3>(kMekfAttitude, kMekfAttitude) += g_pbb * g.transpose();
    p.template block<3, 3>(kMekfAttitude, kMekfOffset) += g_pbb;
    p.template block<3, 3>(kMekfOffset, kMekfAttitude) += g_pbb.transpose();
    store_p<T>(s, p);
}

// The divergence watch (MekfConfig::watch_time) takes this sample's field before its update. The innovation
// y = B_meas − (Â B_ref + p b̂) turned into inertial axes, z = Âᵀ y, is [B_ref×] δθ_I plus noise for an
// attitude error δθ_I fixed in inertial axes: a filter that has lost the attitude leaves a z that does not
// average away, however fast the body turns. Over exponential weights w_k (time constant watch_time) the
// average z̄ = Σ w_k z_k / Σ w_k of a consistent filter has E|z̄|² = Σ w_k² tr R_k / (Σ w_k)² (the noise as
// weighted: a correlated error weighted as white noise of the same information averages down as that white
// noise does) plus at most Σ w_k e_k / Σ w_k with e_k = E|[B_b×] δθ + δb|² from the filter's own covariance
// (Cauchy–Schwarz: the errors of successive samples are correlated, at most fully). The ratio of the two is
// ~1 when the filter is consistent (docs/filter.md, "The watch").
template <class T>
void watch_take(MekfWatch<T>& w, const V3<T>& z, T r, T spread, T t, T watch_time) {
    if (!z.allFinite()) return;
    const T dt = t - w.t;  // since the previous vector, or the start (mekf_start)
    w.t = t;
    if (!(dt > T(0))) return;
    const T alpha = dt < watch_time ? dt / watch_time : T(1);
    const T keep = T(1) - alpha;
    for (int i = 0; i < 3; ++i) w.sum[static_cast<std::size_t>(i)] = keep * w.sum[i] + alpha * z(i);
    w.weight = keep * w.weight + alpha;
    w.noise = keep * keep * w.noise + alpha * alpha * r;
    w.spread = keep * w.spread + alpha * spread;
    const T expected = w.noise / (w.weight * w.weight) + w.spread / w.weight;
    const V3<T> mean = v3(w.sum) / w.weight;
    w.ratio = expected > T(0) ? mean.squaredNorm() / expected : T(0);
}

template <class T>
void watch_field(MekfState<T>& s, const MekfSampleInputs<T>& in, T polarity, const MekfConfig<T>& c) noexcept {
    const T micro = T(1e6);
    const Mat3<T> a = matrix_of(s.q);
    const V3<T> field = a * (micro * v3(in.mag_ref));
    const V3<T> y = micro * (v3(in.mag_body) - polarity * v3(s.mag_offset)) - field;
    const T sigma = micro * c.mag_sigma, ref_sigma = micro * c.mag_ref_sigma;
    const Mat3<T> p_att = view_p(s).template block<3, 3>(kMekfAttitude, kMekfAttitude);
    const T p_off = view_p(s).template block<3, 3>(kMekfOffset, kMekfOffset).trace() * micro * micro;
    const T spread = field.squaredNorm() * p_att.trace() - field.dot(p_att * field) + p_off;
    watch_take(s.watch, V3<T>(a.transpose() * y), T(3) * (sigma * sigma + ref_sigma * ref_sigma), spread, in.t,
               c.watch_time);
}

// MekfConfig::watch_sun: the sun's squared innovation |y|², y = s_meas − Â s_ref (unit vectors), over its size
// for a consistent filter, E|y|² ≤ 3 σ_s² + tr P_θθ − s_bᵀ P_θθ s_b, averaged with the watch's exponential
// weights over watch_time from 0 at the start (as if consistent before it: one sample, or a few, cannot reach the
// gate; a persistent ratio N > gate reaches it after watch_time ln(N / (N − gate))). σ_s is the sun's own error at
// its correlated size, not as weighted: each sample's error is that large, however it averages (the Earth's
// light, its largest part, comes from the nadir, which in inertial axes turns only with the orbit). It watches
// from each start until the filter has been valid for watch_time: what it is for is a rate about the field learnt
// wrong at the start, which nothing else sees; later, a sun that disagrees is a sensor's fault (the fault tests'),
// and a restart from a single-frame attitude built on that sun would be worse than the filter.
template <class T>
void watch_sun(MekfState<T>& s, const MekfSampleInputs<T>& in, const MekfConfig<T>& c) noexcept {
    MekfSunWatch<T>& w = s.sun_watch;
    if (w.valid_for >= c.watch_time) return;
    const V3<T> sun = matrix_of(s.q) * v3(in.sun_ref).normalized();
    const T y2 = (v3(in.sun_body).normalized() - sun).squaredNorm();
    const Mat3<T> p_att = view_p(s).template block<3, 3>(kMekfAttitude, kMekfAttitude);
    const T expected = T(3) * c.sun_sigma * c.sun_sigma + p_att.trace() - sun.dot(p_att * sun);
    const T dt = in.t - w.t;
    if (!std::isfinite(y2) || !(expected > T(0)) || !(dt > T(0))) return;
    w.t = in.t;
    const T alpha = dt < c.watch_time ? dt / c.watch_time : T(1);
    w.ratio = (T(1) - alpha) * w.ratio + alpha * y2 / expected;
}

// MekfConfig::hold_field_axis: one sun direction's information (inertial axes) added to the sum.
template <class T>
void add_sun_information(MekfState<T>& s, const Vec3<T>& sun_ref, T sigma) {
    const V3<T> u = v3(sun_ref).normalized();
    if (!u.allFinite() || !(sigma > T(0))) return;
    const T w = T(1) / (sigma * sigma);
    const Mat3<T> m = w * (Mat3<T>::Identity() - u * u.transpose());
    const T add[6] = {m(0, 0), m(0, 1), m(0, 2), m(1, 1), m(1, 2), m(2, 2)};
    for (std::size_t k = 0; k < 6; ++k) s.sun_information[k] += add[k];
}

// MekfConfig::hold_field_axis: the attitude variance about the field's direction held at no less than what the
// sun alone has told of it, until that is within the validity bound.
template <class T>
void hold_field_axis(MekfState<T>& s, const Vec3<T>& field_ref, const MekfConfig<T>& c) {
    if (!c.hold_field_axis || s.field_axis_seen) return;
    const V3<T> u = v3(field_ref).normalized();
    if (!u.allFinite()) return;
    const auto& a = s.sun_information;
    Mat3<T> m;
    m << a[0], a[1], a[2], a[1], a[3], a[4], a[2], a[4], a[5];
    const T information = u.dot(m * u);
    // A sun along the field tells nothing about the turn about it: at most a half turn's variance.
    const T most = T(3.14159265358979) * T(3.14159265358979);
    const T held = information * most > T(1) ? T(1) / information : most;
    if (T(9) * held < c.valid_bound * c.valid_bound) {
        s.field_axis_seen = 1;
        return;
    }
    const V3<T> axis = matrix_of(s.q) * u;
    // The attitude block in place (a rank-one addition to it alone): no copy of the whole P per sample.
    Eigen::Map<MatN<T>> p(s.p.data());
    auto block = p.template block<3, 3>(kMekfAttitude, kMekfAttitude);
    const T now = axis.dot(block * axis);
    if (now >= held) return;
    block += (held - now) * axis * axis.transpose();
}

}  // namespace

template <class T>
void mekf_start(MekfState<T>& s, const Quaternion<T>& q, const Vec3<T>& omega, T t, const MekfConfig<T>& c) noexcept {
    s.q = normalized(q);
    s.omega = omega;
    s.t_last = t;
    s.stage = 2;
    s.refused_in_row = 0;
    s.watch = MekfWatch<T>{};
    s.watch.t = t;
    s.sun_watch = MekfSunWatch<T>{};
    s.sun_watch.t = t;
    MatN<T> p = MatN<T>::Zero();
    const T sa = c.init_attitude_sigma, sw = c.init_rate_sigma;
    for (int i = 0; i < 3; ++i) {
        p(kMekfAttitude + i, kMekfAttitude + i) = sa * sa;
        p(kMekfRate + i, kMekfRate + i) = sw * sw;
        const T so = offset_prior_sigma(s, c);
        if (c.estimate_offset) p(kMekfOffset + i, kMekfOffset + i) = so * so;
    }
    if (c.estimate_scale) p(kMekfScale, kMekfScale) = c.init_scale_sigma * c.init_scale_sigma;
    store_p<T>(s, p);
}

template <class T>
void mekf_propagate(MekfState<T>& s, T dt, const MekfConfig<T>& c) noexcept {
    if (!(dt > T(0))) return;
    const bool euler = has_inertia(c);
    Euler<T> dyn{};
    if (euler) {
        dyn.j = Eigen::Map<const Eigen::Matrix<T, 3, 3, Eigen::RowMajor>>(c.inertia.data());
        dyn.j_inv = dyn.j.inverse();
    }
    V3<T> w = v3(s.omega);
    // Kinematic: one exact step (constant rate). Euler: substeps of at most 0.05 rad of turn, 16 at most.
    int n = 1;
    if (euler) {
        const T turns = w.norm() * dt / T(0.05);
        n = turns < T(1) ? 1 : (turns > T(15) ? 16 : static_cast<int>(turns) + 1);
    }
    const T h = dt / static_cast<T>(n);
    const T qa = c.attitude_noise * c.attitude_noise, qw = c.rate_noise * c.rate_noise;
    MatN<T> p = map_p(s);
    const T attitude_before = p.template block<3, 3>(kMekfAttitude, kMekfAttitude).trace();
    MatN<T> q = MatN<T>::Zero();
    for (int i = 0; i < 3; ++i) {
        q(kMekfAttitude + i, kMekfAttitude + i) = qa * h + qw * h * h * h / T(3);
        q(kMekfAttitude + i, kMekfRate + i) = q(kMekfRate + i, kMekfAttitude + i) = qw * h * h / T(2);
        q(kMekfRate + i, kMekfRate + i) = qw * h;
        if (c.estimate_offset) q(kMekfOffset + i, kMekfOffset + i) = c.offset_noise * c.offset_noise * h;
    }
    if (c.estimate_scale) q(kMekfScale, kMekfScale) = c.scale_noise * c.scale_noise * h;
    if (euler && c.torque_noise > T(0))  // the unmodelled torques' share, through the inertia
        q.template block<3, 3>(kMekfRate, kMekfRate) +=
            c.torque_noise * c.torque_noise * h * dyn.j_inv * dyn.j_inv.transpose();
    if (euler && c.drag_density_sigma > T(0) && c.drag_correlation_time > T(0)) {
        // The density's uncertainty: the drag torque as modelled at the step's start, times its relative 1σ, as
        // white noise of the same information over drag_correlation_time (a step turns the wind by little).
        const T size = c.drag_density_sigma * drag_at<T>(s, c, matrix_of(s.q), nullptr).norm();
        if (size > T(0))
            q.template block<3, 3>(kMekfRate, kMekfRate) +=
                size * size * T(2) * c.drag_correlation_time * h * dyn.j_inv * dyn.j_inv.transpose();
    }
    const bool torques = euler && has_torques(c);
    Mat3<T> d_torque = Mat3<T>::Zero(), phi_wt = Mat3<T>::Zero();
    for (int step = 0; step < n; ++step) {
        V3<T> w_next = w;
        Mat3<T> phi_ww = Mat3<T>::Identity();
        if (torques) model_torques(s, c, dyn.j, matrix_of(s.q), dyn.torque, d_torque);
        if (euler) {  // RK4 on Euler's equations; the rate Jacobian at the midpoint
            const V3<T> k1 = dyn.rate(w);
            const V3<T> k2 = dyn.rate(w + h / T(2) * k1);
            const V3<T> k3 = dyn.rate(w + h / T(2) * k2);
            const V3<T> k4 = dyn.rate(w + h * k3);
            w_next = w + h / T(6) * (k1 + T(2) * k2 + T(2) * k3 + k4);
            phi_ww += h * dyn.jacobian(T(0.5) * (w + w_next));
        }
        const V3<T> w_mid = euler ? V3<T>(T(0.5) * (w + w_next)) : w;
        // The torques at this substep's start attitude (a substep turns at most 0.05 rad): how an attitude
        // error changes the rate through them.
        if (torques) phi_wt = h * dyn.j_inv * d_torque;
        const Quaternion<T> turn = rotation<T>(w_mid * h);
        MatN<T> phi = MatN<T>::Identity();
        phi.template block<3, 3>(kMekfAttitude, kMekfAttitude) = matrix_of(turn);
        phi.template block<3, 3>(kMekfAttitude, kMekfRate) = rate_to_attitude(w_mid, h);
        phi.template block<3, 3>(kMekfRate, kMekfRate) = phi_ww;
        if (torques) phi.template block<3, 3>(kMekfRate, kMekfAttitude) = phi_wt;
        const MatN<T> phi_p = phi.lazyProduct(p);
        p = phi_p.lazyProduct(phi.transpose()) + q;
        s.q = normalized(compose(turn, s.q));
        w = w_next;
    }
    for (int i = 0; i < 3; ++i) s.omega[i] = w(i);
    const T added = p.template block<3, 3>(kMekfAttitude, kMekfAttitude).trace() - attitude_before;
    s.memory = added > T(0) && dt > T(0) ? attitude_before * dt / added : T(0);
    store_p<T>(s, p);
    s.t_last += dt;
}

template <class T>
MekfUpdate<T> mekf_update_sun(MekfState<T>& s, const Vec3<T>& sun_ref, const Vec3<T>& sun_body,
                              const MekfConfig<T>& c) noexcept {
    const V3<T> ref = v3(sun_ref).normalized();
    const V3<T> predicted = matrix_of(s.q) * ref;
    const V3<T> y = v3(sun_body).normalized() - predicted;
    Eigen::Matrix<T, 3, kMekfStates> h = Eigen::Matrix<T, 3, kMekfStates>::Zero();
    h.template block<3, 3>(0, kMekfAttitude) = skew(predicted);
    const Mat3<T> r = c.sun_sigma * c.sun_sigma * Mat3<T>::Identity();
    return linear_update<T, 3>(s, y, h, r, c.gate);
}

namespace {

// Two axes left (one excluded): their rows i, j become one, the component of the kept pair perpendicular to
// the predicted field's projection (B_i, B_j). Three axes tell a rotation (it turns the field) from a change
// of the field's length (the on-board model's magnitude error, the calibration's scale, the currents' field
// along B: errors correlated over minutes to the orbit), since the length's innovation is outside the range
// of [B×] and moves only the offset state. On two axes the two look alike: a length error ε|B| shows as
// ε (B_i, B_j) and the full rows would read it as a turn. The perpendicular component
// (−B_j y_i + B_i y_j)/|(B_i, B_j)| is unchanged by any length change, and is what a rotation still shows
// there; the sun and the dynamics carry the rest. R is σ² I on these rows, so the one row keeps σ².
// The direction (B_i, B_j) must be known for this: a field near the excluded axis has a projection as small
// as the prediction's own error in it (its variance from P_θθ, the rows' m_k P_θθ m_kᵀ), and then it leaks
// little length error and both rows stay (3σ: the projection at least three times its uncertainty).
template <class T>
void keep_direction_only(const MekfState<T>& s, V3<T>& y, Eigen::Matrix<T, 3, kMekfStates>& h, Mat3<T>& r,
                         const V3<T>& field, int i, int j) {
    const Mat3<T> p_att = view_p(s).template block<3, 3>(kMekfAttitude, kMekfAttitude);
    const auto m_i = h.row(i).template segment<3>(kMekfAttitude);
    const auto m_j = h.row(j).template segment<3>(kMekfAttitude);
    const T uncertainty = m_i.dot(p_att * m_i.transpose()) + m_j.dot(p_att * m_j.transpose());
    const T norm2 = field(i) * field(i) + field(j) * field(j);
    if (!(norm2 > T(9) * uncertainty)) return;
    const T norm = std::sqrt(norm2);
    const T wi = -field(j) / norm, wj = field(i) / norm;
    y(i) = wi * y(i) + wj * y(j);
    h.row(i) = wi * h.row(i) + wj * h.row(j);
    y(j) = T(0);
    h.row(j).setZero();
    r(j, j) = T(1);
}

// An error of 1σ `sigma` correlated over `tau` carries, taken every `dt`, the information of white noise of
// σ √(2τ/dt) (MekfConfig::sun_correlation_time); no less than σ itself, and σ where dt is not known (0).
template <class T>
T white_equivalent_sigma(T sigma, T tau, T dt) {
    const T ratio = dt > T(0) ? T(2) * tau / dt : T(1);
    return ratio > T(1) ? sigma * std::sqrt(ratio) : sigma;
}

// An error that follows the faces as the body turns stays put for about one radian of the tumble: τ = 1/|ω̂|,
// at most `longest` (MekfConfig::mag_turn_correlation, sun_turn_correlation).
template <class T>
T turn_correlation_time(const MekfState<T>& s, T longest) {
    const T rate = std::sqrt(squared_norm(s.omega));
    return rate * longest > T(1) ? T(1) / rate : longest;
}

// What a filter whose memory is T keeps of an error correlated over τ: the information of one correlated over
// τ T/(T + τ) kept by a long memory (an exponentially weighted average over T of a first-order Gauss–Markov error
// has variance σ² τ/(T + τ); MekfConfig::mag_ref_rms). τ where T is not known (0).
template <class T>
T remembered_correlation_time(const MekfState<T>& s, T tau) {
    return s.memory > T(0) ? tau * s.memory / (s.memory + tau) : tau;
}

// The reference field's σ for one field update `step` after the last (MekfConfig::mag_ref_rms), in quadrature with
// mag_ref_sigma, and a part of the field known only within a range (MekfSampleInputs::mag_unknown_sigma): each the
// white equivalent of its correlation as the filter's memory keeps it, σ² (2τ/step) T/(T + τ), never below σ².
template <class T>
T reference_field_sigma(const MekfState<T>& s, T step, T unknown, const MekfConfig<T>& c) {
    T variance = c.mag_ref_sigma * c.mag_ref_sigma;
    if (c.mag_ref_rms > T(0) && c.mag_ref_correlation > T(0)) {
        const T tau = remembered_correlation_time(s, c.mag_ref_correlation);
        const T sigma = white_equivalent_sigma(c.mag_ref_rms, tau, step);
        variance += sigma * sigma;
    }
    if (unknown > T(0)) {
        const T tau = remembered_correlation_time(s, turn_correlation_time(s, c.mag_ref_correlation));
        const T sigma = white_equivalent_sigma(unknown, tau, step);
        variance += sigma * sigma;
    }
    return std::sqrt(variance);
}

// MekfConfig::mag_turn_fluctuation over one step.
template <class T>
T turning_field_sigma(const MekfState<T>& s, T step, const MekfConfig<T>& c) {
    return white_equivalent_sigma(c.mag_turn_fluctuation, turn_correlation_time(s, c.mag_turn_correlation), step);
}

}  // namespace

template <class T>
MekfUpdate<T> mekf_update_field(MekfState<T>& s, const Vec3<T>& field_ref, const Vec3<T>& field_body, T polarity,
                                const MekfConfig<T>& c, std::uint8_t axes) noexcept {
    // The residual in µT: in tesla the innovation covariance (~1e-14 T²) has a determinant below float's
    // smallest normal number. The offset state stays in tesla (its Jacobian carries the 1e6).
    const T micro = T(1e6);
    const V3<T> predicted_field = matrix_of(s.q) * v3(field_ref);
    V3<T> y = micro * (v3(field_body) - (predicted_field + polarity * v3(s.mag_offset)));
    Eigen::Matrix<T, 3, kMekfStates> h = Eigen::Matrix<T, 3, kMekfStates>::Zero();
    h.template block<3, 3>(0, kMekfAttitude) = skew<T>(micro * predicted_field);
    h.template block<3, 3>(0, kMekfOffset) = micro * polarity * Mat3<T>::Identity();
    const T sigma = micro * c.mag_sigma, ref_sigma = micro * c.mag_ref_sigma;
    Mat3<T> r = (sigma * sigma + ref_sigma * ref_sigma) * Mat3<T>::Identity();
    int kept[3] = {0, 0, 0}, n_kept = 0;
    for (int i = 0; i < 3; ++i) {
        if (axes >> i & 1u) {
            kept[n_kept++] = i;
            continue;
        }
        // An excluded axis: a zero row with unit variance gives it zero gain and zero NIS.
        y(i) = T(0);
        h.row(i).setZero();
        r(i, i) = T(1);
    }
    if (n_kept == 2) keep_direction_only(s, y, h, r, V3<T>(micro * predicted_field), kept[0], kept[1]);
    return linear_update<T, 3>(s, y, h, r, c.gate);
}

namespace {

// tr P_θθ, read in place.
template <class T>
T attitude_trace(const MekfState<T>& s) {
    return s.p[0] + s.p[kMekfStates + 1] + s.p[2 * kMekfStates + 2];
}

}  // namespace

template <class T>
int mekf_update_faces(MekfState<T>& s, const Vec3<T>& sun_ref, const std::array<T, 6>& r,
                      const std::array<T, 6>& albedo, std::uint8_t use, const panel_response::Response<T>& response,
                      const MekfConfig<T>& c) noexcept {
    int accepted = 0;
    const V3<T> ref = v3(sun_ref).normalized();
    for (int k = 0; k < 6; ++k) {
        if (!(use & (1u << k))) continue;
        const V3<T> sun = matrix_of(s.q) * ref;  // afresh: each accepted face moves the attitude
        V3<T> normal = V3<T>::Zero();
        normal(k / 2) = (k % 2 == 0) ? T(1) : T(-1);
        const T cos_beta = normal.dot(sun);
        // The response's slope by a central difference (the table law is C¹; the cosine's slope is 1).
        const T d = T(1e-3);
        const T slope = (panel_response::response_from_cos(response, cos_beta + d) -
                         panel_response::response_from_cos(response, cos_beta - d)) /
                        (T(2) * d);
        // The sun's share by the law, plus the Earth's: a lit face that also sees the bright Earth reads more
        // than (1 + ε) R(cos β), and without the albedo that excess would be read as a larger scale.
        const T nominal = panel_response::response_from_cos(response, cos_beta) + albedo[static_cast<std::size_t>(k)];
        const T gain = T(1) + s.panel_scale;
        Eigen::Matrix<T, 1, 1> y;
        y(0) = r[static_cast<std::size_t>(k)] - gain * nominal;
        Eigen::Matrix<T, 1, kMekfStates> h = Eigen::Matrix<T, 1, kMekfStates>::Zero();
        // Only the scale is updated: the attitude enters through the prediction but its column is left out,
        // so that the albedo on a face and the angular law's model error (which the scale cannot absorb)
        // do not pull the attitude. The slope still counts in the innovation's variance.
        const T attitude_variance = (gain * slope * normal.cross(sun)).squaredNorm() * attitude_trace(s) / T(3);
        h(0, kMekfScale) = nominal;
        Eigen::Matrix<T, 1, 1> rr;
        rr(0, 0) = c.face_sigma * c.face_sigma + attitude_variance;
        if (linear_update<T, 1>(s, y, h, rr, c.face_gate).accepted) ++accepted;
    }
    return accepted;
}

template <class T>
T mekf_attitude_bound(const MekfState<T>& s) noexcept {
    const T trace = attitude_trace(s);
    return T(3) * std::sqrt(trace > T(0) ? trace : T(0));
}

template <class T>
T mekf_attitude_bound(const MekfState<T>& s, const MekfConfig<T>& c) noexcept {
    const T trace = attitude_trace(s) + c.mag_ref_tilt * c.mag_ref_tilt;
    return T(3) * std::sqrt(trace > T(0) ? trace : T(0));
}

namespace {

// MekfConfig::mag_ref_tilt's variance in body axes: tilt² along the on-board orbit's normal r × v (v the wind plus
// the air's own motion with the Earth, ω_E ẑ × r), tilt²/3 per axis without an orbit.
template <class T>
Mat3<T> considered_tilt(const MekfState<T>& s, const MekfConfig<T>& c) {
    const T variance = c.mag_ref_tilt * c.mag_ref_tilt;
    if (!(variance > T(0))) return Mat3<T>::Zero();
    const V3<T> r = v3(s.torque_position);
    const T omega_earth = static_cast<T>(ground::atmosphere::kEarthRotationRate);
    const V3<T> v = v3(s.torque_air_velocity) + omega_earth * V3<T>(-r(1), r(0), T(0));
    const V3<T> normal = r.cross(v);
    if (!(normal.squaredNorm() > T(0))) return variance / T(3) * Mat3<T>::Identity();
    const V3<T> body = matrix_of(s.q) * normal.normalized();
    return variance * body * body.transpose();
}

}  // namespace

template <class T>
Matrix3RowMajor<T> mekf_attitude_covariance(const MekfState<T>& s, const MekfConfig<T>& c) noexcept {
    const Mat3<T> p = view_p(s).template block<3, 3>(kMekfAttitude, kMekfAttitude) + considered_tilt(s, c);
    Matrix3RowMajor<T> out{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) out[static_cast<std::size_t>(3 * i + j)] = T(0.5) * (p(i, j) + p(j, i));
    return out;
}

namespace {

// mekf_valid with the bound already at hand (mekf_sample reports it too).
template <class T>
bool valid_at(T bound, const MekfState<T>& s, const MekfConfig<T>& c) {
    return s.stage == 2 && bound < c.valid_bound && s.refused_in_row < c.reset_after;
}

}  // namespace

template <class T>
bool mekf_valid(const MekfState<T>& s, const MekfConfig<T>& c) noexcept {
    return valid_at(mekf_attitude_bound(s, c), s, c);
}

template <class T>
MekfSampleResult<T> mekf_sample(MekfState<T>& s, const MekfSampleInputs<T>& in, const MekfConfig<T>& c) noexcept {
    MekfSampleResult<T> result;
    // The torque models' surroundings for the step to this sample (they change by a few thousandths of a
    // degree in one).
    if (squared_norm(in.mag_ref) > T(0)) s.torque_field = in.mag_ref;
    if (squared_norm(in.position) > T(0)) s.torque_position = in.position;
    if (squared_norm(in.air_velocity) > T(0) && in.air_density > T(0)) {
        s.torque_air_velocity = in.air_velocity;
        s.torque_air_density = in.air_density;
    }
    const T step = s.stage == 2 ? in.t - s.t_last : T(0);
    if (s.stage == 2) {
        mekf_propagate(s, step, c);
    } else {
        // Initialisation from two single-frame attitudes: the first gives the attitude, the difference to the
        // second (close enough not to alias) the rate.
        if (in.attitude_valid) {
            const T gap = in.t - s.t_first;
            if (s.stage == 1 && gap > T(0) && gap <= c.max_init_gap) {
                const Quaternion<T> inverse_first{-s.q_first.x, -s.q_first.y, -s.q_first.z, s.q_first.w};
                const V3<T> turn = rotation_vector(compose(in.q_single, inverse_first));
                const V3<T> w = turn / gap;
                mekf_start(s, in.q_single, Vec3<T>{w.x(), w.y(), w.z()}, in.t, c);
                // The differenced rate carries both attitudes' errors.
                MatN<T> p = map_p(s);
                for (int i = 0; i < 3; ++i)
                    p(kMekfRate + i, kMekfRate + i) +=
                        T(2) * c.init_attitude_sigma * c.init_attitude_sigma / (gap * gap);
                // Fused with the rate known before (zero ± start_rate_sigma per axis): the rate block is diagonal
                // and uncorrelated with the rest here, so per axis a scalar update.
                if (c.start_rate_sigma > T(0)) {
                    const T prior = c.start_rate_sigma * c.start_rate_sigma;
                    for (int i = 0; i < 3; ++i) {
                        const T measured = p(kMekfRate + i, kMekfRate + i);
                        const T keep = prior / (prior + measured);
                        s.omega[static_cast<std::size_t>(i)] *= keep;
                        p(kMekfRate + i, kMekfRate + i) = keep * measured;
                    }
                }
                store_p<T>(s, p);
                add_offset_to_start(s, in, c);
                s.sun_information = {};
                s.field_axis_seen = 0;
                // The single-frame attitude's own: one sun of σ_s turns it about axes across the sun only, so about
                // the field by σ_s / sin θ, θ the sun's angle from it (Shuster and Oh's covariance, the sun's part).
                if (c.hold_field_axis && in.sun_valid) {
                    add_sun_information(s, in.sun_ref, c.sun_sigma);
                    hold_field_axis(s, in.mag_ref, c);
                }
            } else {
                s.stage = 1;
                s.q_first = in.q_single;
                s.t_first = in.t;
            }
        } else if (s.stage == 1 && in.t - s.t_first > c.max_init_gap) {
            s.stage = 0;
        }
        return result;  // the starting sample's measurements are already in the single-frame attitude
    }

    int offered = 0, accepted = 0;
    if (in.sun_valid) {
        // A correlated sun error enters as the white noise of the same information (MekfConfig).
        MekfConfig<T> sun_config = c;
        if (c.sun_correlation_time > T(0)) {
            const T tau =
                c.sun_turn_correlation ? turn_correlation_time(s, c.sun_correlation_time) : c.sun_correlation_time;
            sun_config.sun_sigma = white_equivalent_sigma(c.sun_sigma, tau, s.has_sun ? in.t - s.t_sun : T(0));
        }
        s.t_sun = in.t;
        s.has_sun = 1;
        if (c.watch_time > T(0) && c.watch_sun) watch_sun(s, in, c);
        result.sun = mekf_update_sun(s, in.sun_ref, in.sun_body, sun_config);
        if (c.hold_field_axis && !s.field_axis_seen && result.sun.accepted)
            add_sun_information(s, in.sun_ref, sun_config.sun_sigma);
        ++offered;
        accepted += result.sun.accepted;
    }
    if (in.mag_valid) {
        const std::int32_t calibrated = in.mag_calibrated ? 1 : 0;
        const bool changed = calibrated != s.mag_calibrated;
        s.mag_calibrated = calibrated;
        if (changed && c.estimate_offset) restart_offset(s, c);
        MekfConfig<T> mag_config = c;
        if (in.mag_calibrated && c.mag_sigma_calibrated > T(0)) mag_config.mag_sigma = c.mag_sigma_calibrated;
        if (in.mag_calibrated && !in.sun_valid && c.mag_sigma_calibrated_eclipse > T(0))
            mag_config.mag_sigma = c.mag_sigma_calibrated_eclipse;
        if (!in.mag_calibrated && c.mag_turn_fluctuation > T(0) && step > T(0))
            mag_config.mag_sigma = turning_field_sigma(s, step, c);
        mag_config.mag_ref_sigma = reference_field_sigma(s, step, in.mag_unknown_sigma, c);
        const T polarity = holds_hard_iron(s, c) ? T(1) : in.polarity;
        // The watch needs the three axes (an excluded axis leaves no field to turn into inertial axes).
        if (c.watch_time > T(0) && in.mag_axes == 7) watch_field(s, in, polarity, mag_config);
        result.mag = mekf_update_field(s, in.mag_ref, in.mag_body, polarity, mag_config, in.mag_axes);
        ++offered;
        accepted += result.mag.accepted;
    }
    if (c.estimate_scale && in.sun_valid && in.response != nullptr && in.face_use != 0)
        result.faces_accepted =
            mekf_update_faces(s, in.sun_ref, in.face_r, in.face_albedo, in.face_use, *in.response, c);
    if (squared_norm(in.mag_ref) > T(0)) hold_field_axis(s, in.mag_ref, c);

    // (Held at reset_after while a refused run waits for a single frame: it cannot overflow in a long eclipse.)
    if (offered > 0) s.refused_in_row = accepted > 0 ? 0 : std::min<std::int32_t>(s.refused_in_row + 1, c.reset_after);
    result.lost =
        c.watch_time > T(0) && (s.watch.ratio > c.watch_gate || (c.watch_sun && s.sun_watch.ratio > c.watch_gate));
    // A reset starts over from the single-frame attitude; without one (no sun: eclipse) it would leave no filter
    // until the sun returns, and the fault tests no prediction to judge the field by (a bias jump in eclipse
    // was declared only after the sun's return). So a refused run waits for a single frame to restart from,
    // the filter coasting on its dynamics meanwhile, not valid (docs/filter.md, "Tuning with the drag on board").
    const bool refused_run = s.refused_in_row >= c.reset_after;
    if ((refused_run && in.attitude_valid) || !finite(s) || result.lost) {
        // Diverged: back to the single-frame attitude (and a fresh rate from the next one).
        ++s.resets;
        result.reset = true;
        s.refused_in_row = 0;
        if (!finite(s)) {
            s.omega = {};
            s.mag_offset = {};
            s.panel_scale = T(0);
        }
        s.stage = in.attitude_valid ? 1 : 0;
        s.q_first = in.q_single;
        s.t_first = in.t;
        return result;
    }
    result.bound = mekf_attitude_bound(s, c);
    result.valid = valid_at(result.bound, s, c);
    if (result.valid && step > T(0) && s.sun_watch.valid_for < c.watch_time) s.sun_watch.valid_for += step;
    return result;
}

#define ATTITUDE_ESTIMATOR_MEKF_INSTANTIATE(T)                                                                       \
    template void mekf_start(MekfState<T>&, const Quaternion<T>&, const Vec3<T>&, T, const MekfConfig<T>&) noexcept; \
    template void mekf_propagate(MekfState<T>&, T, const MekfConfig<T>&) noexcept;                                   \
    template MekfUpdate<T> mekf_update_sun(MekfState<T>&, const Vec3<T>&, const Vec3<T>&,                            \
                                           const MekfConfig<T>&) noexcept;                                           \
    template MekfUpdate<T> mekf_update_field(MekfState<T>&, const Vec3<T>&, const Vec3<T>&, T, const MekfConfig<T>&, \
                                             std::uint8_t) noexcept;                                                 \
    template int mekf_update_faces(MekfState<T>&, const Vec3<T>&, const std::array<T, 6>&, const std::array<T, 6>&,  \
                                   std::uint8_t, const panel_response::Response<T>&, const MekfConfig<T>&) noexcept; \
    template T mekf_attitude_bound(const MekfState<T>&) noexcept;                                                    \
    template T mekf_attitude_bound(const MekfState<T>&, const MekfConfig<T>&) noexcept;                              \
    template Matrix3RowMajor<T> mekf_attitude_covariance(const MekfState<T>&, const MekfConfig<T>&) noexcept;        \
    template bool mekf_valid(const MekfState<T>&, const MekfConfig<T>&) noexcept;                                    \
    template MekfSampleResult<T> mekf_sample(MekfState<T>&, const MekfSampleInputs<T>&, const MekfConfig<T>&) noexcept;
ATTITUDE_ESTIMATOR_MEKF_INSTANTIATE(float)
ATTITUDE_ESTIMATOR_MEKF_INSTANTIATE(double)
#undef ATTITUDE_ESTIMATOR_MEKF_INSTANTIATE

}  // namespace attitude_estimator
