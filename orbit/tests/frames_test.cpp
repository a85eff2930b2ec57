// TEME -> J2000 against ERFA (Debian's liberfa), the independent route: eraPmat76 (IAU 1976 precession),
// eraNut80 and eraObl80 (IAU 1980 nutation and mean obliquity), composed with ERFA's own rotations; and
// the truncated nutation's error against ERFA's full series, which is what the frames.hpp figures state.
#include <erfa.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "orbit/frames.hpp"

namespace {

constexpr double kArcsec = 3.14159265358979323846 / (180.0 * 3600.0);

Eigen::Matrix3d from_erfa(const double m[3][3]) {
    Eigen::Matrix3d out;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) out(i, j) = m[i][j];
    return out;
}

// The angle (rad) of the rotation a^T b: how far apart two rotation matrices are.
double angle_between(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
    const double c = std::clamp(((a.transpose() * b).trace() - 1.0) / 2.0, -1.0, 1.0);
    // acos loses precision near 0; the Frobenius norm of the difference is sqrt(8) sin(angle/2) there.
    return c > 0.999 ? 2.0 * std::asin(std::min(1.0, (a - b).norm() / std::sqrt(8.0))) : std::acos(c);
}

// ERFA's TEME -> J2000: r_J2000 = P^T N^T R3(-Eq) r_TEME with Eq = dpsi cos(eps0), all from ERFA.
Eigen::Matrix3d erfa_j2000_from_teme(double jd) {
    double p[3][3], n[3][3], eq[3][3];
    eraPmat76(jd, 0.0, p);
    eraNutm80(jd, 0.0, n);
    double dpsi = 0.0, deps = 0.0;
    eraNut80(jd, 0.0, &dpsi, &deps);
    const double eps0 = eraObl80(jd, 0.0);
    // eraRz(psi, r) applies the passive rotation R3(psi) to r (r := R3(psi) r).
    double ident[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    eraRz(-dpsi * std::cos(eps0), ident);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) eq[i][j] = ident[i][j];
    return from_erfa(p).transpose() * from_erfa(n).transpose() * from_erfa(eq);
}

// Julian dates spanning 2000-2040 every 13.7 days (not a multiple of any nutation period).
template <typename F>
void for_dates(double from_year, double to_year, F&& f) {
    for (double jd = orbit::kJulianDateJ2000 + (from_year - 2000.0) * 365.25;
         jd < orbit::kJulianDateJ2000 + (to_year - 2000.0) * 365.25; jd += 13.7) {
        f(jd);
    }
}

TEST(Frames, PrecessionMatchesErfa) {
    double worst = 0.0;
    for_dates(2000.0, 2040.0, [&](double jd) {
        double p[3][3];
        eraPmat76(jd, 0.0, p);
        worst = std::max(worst, angle_between(orbit::mod_from_j2000(orbit::julian_centuries(jd)), from_erfa(p)));
    });
    std::printf("precession: max rotation between ours and eraPmat76, 2000-2040: %.3g rad\n", worst);
    EXPECT_LT(worst, 1e-13);
}

TEST(Frames, NutationAndObliquityMatchErfa) {
    double worst_psi = 0.0, worst_eps = 0.0, worst_obl = 0.0;
    for_dates(2000.0, 2040.0, [&](double jd) {
        double dpsi = 0.0, deps = 0.0;
        eraNut80(jd, 0.0, &dpsi, &deps);
        const orbit::Nutation<double> n = orbit::nutation_iau1980(orbit::julian_centuries(jd));
        worst_psi = std::max(worst_psi, std::abs(n.dpsi - dpsi));
        worst_eps = std::max(worst_eps, std::abs(n.deps - deps));
        worst_obl = std::max(worst_obl, std::abs(n.mean_obliquity - eraObl80(jd, 0.0)));
    });
    std::printf("nutation vs eraNut80: dpsi %.3g rad, deps %.3g rad; obliquity vs eraObl80 %.3g rad\n", worst_psi,
                worst_eps, worst_obl);
    // A wrong coefficient of the smallest terms (0.0001") would show as 5e-10 rad.
    EXPECT_LT(worst_psi, 1e-13);
    EXPECT_LT(worst_eps, 1e-13);
    EXPECT_LT(worst_obl, 1e-14);
}

