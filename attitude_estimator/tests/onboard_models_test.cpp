// The on-board computer's own reference models against independent ones: the sun against ERFA's
// planetary ephemeris (eraEpv00, the IAU SOFA implementation of VSOP87-based Earth positions, BCRS ≈ J2000
// to 0.02"), the clock's sidereal time and the field against the environment's truth (double, Eigen, its
// own tests check it against published IGRF values), the truncation error falling with the degree.
#include <erfa.h>
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <random>

#include "attitude_estimator/onboard_clock.hpp"
#include "attitude_estimator/onboard_computer.hpp"
#include "attitude_estimator/onboard_field.hpp"
#include "attitude_estimator/onboard_sun.hpp"
#include "attitude_estimator/reference_error.hpp"
#include "environment/earth_rotation.hpp"
#include "environment/geomagnetic_field.hpp"
#include "environment/time_scales.hpp"
#include "orbit/element_age.hpp"
#include "orbit/orbit_classes.hpp"
#include "orbit/sgp4.hpp"
#include "orbit/tle.hpp"
#include "ordered_draws.hpp"
#include "test_support.hpp"

namespace ae = attitude_estimator;
namespace env = environment;
using ae::test::ScalarName;
using ae::test::Scalars;
using ae::test::tol;

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;

double angle(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    return std::atan2(a.cross(b).norm(), a.dot(b));
}
template <class T>
Eigen::Vector3d eig(const ae::Vec3<T>& v) {
    return {double(v[0]), double(v[1]), double(v[2])};
}
}  // namespace

template <class T>
class OnboardModels : public ::testing::Test {};
TYPED_TEST_SUITE(OnboardModels, Scalars, ScalarName);

// The almanac's sun against ERFA's geometric Earth–Sun vector every 5 days over IGRF-14's 2025–2030: the
// formula claims about 0.01°, plus 20.5" of annual aberration it includes and ERFA's geometric vector does
// not. Distance to 1e-4 AU (the formula's R to 5 digits).
TYPED_TEST(OnboardModels, SunAgreesWithErfaOver2025To2030) {
    using T = TypeParam;
    double worst = 0.0, worst_distance = 0.0;
    for (int d = 0; d < 5 * 365; d += 5) {
        const ae::CalendarInstant epoch{.year = 2025, .month = 1, .day = 1, .hour = 6, .minute = 0, .second = 0.0};
        const ae::OnboardClock<T> clock = ae::make_onboard_clock<T>(epoch);
        const T t = static_cast<T>(d * 86400.0);
        const ae::SunReference<T> s = ae::onboard_sun(clock, t);
        // ERFA in TDB; the clock is UTC: TT − UTC = 69.184 s in 2025 (37 leap seconds + 32.184 s).
        const double jd = clock.epoch_julian_date + d + 69.184 / 86400.0;
        double pvh[2][3], pvb[2][3];
        ASSERT_EQ(eraEpv00(jd, 0.0, pvh, pvb), 0);
        const Eigen::Vector3d sun = -Eigen::Vector3d(pvh[0][0], pvh[0][1], pvh[0][2]);
        worst = std::max(worst, angle(eig(s.direction), sun));
        worst_distance = std::max(worst_distance, std::abs(double(s.distance) / ae::kAstronomicalUnit - sun.norm()));
        EXPECT_NEAR(eig(s.direction).norm(), 1.0, tol<T>(1e-6, 1e-12));
    }
    EXPECT_LT(worst, 0.015 * kDeg) << worst / kDeg << " deg";
    EXPECT_LT(worst_distance, 1e-4) << worst_distance << " AU";
    std::printf("on-board sun vs ERFA 2025-2030 (%s): worst %.4f deg, distance %.2e AU\n",
                std::is_same_v<T, float> ? "float" : "double", worst / kDeg, worst_distance);
}

