// Replays the attitude filter (mekf.hpp) over the single-frame measurements a `cosim run` recorded, so that
// its tuning can be studied without re-running the plant: for each row (one row per estimator sample,
// `--output-interval` = `sample_period`) it feeds est.sun_meas/est.sun_valid, est.mag_field/est.mag_valid,
// env.sun_eci, env.mag_eci and the single-frame est.q_est/est.valid to mekf_sample, and compares with
// env.q_true and env.omega_body. docs/filter.md lists the runs and the columns they record.
//
//   attitude_estimator_mekf_replay run.csv [--from T] [--trace out.csv] [key=value ...]
//   keys: sun_sigma, sun_correlation (s), mag_sigma (T), mag_ref_sigma (T), mag_sigma_calibrated (T: from the rows where
//   est.mag_cal_valid, when recorded), mag_sigma_eclipse (T: the same in rows without a sun vector), rate_noise, attitude_noise, offset (0/1), polarity (plus | column:
//   est.mag_set_reset of the row before), euler (0/1: the environment's default inertia), inertia_diag (Jxx,Jyy,Jzz), reset_after,
//   scale (0/1: face update from plant.i_face_sh with the Kelly law), face_sigma, i_face_norm (A, at 1 AU),
//   face_min (smallest relative response of a face used for the scale)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "attitude_estimator/mekf.hpp"
#include "recorded_columns.hpp"

namespace ae = attitude_estimator;

namespace {

constexpr double kAu = 1.495978707e11;  // m
constexpr double kPi = 3.14159265358979323846;

double angle_deg(const double* a, const double* b) {
    double dot = 0, na = 0, nb = 0;
    for (int i = 0; i < 4; ++i) {
        dot += a[i] * b[i];
        na += a[i] * a[i];
        nb += b[i] * b[i];
    }
    return 2.0 * std::acos(std::min(1.0, std::abs(dot) / std::sqrt(na * nb))) * 180.0 / kPi;
}

double pct(std::vector<double> v, double p) {
    if (v.empty()) return NAN;
    std::sort(v.begin(), v.end());
    return v[std::min(v.size() - 1, static_cast<std::size_t>(std::lround(p * static_cast<double>(v.size() - 1))))];
}

struct Options {
    ae::MekfConfig<double> filter;
    bool column_polarity = false;
    double i_face_norm = 0.84754;
    double face_min = 0.45;
    double from = 0;
    std::string trace;
};

Options parse(int argc, char** argv, std::string& file) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--from" && i + 1 < argc) {
            o.from = std::stod(argv[++i]);
            continue;
        }
        if (a == "--trace" && i + 1 < argc) {
            o.trace = argv[++i];
            continue;
        }
        const auto eq = a.find('=');
        if (eq == std::string::npos) {
            file = a;
            continue;
        }
        const std::string k = a.substr(0, eq), v = a.substr(eq + 1);
        auto& f = o.filter;
        if (k == "sun_sigma")
            f.sun_sigma = std::stod(v);
        else if (k == "mag_sigma")
            f.mag_sigma = std::stod(v);
        else if (k == "sun_correlation")
            f.sun_correlation_time = std::stod(v);
        else if (k == "mag_ref_sigma")
            f.mag_ref_sigma = std::stod(v);
        else if (k == "mag_sigma_calibrated")
            f.mag_sigma_calibrated = std::stod(v);
        else if (k == "mag_sigma_eclipse")
            f.mag_sigma_calibrated_eclipse = std::stod(v);
        else if (k == "rate_noise")
            f.rate_noise = std::stod(v);
        else if (k == "attitude_noise")
            f.attitude_noise = std::stod(v);
        else if (k == "offset")
            f.estimate_offset = v == "1";
        else if (k == "scale")
            f.estimate_scale = v == "1";
        else if (k == "face_sigma")
            f.face_sigma = std::stod(v);
        else if (k == "reset_after")
            f.reset_after = std::stoi(v);
        else if (k == "polarity")
            o.column_polarity = v == "column";
        else if (k == "i_face_norm")
            o.i_face_norm = std::stod(v);
        else if (k == "face_min")
            o.face_min = std::stod(v);
        else if (k == "euler") {
            if (v == "1") f.inertia = {3.2, 0.05, -0.02, 0.05, 2.9, 0.03, -0.02, 0.03, 3.6};
        } else if (k == "inertia_diag") {  // Jxx,Jyy,Jzz
            const auto c1 = v.find(','), c2 = v.find(',', c1 + 1);
            f.inertia = {std::stod(v.substr(0, c1)), 0, 0, 0, std::stod(v.substr(c1 + 1, c2 - c1 - 1)), 0, 0, 0,
                         std::stod(v.substr(c2 + 1))};
        } else
            throw std::runtime_error("unknown option " + a);
    }
    return o;
}

