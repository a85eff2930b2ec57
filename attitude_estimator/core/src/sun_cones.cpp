// Sun vector from intersecting cones of orthogonal lit faces (seed 002 eq. 13–20), with mirror and albedo
// rejection and the 27-state panel cube (docs/sun_methods.md).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>

#include "attitude_estimator/sun_methods.hpp"
#include "attitude_estimator/vec3_math.hpp"
#include "sun_methods_detail.hpp"

namespace attitude_estimator {
namespace {

using detail::face_axis;
using detail::face_bit;
using detail::face_sign;

// 12 orthogonal pairs × 2 candidates + 6 single-face candidates.
constexpr int kMaxCandidates = 30;

template <class T>
struct Candidate {
    Vec3<T> v{};
    std::uint8_t faces = 0;   // the faces whose cones made it
    bool feasible = false;    // no face reads below the candidate's prediction (light cannot be removed)
    std::uint8_t agree = 0;   // lit faces whose reading matches the prediction
    std::uint8_t excess = 0;  // lit faces reading above the prediction: albedo
    int n_agree = 0;
    T sq = T(0);          // Σ (R(v·n) − r)² over the agreeing faces
    T excess_sum = T(0);  // Σ (r − R(v·n)) over the excess faces
    int cube = kCubeDark;
};

template <class T>
void evaluate(Candidate<T>& cand, const FaceReadings<T>& fr, const SunMethodConfig<T>& cfg) noexcept {
    cand.feasible = true;
    int s[3] = {0, 0, 0};
    for (int k = 0; k < 6; ++k) {
        const T cosb = T(face_sign(k)) * cand.v[face_axis(k)];
        const T pred = panel_response::response_from_cos(cfg.response, cosb);
        const T d = fr.r[k] - pred;
        if (pred > cfg.dark_threshold) s[face_axis(k)] = face_sign(k);
        if (d < -cfg.cone_tolerance) {
            cand.feasible = false;  // e.g. the mirror candidate lighting a face that reads dark
        } else if (d > cfg.cone_tolerance) {
            if (fr.lit & face_bit(k)) {
                cand.excess |= face_bit(k);
                cand.excess_sum += d;
            }
        } else if (fr.lit & face_bit(k)) {
            cand.agree |= face_bit(k);
            ++cand.n_agree;
            cand.sq += d * d;
        }
    }
    cand.cube = cube_state_of(s[0], s[1], s[2]);
}

// Is a better than b? More agreeing faces; then (ties: the data alone cannot tell which of the faces is
// polluted) closer to the last accepted direction when there is one, else less albedo needed to explain
// the readings; then the smaller misfit.
template <class T>
bool better(const Candidate<T>& a, const Candidate<T>& b, const SunMethodState<T>& state) noexcept {
    if (a.n_agree != b.n_agree) return a.n_agree > b.n_agree;
    if (state.has_last) {
        const T da = dot(a.v, state.last_unit), db = dot(b.v, state.last_unit);
        if (std::abs(da - db) > T(1e-4)) return da > db;
    }
    if (std::abs(a.excess_sum - b.excess_sum) > T(1e-6)) return a.excess_sum < b.excess_sum;
    return a.sq < b.sq;
}

// The model-free cones (seed 002): pair intersections, mirror and albedo rejection by agreement counts.
template <class T>
SunMethodResult<T> cones_candidates(const FaceReadings<T>& fr, const SunMethodConfig<T>& cfg,
                                    SunMethodState<T>& state) noexcept {
    SunMethodResult<T> out;
    out.lit_faces = fr.lit;
    std::array<T, 6> c{};  // cone half-angle cosines: cos β_k from the inverse response
    for (int k = 0; k < 6; ++k)
        if (fr.lit & face_bit(k)) c[k] = panel_response::cos_from_response(cfg.response, fr.r[k]);

    std::array<Candidate<T>, kMaxCandidates> cand{};
    int n = 0;
    for (int f = 0; f < 6; ++f) {
        if (!(fr.lit & face_bit(f))) continue;
        // Alone: the face's own normal (the sun within the dark zone of every other face).
        Candidate<T>& single = cand[n++];
        single.v[face_axis(f)] = T(face_sign(f));
        single.faces = face_bit(f);
        for (int g = f + 1; g < 6; ++g) {
            if (!(fr.lit & face_bit(g)) || face_axis(g) == face_axis(f)) continue;  // opposite faces: no pair
            // Cones about the two orthogonal normals with a common origin (002 eq. 13–18) meet where
            // s·n_f = cos β_f and s·n_g = cos β_g; with |s| = 1 the third component is ±√(1 − c_f² − c_g²)
            // (eq. 19–20 solved for the components: the two candidates, mirror images across the pair's plane).
            const int af = face_axis(f), ag = face_axis(g), at = 3 - af - ag;
            T rem = T(1) - c[f] * c[f] - c[g] * c[g];
            if (rem < -T(2) * cfg.cone_tolerance) continue;  // the cones do not meet: combined angles < 90°
            if (rem < T(0)) rem = T(0);
            const T st = std::sqrt(rem);
            for (int sign = 1; sign >= -1; sign -= 2) {
                if (sign < 0 && st == T(0)) break;  // tangent cones: a single line
                Candidate<T>& k = cand[n++];
                k.v[af] = T(face_sign(f)) * c[f];
                k.v[ag] = T(face_sign(g)) * c[g];
                k.v[at] = T(sign) * st;
                const T len = std::sqrt(squared_norm(k.v));
                k.v = scaled(k.v, T(1) / len);
                k.faces = static_cast<std::uint8_t>(face_bit(f) | face_bit(g));
            }
        }
    }
    for (int i = 0; i < n; ++i) evaluate(cand[i], fr, cfg);

    // Choose among feasible candidates the transition graph allows; remember whether it refused any.
    int best = -1, best_any = -1;
    for (int i = 0; i < n; ++i) {
        if (!cand[i].feasible) continue;
        if (best_any < 0 || better(cand[i], cand[best_any], state)) best_any = i;
        const bool small_step = state.has_last && cfg.cube_max_step > T(0) &&
                                dot(cand[i].v, state.last_unit) >= std::cos(cfg.cube_max_step);
        if (!small_step && !cube_transition_allowed(state.cube_state, cand[i].cube)) continue;
        if (best < 0 || better(cand[i], cand[best], state)) best = i;
    }
    if (best < 0 && best_any >= 0) {
        // Every feasible explanation needs a jump the panel cube forbids (e.g. +x straight to −x).
        ++state.refusals;
        if (cfg.cube_refusals_before_reset > 0 && state.refusals >= cfg.cube_refusals_before_reset) {
            best = best_any;  // persistent: a missed sample, not a glitch; accept and start tracking again
        } else {
            out.cube_state = state.cube_state;
            out.rejected_faces = fr.lit;
            return out;
        }
    }
    if (best < 0) {  // nothing fits (e.g. the only intersections would light faces that read dark)
        out.cube_state = state.cube_state;
        out.rejected_faces = fr.lit;
        return out;
    }
    const Candidate<T>& b = cand[best];
    // Average the candidates of the agreeing pairs that cluster around the chosen one. The chosen candidate's
    // mirror joins when it explains exactly the same faces (both feasible: the third component is inside the
    // dark band of both its faces, sign unknown): the average puts it at 0, halving the worst error.
    Vec3<T> sum{};
    const T cos_cluster = std::cos(cfg.cone_cluster_angle);
    int used = 0;
    for (int i = 0; i < n; ++i) {
        const Candidate<T>& k = cand[i];
        if (!k.feasible || (k.faces & ~b.agree) != 0) continue;
        if (k.faces != b.faces && (k.faces & (k.faces - 1)) == 0) continue;  // single-face: only as the choice
        const bool mirror = k.faces == b.faces && k.agree == b.agree && k.excess == b.excess;
        if (!mirror && dot(k.v, b.v) < cos_cluster) continue;
        for (int j = 0; j < 3; ++j) sum[j] += k.v[j];
        ++used;
    }
    const T len = std::sqrt(squared_norm(sum));
    out.unit = (used > 0 && len > T(0)) ? scaled(sum, T(1) / len) : b.v;
    out.rejected_faces = static_cast<std::uint8_t>(fr.lit & ~b.agree);
    {
        int s[3] = {0, 0, 0};  // the cube state of the direction returned
        for (int k = 0; k < 6; ++k)
            if (panel_response::response_from_cos(cfg.response, T(face_sign(k)) * out.unit[face_axis(k)]) >
                cfg.dark_threshold)
                s[face_axis(k)] = face_sign(k);
        out.cube_state = cube_state_of(s[0], s[1], s[2]);
    }
    out.residual = b.n_agree > 0 ? std::sqrt(b.sq / T(b.n_agree)) : T(0);
    T n2 = T(0);
    for (int k = 0; k < 6; ++k)
        if (b.agree & face_bit(k)) n2 += c[k] * c[k];
    out.norm = std::sqrt(n2);
    out.valid = b.n_agree >= 1;
    state.cube_state = out.cube_state;
    state.refusals = 0;
    state.last_unit = out.unit;
    state.has_last = true;
    return out;
}

// ---- The albedo model: the Earth as a uniformly bright sphere seen from the orbit ----
//
// A face whose normal is at θ to the nadir d receives α G(cos θ), α the albedo of a face squarely toward
// the Earth (relative to full sun) and G the sphere's light weighed by the panels' response
// (cone_albedo_shape.hpp: the closed-form view factor for cosine panels, the configured table otherwise).
// A face at 90° to the nadir still gets G(0) ≈ 0.30 (cosine, 570 km): several faces share the Earth's
// light, which is what ties them to one nadir.
template <class T>
T albedo_shape(const SunMethodConfig<T>& cfg, T cos_t, T inv_h) noexcept {
    return cone_albedo_shape(cfg.cone_albedo_shape, cos_t, inv_h);
}

template <class T>
Vec3<T> unit_of(const Vec3<T>& v) noexcept {
    const T n = std::sqrt(squared_norm(v));
    return n > T(0) ? scaled(v, T(1) / n) : v;
}

// Two unit vectors orthogonal to the unit v (the tangent plane the fit moves v in).
template <class T>
void tangent_basis(const Vec3<T>& v, Vec3<T>& e1, Vec3<T>& e2) noexcept {
    const Vec3<T> a = std::abs(v[0]) > T(0.6) ? Vec3<T>{T(0), T(1), T(0)} : Vec3<T>{T(1), T(0), T(0)};
    e1 = unit_of(cross(v, a));
    e2 = cross(v, e1);
}

template <class T>
Vec3<T> moved(const Vec3<T>& v, const Vec3<T>& e1, const Vec3<T>& e2, T a, T b) noexcept {
    return unit_of(Vec3<T>{v[0] + a * e1[0] + b * e2[0], v[1] + a * e1[1] + b * e2[1], v[2] + a * e1[2] + b * e2[2]});
}

// Residuals of the model r_k = R(s·n_k) + α G(d·n_k) on the six faces, and two penalties: the satellite is
// sunlit, so the sun is at least 90° − λ from the nadir (s·d ≤ cos λ); α ≤ cone_albedo_max.
constexpr int kResiduals = 8;
template <class T>
struct ModelFit {
    Vec3<T> s{};     // sun
    Vec3<T> d{};     // nadir (the centre of the equivalent uniform sphere)
    T alpha = T(0);  // albedo of a face squarely toward the Earth, relative
    T cost = T(0);   // Σ residual²
};

template <class T>
void model_residuals(const ModelFit<T>& m, const FaceReadings<T>& fr, const SunMethodConfig<T>& cfg, T inv_h,
                     T cos_lambda, std::array<T, kResiduals>& e) noexcept {
    for (int k = 0; k < 6; ++k) {
        const T sg = T(face_sign(k));
        e[k] = panel_response::response_from_cos(cfg.response, sg * m.s[face_axis(k)]) +
               m.alpha * albedo_shape(cfg, sg * m.d[face_axis(k)], inv_h) - fr.r[k];
    }
    e[6] = std::max(T(0), dot(m.s, m.d) - cos_lambda);
    e[7] = std::max(T(0), m.alpha - cfg.cone_albedo_max);
}

template <class T>
T sum_sq(const std::array<T, kResiduals>& e) noexcept {
    T c = T(0);
    for (T x : e) c += x * x;
    return c;
}

// 5×5 linear system by Gaussian elimination with partial pivoting; false when singular.
template <class T>
bool solve5(std::array<std::array<T, 5>, 5> a, std::array<T, 5> b, std::array<T, 5>& x) noexcept {
    for (int c = 0; c < 5; ++c) {
        int p = c;
        for (int i = c + 1; i < 5; ++i)
            if (std::abs(a[i][c]) > std::abs(a[p][c])) p = i;
        if (!(std::abs(a[p][c]) > T(0))) return false;
        std::swap(a[p], a[c]);
        std::swap(b[p], b[c]);
        for (int i = c + 1; i < 5; ++i) {
            const T f = a[i][c] / a[c][c];
            for (int j = c; j < 5; ++j) a[i][j] -= f * a[c][j];
            b[i] -= f * b[c];
        }
    }
    for (int i = 4; i >= 0; --i) {
        T v = b[i];
        for (int j = i + 1; j < 5; ++j) v -= a[i][j] * x[j];
        x[i] = v / a[i][i];
    }
    return true;
}

// Levenberg–Marquardt on (s, d on the unit sphere, α ≥ 0), forward-difference Jacobian.
// Stops early when converged (a step that lowers the cost by less than 1e-6 of it) or hopeless
// (still 100 × the admissible cost budget `max_cost` after 3 iterations, 16 × after 6).
template <class T>
void fit_model(ModelFit<T>& m, const FaceReadings<T>& fr, const SunMethodConfig<T>& cfg, T inv_h, T cos_lambda,
               T max_cost) noexcept {
    constexpr int kIterations = 20;
    const T step = sizeof(T) < sizeof(double) ? T(1e-3) : T(1e-6);
    std::array<T, kResiduals> e{};
    model_residuals(m, fr, cfg, inv_h, cos_lambda, e);
    m.cost = sum_sq(e);
    T mu = T(1e-3);
    for (int it = 0; it < kIterations && m.cost > T(0); ++it) {
        if ((it >= 3 && m.cost > T(100) * max_cost) || (it >= 6 && m.cost > T(16) * max_cost)) break;
        Vec3<T> s1, s2, d1, d2;
        tangent_basis(m.s, s1, s2);
        tangent_basis(m.d, d1, d2);
        std::array<std::array<T, kResiduals>, 5> jac{};
        for (int p = 0; p < 5; ++p) {
            ModelFit<T> q = m;
            if (p == 0) q.s = moved(m.s, s1, s2, step, T(0));
            if (p == 1) q.s = moved(m.s, s1, s2, T(0), step);
            if (p == 2) q.d = moved(m.d, d1, d2, step, T(0));
            if (p == 3) q.d = moved(m.d, d1, d2, T(0), step);
            if (p == 4) q.alpha = m.alpha + step;
            std::array<T, kResiduals> eq{};
            model_residuals(q, fr, cfg, inv_h, cos_lambda, eq);
            for (int k = 0; k < kResiduals; ++k) jac[p][k] = (eq[k] - e[k]) / step;
        }
        std::array<std::array<T, 5>, 5> a{};
        std::array<T, 5> g{};
        for (int p = 0; p < 5; ++p) {
            for (int q = 0; q < 5; ++q) {
                T v = T(0);
                for (int k = 0; k < kResiduals; ++k) v += jac[p][k] * jac[q][k];
                a[p][q] = v;
            }
            T v = T(0);
            for (int k = 0; k < kResiduals; ++k) v += jac[p][k] * e[k];
            g[p] = -v;
        }
        bool improved = false, converged = false;
        for (int tries = 0; tries < 6 && !improved; ++tries) {
            std::array<std::array<T, 5>, 5> b = a;
            for (int p = 0; p < 5; ++p) b[p][p] += mu * (a[p][p] + T(1e-6));
            std::array<T, 5> x{};
            if (!solve5(b, g, x)) {
                mu *= T(10);
                continue;
            }
            ModelFit<T> n;
            n.s = moved(m.s, s1, s2, x[0], x[1]);
            n.d = moved(m.d, d1, d2, x[2], x[3]);
            n.alpha = std::max(T(0), m.alpha + x[4]);
            std::array<T, kResiduals> en{};
            model_residuals(n, fr, cfg, inv_h, cos_lambda, en);
            n.cost = sum_sq(en);
            if (n.cost < m.cost) {
                converged = n.cost > m.cost * T(1 - 1e-6);
                m = n;
                e = en;
                mu = std::max(mu * T(0.3), T(1e-7));
                improved = true;
            } else {
                mu *= T(10);
            }
        }
        if (!improved || converged) break;
    }
}

// An axis whose fitted sun component lies in the dark band (|s_k| ≤ dark_cos) is not determined by the fit
// (the response is flat there, 0 from 85° with Kelly). Its component is taken from what the face toward it
// reads above the fitted albedo, faded to 0 when that excess is within `fade` of the opposite face's (no sign
// information: 0 halves the worst error); fade = a quarter of the albedo the model puts on the axis's two
// faces (the model's own uncertainty there), between dark_threshold/20 and dark_threshold/2.
template <class T>
void settle_dark_axes(ModelFit<T>& m, const FaceReadings<T>& fr, const SunMethodConfig<T>& cfg, T inv_h) noexcept {
    const T dark = panel_response::dark_cos(cfg.response, cfg.dark_threshold);
    for (int ax = 0; ax < 3; ++ax) {
        if (std::abs(m.s[ax]) > dark) continue;
        const T ap = m.alpha * albedo_shape(cfg, m.d[ax], inv_h), am = m.alpha * albedo_shape(cfg, -m.d[ax], inv_h);
        const T fade = std::min(cfg.dark_threshold / T(2), std::max(cfg.dark_threshold / T(20), (ap + am) / T(4)));
        const T ep = fr.r[2 * ax] - ap;
        const T em = fr.r[2 * ax + 1] - am;
        const T diff = std::abs(ep - em);
        const T w = (fade > T(0) && diff < fade) ? diff / fade : T(1);
        T v = T(0);
        if (ep > em && ep > T(0)) v = w * std::min(dark, panel_response::cos_from_response(cfg.response, ep));
        if (em > ep && em > T(0)) v = -w * std::min(dark, panel_response::cos_from_response(cfg.response, em));
        T o2 = T(0);
        for (int j = 0; j < 3; ++j)
            if (j != ax) o2 += m.s[j] * m.s[j];
        if (!(o2 > T(0))) continue;
        const T sc = std::sqrt(std::max(T(0), T(1) - v * v) / o2);
        for (int j = 0; j < 3; ++j) m.s[j] = (j == ax) ? v : m.s[j] * sc;
    }
}

template <class T>
int cube_of_direction(const Vec3<T>& u, const SunMethodConfig<T>& cfg) noexcept {
    int s[3] = {0, 0, 0};
    for (int k = 0; k < 6; ++k)
        if (panel_response::response_from_cos(cfg.response, T(face_sign(k)) * u[face_axis(k)]) > cfg.dark_threshold)
            s[face_axis(k)] = face_sign(k);
    return cube_state_of(s[0], s[1], s[2]);
}

// The 27 per-axis hypotheses (+ face sunlit, − face sunlit, neither), each started from its cones (the lit
// faces' cos β with their signs: the pair intersections of eq. 13–20 taken together) and an albedo seed
// from the faces the hypothesis leaves to the Earth, fitted with the model; the best fit the cube graph
// allows. Returns false when no fit is within cone_fit_tolerance (the model-free cones decide then).
template <class T>
bool cones_albedo_model(const FaceReadings<T>& fr, const SunMethodConfig<T>& cfg, SunMethodState<T>& state,
                        SunMethodResult<T>& out) noexcept {
    const T sin_l = cfg.cone_earth_sin_radius;
    if (!(cfg.cone_fit_tolerance > T(0)) || !(sin_l > T(0) && sin_l < T(1))) return false;
    const T inv_h = sin_l, cos_lambda = std::sqrt(T(1) - sin_l * sin_l);
    const T max_cost = T(6) * cfg.cone_fit_tolerance * cfg.cone_fit_tolerance;
    ModelFit<T> fits[27];
    bool ok[27] = {};
    int best = -1;
    for (int h = 0; h < 27; ++h) {
        const int hyp[3] = {cube_axis(h, 0), cube_axis(h, 1), cube_axis(h, 2)};
        if (h == kCubeDark) continue;
        ModelFit<T> m;
        Vec3<T> earth{};
        T seed_alpha = T(0);
        bool usable = true;
        for (int ax = 0; ax < 3 && usable; ++ax) {
            const int p = 2 * ax, q = 2 * ax + 1;
            if (hyp[ax] == 0) {
                earth[ax] = fr.r[p] - fr.r[q];
                seed_alpha = std::max(seed_alpha, std::max(fr.r[p], fr.r[q]));
                continue;
            }
            const int f = hyp[ax] > 0 ? p : q, g = hyp[ax] > 0 ? q : p;
            if (!(fr.lit & face_bit(f))) {
                usable = false;
                break;
            }
            m.s[ax] = T(hyp[ax]) * panel_response::cos_from_response(cfg.response, fr.r[f]);
            earth[ax] = -T(hyp[ax]) * fr.r[g];
            seed_alpha = std::max(seed_alpha, fr.r[g]);
        }
        if (!usable || !(squared_norm(m.s) > T(0))) continue;
        m.s = unit_of(m.s);
        m.d = squared_norm(earth) > T(1e-8) ? unit_of(earth) : scaled(m.s, T(-1));
        m.alpha = std::min(seed_alpha, cfg.cone_albedo_max);
        fit_model(m, fr, cfg, inv_h, cos_lambda, max_cost);
        if (!(m.cost <= max_cost)) continue;
        settle_dark_axes(m, fr, cfg, inv_h);
        fits[h] = m;
        ok[h] = true;
        if (best < 0 || m.cost < fits[best].cost) best = h;
    }
    if (best < 0) return false;
    // Fits that explain the readings as well as the best one (within a hundredth of the cost budget) are the
    // single-sample ambiguities (the mirror of sun and Earth across an axis whose two faces read alike). Among
    // them the cube graph's allowed ones, and of those the one closest to the last accepted direction when
    // there is one, else the best.
    const T near_cost = fits[best].cost + max_cost / T(100);
    int pick = -1;
    for (int h = 0; h < 27; ++h) {
        if (!ok[h] || fits[h].cost > near_cost) continue;
        const bool small_step = state.has_last && cfg.cube_max_step > T(0) &&
                                dot(fits[h].s, state.last_unit) >= std::cos(cfg.cube_max_step);
        if (!small_step && !cube_transition_allowed(state.cube_state, cube_of_direction(fits[h].s, cfg))) continue;
        if (pick < 0) {
            pick = h;
        } else if (state.has_last) {
            if (dot(fits[h].s, state.last_unit) > dot(fits[pick].s, state.last_unit) + T(1e-4)) pick = h;
        } else if (fits[h].cost < fits[pick].cost) {
            pick = h;
        }
    }
    if (pick < 0) {
        // The readings' explanation needs a jump the panel cube forbids (e.g. +x straight to −x): refused as in
        // the model-free path (the candidates there would only explain the Earth's light as sun), until
        // darkness or cube_refusals_before_reset consecutive refusals (then the jump is accepted).
        ++state.refusals;
        if (!(cfg.cube_refusals_before_reset > 0 && state.refusals >= cfg.cube_refusals_before_reset)) {
            out.valid = false;
            out.cube_state = state.cube_state;
            out.rejected_faces = fr.lit;
            return true;
        }
        pick = best;
    }
    best = pick;
    const ModelFit<T>& m = fits[best];
    out.unit = m.s;
    out.valid = true;
    out.cube_state = cube_of_direction(m.s, cfg);
    std::uint8_t rejected = 0;
    T n2 = T(0);
    for (int k = 0; k < 6; ++k) {
        const T earth = m.alpha * albedo_shape(cfg, T(face_sign(k)) * m.d[face_axis(k)], inv_h);
        out.face_albedo[static_cast<std::size_t>(k)] = earth;
        if (!(fr.lit & face_bit(k))) continue;
        const T sun = panel_response::response_from_cos(cfg.response, T(face_sign(k)) * m.s[face_axis(k)]);
        if (sun <= cfg.dark_threshold || earth > cfg.cone_tolerance) {
            rejected |= face_bit(k);  // lit by the Earth only, or carrying more albedo than the agreement band
        } else {
            const T c = panel_response::cos_from_response(cfg.response, fr.r[k]);
            n2 += c * c;
        }
    }
    out.rejected_faces = rejected;
    out.residual = std::sqrt(m.cost / T(6));
    out.norm = std::sqrt(n2);
    state.cube_state = out.cube_state;
    state.refusals = 0;
    state.last_unit = out.unit;
    state.has_last = true;
    return true;
}

}  // namespace

template <class T>
SunMethodResult<T> sun_cones(const std::array<T, 6>& i_face, const SunMethodConfig<T>& cfg,
                             SunMethodState<T>& state) noexcept {
    SunMethodResult<T> out;
    const FaceReadings<T> fr = face_readings(i_face, cfg);
    if (!fr.ok) return out;
    out.lit_faces = fr.lit;
    if (fr.lit == 0) {  // darkness: the cube may be turned arbitrarily before the light returns
        state = SunMethodState<T>{};
        return out;
    }
    if (cones_albedo_model(fr, cfg, state, out)) return out;
    return cones_candidates(fr, cfg, state);
}

template SunMethodResult<float> sun_cones(const std::array<float, 6>&, const SunMethodConfig<float>&,
                                          SunMethodState<float>&) noexcept;
template SunMethodResult<double> sun_cones(const std::array<double, 6>&, const SunMethodConfig<double>&,
                                           SunMethodState<double>&) noexcept;

}  // namespace attitude_estimator