// The clock's sidereal time and Earth-fixed rotation against the environment's at the same instants, two
// days after an epoch in mid-afternoon.
TYPED_TEST(OnboardModels, ClockRotationIsTheEnvironments) {
    using T = TypeParam;
    const ae::CalendarInstant epoch{.year = 2026, .month = 7, .day = 14, .hour = 15, .minute = 42, .second = 17.25};
    const ae::OnboardClock<T> clock = ae::make_onboard_clock<T>(epoch);
    const double jd0 = env::julian_date(env::UtcDate{2026, 7, 14, 15, 42, 17.25});
    EXPECT_NEAR(clock.epoch_julian_date, jd0, 1e-9);
    EXPECT_NEAR(double(clock.epoch_year), env::decimal_year(jd0), tol<T>(2e-4, 1e-9));
    for (double t : {0.0, 0.05, 5764.0, 11528.0, 172800.0}) {
        const double jd = jd0 + t / 86400.0;
        double d = double(ae::gmst_at(clock, T(t))) - env::gmst(jd);
        d = std::remainder(d, 2.0 * kPi);
        EXPECT_NEAR(d, 0.0, tol<T>(2e-6, 1e-8)) << t;  // the formula's t² term over days
        const Eigen::Matrix3d truth = env::ecef_from_eci(jd);
        const Eigen::Matrix3d onboard = ae::test::to_eigen(ae::ecef_from_j2000(clock, T(t)));
        EXPECT_LT((onboard - truth).cwiseAbs().maxCoeff(), tol<T>(3e-6, 1e-8)) << t;
    }
}

// Degree 13 is the whole IGRF-14: the truth's field at the same Earth-fixed points and dates, over the
// globe at 570 km and at the surface, poles included.
TYPED_TEST(OnboardModels, FieldAtDegree13IsTheEnvironmentsIgrf) {
    using T = TypeParam;
    const ae::FieldModel<T> model = ae::make_field_model<T>(13);
    std::mt19937 rng(26);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    double worst = 0.0;
    for (int k = 0; k < 300; ++k) {
        Eigen::Vector3d r = ordered_draws::vector3(u, rng);
        if (k == 0) r = Eigen::Vector3d(0, 0, 1);   // north pole
        if (k == 1) r = Eigen::Vector3d(0, 0, -1);  // south pole
        r = r.normalized() * (k % 2 ? 6371.2e3 : 6948.0e3);
        const double year = 2025.0 + 5.0 * (u(rng) + 1.0) / 2.0;
        const Eigen::Vector3d truth = env::spherical_harmonic_field(env::igrf_coefficients(year), 13, r);
        const Eigen::Vector3d onboard = eig(ae::field_ecef(model, ae::test::to_vec<T>(r), T(year)));
        worst = std::max(worst, (onboard - truth).norm() / truth.norm());
    }
    EXPECT_LT(worst, tol<T>(2e-5, 1e-10)) << worst;
}

// Degree 1 is the tilted centred dipole of the environment's `dipole` model.
TYPED_TEST(OnboardModels, FieldAtDegree1IsTheDipole) {
    using T = TypeParam;
    const ae::FieldModel<T> model = ae::make_field_model<T>(1);
    const Eigen::Vector3d r = Eigen::Vector3d(0.3, -0.5, 0.8).normalized() * 6948e3;
    const Eigen::Vector3d truth = env::dipole_field(env::igrf_coefficients(2026.5), r);
    const Eigen::Vector3d onboard = eig(ae::field_ecef(model, ae::test::to_vec<T>(r), T(2026.5)));
    EXPECT_LT((onboard - truth).norm() / truth.norm(), tol<T>(2e-6, 1e-12));
}

