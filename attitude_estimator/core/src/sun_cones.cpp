// Sun vector from intersecting cones of orthogonal lit faces (seed 002 eq. 13–20), with mirror and albedo
// rejection and the 27-state panel cube (docs/sun_methods.md).
#include <cmath>
#include <cstdint>

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
  std::uint8_t faces = 0;       // the faces whose cones made it
  bool feasible = false;        // no face reads below the candidate's prediction (light cannot be removed)
  std::uint8_t agree = 0;       // lit faces whose reading matches the prediction
  std::uint8_t excess = 0;      // lit faces reading above the prediction: albedo
  int n_agree = 0;
  T sq = T(0);                  // Σ (R(v·n) − r)² over the agreeing faces
  T excess_sum = T(0);          // Σ (r − R(v·n)) over the excess faces
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

template SunMethodResult<float> sun_cones(const std::array<float, 6>&, const SunMethodConfig<float>&,
                                          SunMethodState<float>&) noexcept;
template SunMethodResult<double> sun_cones(const std::array<double, 6>&, const SunMethodConfig<double>&,
                                           SunMethodState<double>&) noexcept;

}  // namespace attitude_estimator