TEST(Frames, TemeToJ2000MatchesErfaRoute) {
    double worst = 0.0;
    double worst_kinematic = 0.0;
    for_dates(2000.0, 2040.0, [&](double jd) {
        const double t = orbit::julian_centuries(jd);
        worst = std::max(worst, angle_between(orbit::j2000_from_teme(t), erfa_j2000_from_teme(jd)));
        // eraEqeq94 adds the 1994 kinematic terms, which TEME leaves out: their size, for the README.
        double dpsi = 0.0, deps = 0.0;
        eraNut80(jd, 0.0, &dpsi, &deps);
        worst_kinematic = std::max(worst_kinematic, std::abs(eraEqeq94(jd, 0.0) - dpsi * std::cos(eraObl80(jd, 0.0))));
    });
    std::printf("TEME->J2000 vs ERFA's route: %.3g rad (%.3g m at 7000 km); eqeq94's kinematic terms: %.3g\"\n", worst,
                worst * 7.0e6, worst_kinematic / kArcsec);
    EXPECT_LT(worst, 1e-13);
    // The state rotates with the matrix: a position and a velocity keep their lengths and turn alike.
    const orbit::OrbitState<double> teme{{7000.0, -1200.0, 300.0}, {1.0, 7.0, 0.5}};
    const double t = orbit::julian_centuries(2461120.5);  // 2026-03-20
    const orbit::OrbitState<double> j2000 = orbit::teme_to_j2000(teme, t);
    const Eigen::Matrix3d m = erfa_j2000_from_teme(2461120.5);
    EXPECT_LT((j2000.position_km - m * teme.position_km).norm(), 1e-9);  // km: a micrometre
    EXPECT_LT((j2000.velocity_km_s - m * teme.velocity_km_s).norm(), 1e-12);
}

TEST(Frames, TruncatedNutationErrorOver2020To2035) {
    // The error of the first n terms against ERFA's full series; the bound is the sum of the amplitudes
    // left out (at T = 0.35, the rate terms add < 1e-5"), which the truncated series cannot exceed.
    for (int terms : {1, 2, 4, 9, 13, 30}) {
        double bound_psi = 0.0, bound_eps = 0.0;
        for (int i = terms; i < orbit::kIau1980NutationTerms; ++i) {
            bound_psi += std::abs(orbit::kIau1980Nutation[static_cast<std::size_t>(i)].a) * 1e-4 * kArcsec;
            bound_eps += std::abs(orbit::kIau1980Nutation[static_cast<std::size_t>(i)].c) * 1e-4 * kArcsec;
        }
        double worst_psi = 0.0, worst_eps = 0.0, worst_rotation = 0.0;
        for_dates(2020.0, 2035.0, [&](double jd) {
            double dpsi = 0.0, deps = 0.0;
            eraNut80(jd, 0.0, &dpsi, &deps);
            const double t = orbit::julian_centuries(jd);
            const orbit::Nutation<double> n = orbit::nutation_iau1980(t, terms);
            worst_psi = std::max(worst_psi, std::abs(n.dpsi - dpsi));
            worst_eps = std::max(worst_eps, std::abs(n.deps - deps));
            worst_rotation =
                std::max(worst_rotation, angle_between(orbit::j2000_from_teme(t, terms), erfa_j2000_from_teme(jd)));
        });
        std::printf(
            "%3d terms: dpsi %.3f\" (bound %.3f\"), deps %.3f\" (bound %.3f\"), TEME->J2000 %.3f\" = %.2f m at "
            "7000 km\n",
            terms, worst_psi / kArcsec, bound_psi / kArcsec, worst_eps / kArcsec, bound_eps / kArcsec,
            worst_rotation / kArcsec, worst_rotation * 7.0e6);
        EXPECT_LE(worst_psi, bound_psi + 1e-5 * kArcsec);
        EXPECT_LE(worst_eps, bound_eps + 1e-5 * kArcsec);
    }
    // The figure frames.hpp and the README state for the on-board default of 4 terms: the rotation within
    // 0.2" (7 m at 7000 km) of the full series.
    double worst4 = 0.0;
    for_dates(2020.0, 2035.0, [&](double jd) {
        worst4 = std::max(
            worst4, angle_between(orbit::j2000_from_teme(orbit::julian_centuries(jd), 4), erfa_j2000_from_teme(jd)));
    });
    EXPECT_LT(worst4, 0.2 * kArcsec);
}

TEST(Frames, FloatRotationAgainstErfa) {
    double worst = 0.0;
    for_dates(2020.0, 2035.0, [&](double jd) {
        const Eigen::Matrix3d f =
            orbit::j2000_from_teme(static_cast<float>(orbit::julian_centuries(jd))).cast<double>();
        worst = std::max(worst, angle_between(f, erfa_j2000_from_teme(jd)));
    });
    std::printf("float TEME->J2000 vs ERFA (double), 2020-2035: %.3g rad (%.3g m at 7000 km)\n", worst, worst * 7.0e6);
    EXPECT_LT(worst, 5e-7);  // float rounding (6e-8 per element), with margin: 3.5 m at 7000 km
}

}  // namespace