// The attitude error δθ of the estimate q against the truth qt (A_true = (I − [δθ×]) Â, body axes) and its
// normalized square δθᵀ P_θθ⁻¹ δθ / 3 (the normalized estimation error squared per degree of freedom).
double nees_per_dof(const double* qt, const ae::MekfState<double>& s) {
    const ae::Quaternion<double> t{qt[0], qt[1], qt[2], qt[3]};
    // δq = q_true ⊗ q̂⁻¹ (Shuster's order: A(δq) = A_true Âᵀ); δθ = 2 vec(δq) sign-fixed by its scalar part.
    const double x1 = t.x, y1 = t.y, z1 = t.z, w1 = t.w;
    const double x2 = -s.q.x, y2 = -s.q.y, z2 = -s.q.z, w2 = s.q.w;
    // Shuster's product p ⊗ q = [p4 q + q4 p − p × q; p4 q4 − p·q] with p = q_true, q = q̂⁻¹.
    double d[3] = {w1 * x2 + w2 * x1 - (y1 * z2 - z1 * y2), w1 * y2 + w2 * y1 - (z1 * x2 - x1 * z2),
                   w1 * z2 + w2 * z1 - (x1 * y2 - y1 * x2)};
    const double dw = w1 * w2 - (x1 * x2 + y1 * y2 + z1 * z2);
    const double sign = dw < 0 ? -2.0 : 2.0;
    for (double& v : d) v *= sign;
    // Solve P_θθ x = δθ by Cholesky.
    double l[3][3] = {};
    for (int j = 0; j < 3; ++j) {
        double a = s.p[ae::kMekfStates * j + j];
        for (int k = 0; k < j; ++k) a -= l[j][k] * l[j][k];
        if (!(a > 0)) return NAN;
        l[j][j] = std::sqrt(a);
        for (int i = j + 1; i < 3; ++i) {
            double b = s.p[ae::kMekfStates * i + j];
            for (int k = 0; k < j; ++k) b -= l[i][k] * l[j][k];
            l[i][j] = b / l[j][j];
        }
    }
    double z[3];
    for (int i = 0; i < 3; ++i) {
        double b = d[i];
        for (int k = 0; k < i; ++k) b -= l[i][k] * z[k];
        z[i] = b / l[i][i];
    }
    return (z[0] * z[0] + z[1] * z[1] + z[2] * z[2]) / 3.0;
}

}  // namespace