// The truncation error against the whole model, RMS over the sphere at 570 km (the on-board model's
// use), falls with every degree added, and reaches the figures docs/onboard_references.md quotes.
TEST(OnboardField, TruncationErrorFallsWithDegree) {
    std::mt19937 rng(8);
    std::normal_distribution<double> n(0.0, 1.0);
    std::vector<Eigen::Vector3d> points;
    for (int k = 0; k < 2000; ++k) points.push_back(ordered_draws::vector3(n, rng).normalized() * 6948e3);
    const ae::FieldModel<double> full = ae::make_field_model<double>(13);
    double previous = 1e300;
    for (int degree = 1; degree <= 12; ++degree) {
        const ae::FieldModel<double> m = ae::make_field_model<double>(degree);
        double sum_b = 0.0, sum_angle = 0.0;
        for (const auto& r : points) {
            const Eigen::Vector3d b = eig(ae::field_ecef(m, ae::test::to_vec<double>(r), 2026.2));
            const Eigen::Vector3d b13 = eig(ae::field_ecef(full, ae::test::to_vec<double>(r), 2026.2));
            sum_b += (b - b13).squaredNorm();
            sum_angle += std::pow(angle(b, b13), 2);
        }
        const double rms = std::sqrt(sum_b / points.size());
        std::printf("degree %2d: RMS vector error %7.1f nT, RMS direction error %.4f deg\n", degree, rms * 1e9,
                    std::sqrt(sum_angle / points.size()) / kDeg);
        EXPECT_LT(rms, previous) << degree;
        previous = rms;
    }
}

// The ground's number for the degrees a model leaves out (omitted_field_rms) against the synthesis it stands for:
// the rms per axis of the whole model minus the degree-8 one over 4000 points drawn uniformly on the sphere, at the
// robustness campaign's lowest and highest altitudes (420 and 650 km; Monte Carlo error about 2 %), and against
// the spectrum summed independently from ground/data/IGRF14.SHC's 2025.0 column (Python, the formula of the
// header: 40.4 and 27.8 nT per axis).
TEST(OnboardField, OmittedDegreesRmsIsTheSynthesisOverTheSphere) {
    std::mt19937 rng(13);
    std::normal_distribution<double> n(0.0, 1.0);
    const ae::FieldModel<double> full = ae::make_field_model<double>(13), eight = ae::make_field_model<double>(8);
    const struct { double altitude, spectrum; } cases[] = {{420e3, 40.4e-9}, {650e3, 27.8e-9}};
    for (const auto& c : cases) {
        const double radius = 6371.2e3 + c.altitude;
        Eigen::Vector3d sum = Eigen::Vector3d::Zero();
        const int count = 4000;
        for (int k = 0; k < count; ++k) {
            const Eigen::Vector3d r = ordered_draws::vector3(n, rng).normalized() * radius;
            const Eigen::Vector3d d = eig(ae::field_ecef(full, ae::test::to_vec<double>(r), 2025.0)) -
                                      eig(ae::field_ecef(eight, ae::test::to_vec<double>(r), 2025.0));
            sum += d.cwiseProduct(d);
        }
        const double synthesis = std::sqrt(sum.sum() / (3.0 * count));
        const double rms = ae::omitted_field_rms(8, radius, 2025.0);
        EXPECT_NEAR(rms, synthesis, 0.05 * synthesis) << c.altitude;
        EXPECT_NEAR(rms, c.spectrum, 0.05e-9) << c.altitude;
    }
    // Nothing is omitted from the whole model, and more is omitted from a lower degree.
    EXPECT_EQ(ae::omitted_field_rms(13, 6948e3, 2026.0), 0.0);
    EXPECT_GT(ae::omitted_field_rms(6, 6948e3, 2026.0), ae::omitted_field_rms(8, 6948e3, 2026.0));
}