int main(int argc, char** argv) try {
    std::string file;
    const Options o = parse(argc, argv, file);
    const ae::study::RecordedColumns col(file);
    auto has = [&](const std::string& name) { return col.has(name); };
    const auto& time = col("time");
    const bool have_irradiance = has("env.irradiance");
    const auto kelly = panel_response::kelly<double>();
    ae::MekfState<double> s;
    std::vector<double> single_lit, filt_lit, filt_dark, rate_err, nees_lit, nees_dark;
    std::size_t rows = 0, covered = 0, filter_valid = 0;
    std::FILE* trace = o.trace.empty() ? nullptr : std::fopen(o.trace.c_str(), "w");
    if (trace) std::fprintf(trace, "time,error_deg,bound_deg,single_deg,lit\n");
    // Columns resolved once (find is a linear search over the names).
    const auto& valid = col("est.valid");
    const auto& sun_valid = col("est.sun_valid");
    const auto& mag_valid = col("est.mag_valid");
    const std::vector<double>* q_est[4];
    const std::vector<double>* q_true[4];
    const std::vector<double>* sun_ref[3];
    const std::vector<double>* sun_meas[3];
    const std::vector<double>* mag_ref[3];
    const std::vector<double>* mag_field[3];
    const std::vector<double>* omega[3];
    const std::vector<double>* faces[6] = {};
    for (int k = 0; k < 4; ++k) {
        const std::string i = "[" + std::to_string(k + 1) + "]";
        q_est[k] = &col("est.q_est" + i);
        q_true[k] = &col("env.q_true" + i);
        if (k == 3) break;
        sun_ref[k] = &col("env.sun_eci" + i);
        sun_meas[k] = &col("est.sun_meas" + i);
        mag_ref[k] = &col("env.mag_eci" + i);
        mag_field[k] = &col("est.mag_field" + i);
        omega[k] = &col("env.omega_body" + i);
    }
    // est.mag_set_reset of a row is the pulse commanded after that sample: the polarity of the next reading.
    const std::vector<double>* polarity = o.column_polarity ? &col("est.mag_set_reset") : nullptr;
    const std::vector<double>* irradiance = have_irradiance ? &col("env.irradiance") : nullptr;
    const std::vector<double>* calibrated = has("est.mag_cal_valid") ? &col("est.mag_cal_valid") : nullptr;
    const std::vector<double>* distance = nullptr;
    const std::vector<double>* lit_faces = nullptr;
    const std::vector<double>* rejected_faces = nullptr;
    if (o.filter.estimate_scale) {
        distance = &col("env.sun_distance");
        lit_faces = &col("est.lit_faces");
        rejected_faces = &col("est.rejected_faces");
        for (int k = 0; k < 6; ++k) faces[k] = &col("plant.i_face_sh[" + std::to_string(k + 1) + "]");
    }
    for (std::size_t r = 0; r < time.size(); ++r) {
        ae::MekfSampleInputs<double> in;
        in.t = time[r];
        in.attitude_valid = valid[r] > 0.5;
        in.q_single = {(*q_est[0])[r], (*q_est[1])[r], (*q_est[2])[r], (*q_est[3])[r]};
        in.sun_valid = sun_valid[r] > 0.5;
        in.mag_valid = mag_valid[r] > 0.5;
        for (int k = 0; k < 3; ++k) {
            in.sun_ref[k] = (*sun_ref[k])[r];
            in.sun_body[k] = (*sun_meas[k])[r];
            in.mag_ref[k] = (*mag_ref[k])[r];
            in.mag_body[k] = (*mag_field[k])[r];
        }
        in.mag_calibrated = calibrated && (*calibrated)[r] > 0.5;
        in.polarity = (polarity && r > 0) ? ((*polarity)[r - 1] > 0.5 ? 1.0 : -1.0) : 1.0;
        if (o.filter.estimate_scale) {
            const double au = kAu / (*distance)[r];
            const int lit = static_cast<int>((*lit_faces)[r]), rejected = static_cast<int>((*rejected_faces)[r]);
            for (int k = 0; k < 6; ++k) {
                in.face_r[k] = (*faces[k])[r] / (o.i_face_norm * au * au);
                if ((lit >> k & 1) && !(rejected >> k & 1) && in.face_r[k] >= o.face_min) in.face_use |= 1u << k;
            }
            in.response = &kelly;
        }
        const auto res = ae::mekf_sample(s, in, o.filter);
        if (time[r] < o.from) continue;
        ++rows;
        const bool lit = !irradiance || (*irradiance)[r] > 0.0;
        const double qt[4] = {(*q_true[0])[r], (*q_true[1])[r], (*q_true[2])[r], (*q_true[3])[r]};
        const double qe[4] = {in.q_single.x, in.q_single.y, in.q_single.z, in.q_single.w};
        const double qf[4] = {s.q.x, s.q.y, s.q.z, s.q.w};
        const double single = in.attitude_valid ? angle_deg(qt, qe) : NAN;
        if (lit && in.attitude_valid) single_lit.push_back(single);
        const double err = angle_deg(qt, qf);
        const double bound = res.bound * 180.0 / kPi;
        if (res.valid) {
            ++filter_valid;
            (lit ? filt_lit : filt_dark).push_back(err);
            (lit ? nees_lit : nees_dark).push_back(nees_per_dof(qt, s));
        }
        covered += s.stage == 2 && err <= bound;
        double w2 = 0;
        for (int k = 0; k < 3; ++k) {
            const double d = s.omega[k] - (*omega[k])[r];
            w2 += d * d;
        }
        rate_err.push_back(std::sqrt(w2) * 180.0 / kPi);
        if (trace) std::fprintf(trace, "%.3f,%.5f,%.5f,%.5f,%d\n", time[r], err, bound, single, lit ? 1 : 0);
    }
    if (trace) std::fclose(trace);
    std::printf("rows %zu from t = %g s, filter valid %zu, resets %d\n", rows, o.from, filter_valid, s.resets);
    std::printf("sunlit single-frame median %.3f p95 %.3f deg (n %zu)\n", pct(single_lit, 0.5), pct(single_lit, 0.95),
                single_lit.size());
    std::printf("sunlit filter median %.3f p95 %.3f deg (n %zu)\n", pct(filt_lit, 0.5), pct(filt_lit, 0.95),
                filt_lit.size());
    std::printf("eclipse filter median %.3f p95 %.3f deg (n %zu)\n", pct(filt_dark, 0.5), pct(filt_dark, 0.95),
                filt_dark.size());
    std::printf("3-sigma bound covers the error in %.2f %% of rows\n",
                100.0 * static_cast<double>(covered) / static_cast<double>(std::max<std::size_t>(rows, 1)));
    auto mean = [](const std::vector<double>& v) {
        double m = 0;
        for (double x : v) m += x;
        return v.empty() ? NAN : m / static_cast<double>(v.size());
    };
    std::printf("normalized error per dof (NEES/3): sunlit %.3f, eclipse %.3f\n", mean(nees_lit), mean(nees_dark));
    std::printf("rate error median %.4f p95 %.4f deg/s\n", pct(rate_err, 0.5), pct(rate_err, 0.95));
    std::printf("offset %.3e %.3e %.3e T, panel scale %.4f\n", s.mag_offset[0], s.mag_offset[1], s.mag_offset[2],
                s.panel_scale);
    return 0;
} catch (const std::exception& e) {
    std::fprintf(stderr, "mekf_replay: %s\n", e.what());
    return 1;
}