// The on-board element sets of the leo_orbit study (attitude_estimator/study/older_tle.py from the truth's
// set, 24 h and 72 h older) propagated by SGP4 to the two orbits after the truth's epoch: the position
// error the age makes (TEME, both). Printed for docs/onboard_references.md; bounded by the along-track
// drift of a mean-motion error of the order of the set's ndot term over the age.
TEST(OnboardOrbit, OlderElementSetsMissTheTruthByTheirAge) {
    const auto sgp4 = [](const char* l1, const char* l2) {
        orbit::Sgp4<double> s;
        EXPECT_EQ(s.initialize(orbit::parse_tle(l1, l2).mean_elements<double>()), orbit::Sgp4Status::ok);
        return s;
    };
    const auto truth = sgp4("1 90001U          26079.00000000  .00002000  00000-0  15000-3 0  9995",
                            "2 90001  64.9000   0.0000 0012000  90.0000 270.0000 14.98524078  1001");
    struct Older {
        double hours;
        orbit::Sgp4<double> set;
    };
    const Older older[] = {{24.0, sgp4("1 90001U          26078.00000000  .00002000  00000-0  15000-3 0  9994",
                                       "2 90001  64.9000   3.1277 0012000  90.3760 275.3137 14.98524078  1006")},
                           {72.0, sgp4("1 90001U          26076.00000000  .00002000  00000-0  15000-3 0  9992",
                                       "2 90001  64.9000   9.3831 0012000  91.1280 285.9410 14.98524078  1007")}};
    double previous = 0.0;
    for (const Older& o : older) {
        double worst = 0.0, sum = 0.0;
        int n = 0;
        for (double t = 0.0; t <= 11528.0; t += 60.0) {
            orbit::OrbitState<double> a, b;
            ASSERT_EQ(truth.propagate(t / 60.0, a), orbit::Sgp4Status::ok);
            ASSERT_EQ(o.set.propagate(o.hours * 60.0 + t / 60.0, b), orbit::Sgp4Status::ok);
            const double e = (a.position_km - b.position_km).norm();
            worst = std::max(worst, e);
            sum += e;
            ++n;
        }
        std::printf("on-board set %2.0f h older: position error over two orbits mean %.2f km, worst %.2f km\n", o.hours,
                    sum / n, worst);
        EXPECT_GT(worst, previous);
        EXPECT_LT(worst, 50.0);
        previous = worst;
    }
}

// The truth's set (circular, 51.6°, B* 1.5e-4, at leo_orbit's epoch 2026-03-20 0 h UTC) at an altitude and the
// computer's made 24 h older (orbit::older_set, as the block derives it), both ready for SGP4, with the ground's
// figure for the older one (reference_error.hpp, the degree-8 model, the clock at the epoch) and its period.
struct AgedSets {
    ae::CalendarInstant clock{};
    ae::OnboardClock<double> c = ae::make_onboard_clock<double>(clock);
    ae::FieldModel<double> model = ae::make_field_model<double>(8);
    orbit::Tle truth, onboard;
    ae::ReferenceFieldError e;
    orbit::Sgp4<double> a, b;  // the truth's, the computer's
    double period = 0.0;       // s
    bool ok = false;
    explicit AgedSets(double altitude)
        : truth(orbit::circular_orbit_set(2461119.5, altitude, 51.6, 10.0, 30.0, 1.5e-4)),
          onboard(orbit::older_set(truth, 86400.0)),
          e(ae::reference_field_error(model, clock, onboard.mean_elements<double>(), onboard.epoch_jd_utc)) {
        ok = a.initialize(truth.mean_elements<double>()) == orbit::Sgp4Status::ok &&
             b.initialize(onboard.mean_elements<double>()) == orbit::Sgp4Status::ok;
        period = 2.0 * kPi * std::sqrt(std::pow(b.semi_major_axis_km(), 3) / 398600.4418);
    }
};

// The ground's figure for the reference's error along the computer's orbit (reference_error.hpp) against what the
// aged set does: the truth's set (circular, B* 1.5e-4, at the bundled epoch) and the computer's made 24 h older
// (orbit::older_set, as the block derives it), both by SGP4 over the first period; their distance against the
// set's own drag displacement, and the degree-8 model's field at the two positions against the position part.
// Each comes from another computation (two sets, two positions, the model evaluated there), not from the
// function's difference along one orbit.
TEST(OnboardOrbit, TheReferenceErrorIsWhatTheAgedSetMakesOfTheField) {
    for (const double altitude : {420.0, 570.0}) {
        AgedSets sets(altitude);
        ASSERT_TRUE(sets.ok) << altitude;
        const ae::CalendarInstant& clock = sets.clock;
        const ae::OnboardClock<double>& c = sets.c;
        const ae::FieldModel<double>& model = sets.model;
        const orbit::Tle& onboard = sets.onboard;
        const ae::ReferenceFieldError& e = sets.e;
        orbit::Sgp4<double>&a = sets.a, &b = sets.b;
        const double period = sets.period;
        double distance = 0.0, field = 0.0;
        const int n = 200;
        for (int k = 0; k < n; ++k) {
            const double t = period * k / n;
            orbit::OrbitState<double> x, y;
            ASSERT_EQ(a.propagate(t / 60.0, x), orbit::Sgp4Status::ok);
            ASSERT_EQ(b.propagate(1440.0 + t / 60.0, y), orbit::Sgp4Status::ok);
            distance += 1e6 * (x.position_km - y.position_km).squaredNorm();
            // TEME to Earth-fixed by GMST, the same turn for both: the difference is the positions'.
            const double g = ae::gmst_at(c, t);
            const Eigen::Matrix3d r3 = Eigen::AngleAxisd(-g, Eigen::Vector3d::UnitZ()).toRotationMatrix();
            const Eigen::Vector3d bx =
                eig(ae::field_ecef(model, ae::test::to_vec<double>(1e3 * r3 * x.position_km), 2026.2));
            const Eigen::Vector3d by =
                eig(ae::field_ecef(model, ae::test::to_vec<double>(1e3 * r3 * y.position_km), 2026.2));
            field += (bx - by).squaredNorm();
        }
        distance = std::sqrt(distance / n);
        field = std::sqrt(field / (3.0 * n));
        std::printf(
            "%.0f km: aged set off by %.0f m (drag displacement %.0f m); field %.1f nT per axis (estimate "
            "%.1f nT); truncation %.1f nT; in all %.1f nT\n",
            altitude, distance, e.drag_displacement, field * 1e9, e.position * 1e9, e.truncation * 1e9, e.rms * 1e9);
        EXPECT_NEAR(e.drag_displacement, distance, 0.05 * distance) << altitude;
        EXPECT_NEAR(e.position, field, 0.1 * field) << altitude;
        EXPECT_NEAR(e.truncation, ae::omitted_field_rms(8, 1e3 * b.semi_major_axis_km(), 2026.2), 1e-11);
        EXPECT_NEAR(e.rms, std::hypot(e.truncation, e.position), 1e-15);
        // The firmware's float model: the same figure (its field evaluations round at pT, the error is nT).
        const ae::ReferenceFieldError f = ae::reference_field_error(
            ae::make_field_model<float>(8), clock, onboard.mean_elements<double>(), onboard.epoch_jd_utc);
        EXPECT_NEAR(f.rms, e.rms, 0.01 * e.rms);
        EXPECT_NEAR(f.turn, e.turn, 0.02 * e.turn);
    }
}

// The position part read as one turn over the period (ReferenceFieldError::turn, MekfConfig::mag_ref_tilt)
// against the rotation fitted apart: over 300 points of the period, in TEME axes, by an SVD of the stacked system
// B_k × θ = e_k (not its normal equations), with the truth's set against the computer's 24 h-older one (not the
// set with and without its B*). It is also what geometry says: the along-track lag δs turns the field pattern
// about the orbit's normal, and a near-dipole field turns about twice per orbit as fast as the position does, so
// θ ≈ 2 δs / r along the normal. The truncation's own turn (the truth's field, environment/, IGRF-14 to degree 13,
// against the degree-8 model) is printed for the first two orbits: it is as large, but another turn each orbit
// as the Earth turns under the track, which a filter's memory averages (docs/filter.md, "The reference's tilt").
TEST(OnboardOrbit, TheReferenceErrorReadAsOneTurnIsTheLagsTurnAboutTheOrbitsNormal) {
    for (const double altitude : {420.0, 570.0}) {
        AgedSets sets(altitude);
        ASSERT_TRUE(sets.ok) << altitude;
        const ae::OnboardClock<double>& c = sets.c;
        const ae::FieldModel<double>& model = sets.model;
        const ae::ReferenceFieldError& e = sets.e;
        orbit::Sgp4<double>&a = sets.a, &b = sets.b;
        const double period = sets.period;
        const int n = 300;
        Eigen::Vector3d truncation_turn[2], position_turn = Eigen::Vector3d::Zero(), normal = Eigen::Vector3d::Zero();
        double lag = 0.0, radius = 0.0;
        for (int orbit_index = 0; orbit_index < 2; ++orbit_index) {
            Eigen::MatrixXd turns(3 * n, 3);
            Eigen::VectorXd truncation(3 * n), position(3 * n);
            for (int k = 0; k < n; ++k) {
                const double t = period * (orbit_index + static_cast<double>(k) / n);
                orbit::OrbitState<double> x, y;
                ASSERT_EQ(a.propagate(t / 60.0, x), orbit::Sgp4Status::ok);
                ASSERT_EQ(b.propagate(1440.0 + t / 60.0, y), orbit::Sgp4Status::ok);
                const Eigen::Matrix3d to_ecef =
                    Eigen::AngleAxisd(-ae::gmst_at(c, t), Eigen::Vector3d::UnitZ()).toRotationMatrix();
                const auto field = [&](const Eigen::Vector3d& r_km) {
                    return Eigen::Vector3d(
                        to_ecef.transpose() *
                        eig(ae::field_ecef(model, ae::test::to_vec<double>(1e3 * to_ecef * r_km), 2026.2)));
                };
                const Eigen::Vector3d on_board = field(y.position_km);
                const Eigen::Vector3d full =
                    to_ecef.transpose() *
                    env::spherical_harmonic_field(env::igrf_coefficients(2026.2), 13, 1e3 * to_ecef * y.position_km);
                Eigen::Matrix3d cross;
                cross << 0.0, -on_board(2), on_board(1), on_board(2), 0.0, -on_board(0), -on_board(1), on_board(0), 0.0;
                turns.block<3, 3>(3 * k, 0) = cross;
                truncation.segment<3>(3 * k) = full - on_board;
                position.segment<3>(3 * k) = field(x.position_km) - on_board;
                if (orbit_index == 0) {
                    normal += y.position_km.cross(y.velocity_km_s).normalized();
                    lag += (x.position_km - y.position_km).norm() * 1e3 / n;
                    radius += y.position_km.norm() * 1e3 / n;
                }
            }
            const Eigen::JacobiSVD<Eigen::MatrixXd> svd(turns, Eigen::ComputeThinU | Eigen::ComputeThinV);
            truncation_turn[orbit_index] = svd.solve(truncation);
            if (orbit_index == 0) position_turn = svd.solve(position);
        }
        normal.normalize();
        const double along_normal = std::abs(position_turn.normalized().dot(normal));
        const double between =
            std::acos(std::clamp(truncation_turn[0].normalized().dot(truncation_turn[1].normalized()), -1.0, 1.0));
        std::printf(
            "%.0f km: the lag's turn %.4f deg (fitted apart %.4f, %.2f of it along the orbit's normal; 2 lag / r "
            "%.4f deg); the truncation's turn %.4f deg, next orbit %.4f deg, %.0f deg apart\n",
            altitude, e.turn / kDeg, position_turn.norm() / kDeg, along_normal, 2.0 * lag / radius / kDeg,
            truncation_turn[0].norm() / kDeg, truncation_turn[1].norm() / kDeg, between / kDeg);
        EXPECT_NEAR(e.turn, position_turn.norm(), 0.1 * e.turn) << altitude;
        EXPECT_GT(along_normal, 0.9) << altitude;
        EXPECT_NEAR(position_turn.norm(), 2.0 * lag / radius, 0.25 * 2.0 * lag / radius) << altitude;
    }
}
