// The on-board computer's own reference models against independent ones: the sun against ERFA's
// planetary ephemeris (eraEpv00, the IAU SOFA implementation of VSOP87-based Earth positions, BCRS ≈ J2000
// to 0.02"), the clock's sidereal time and the field against the environment's truth (double, Eigen, its
// own tests check it against published IGRF values), the truncation error falling with the degree.
#include <erfa.h>
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <random>

#include "attitude_estimator/onboard_clock.hpp"
#include "attitude_estimator/onboard_computer.hpp"
#include "attitude_estimator/onboard_field.hpp"
#include "attitude_estimator/onboard_sun.hpp"
#include "environment/earth_rotation.hpp"
#include "environment/geomagnetic_field.hpp"
#include "environment/time_scales.hpp"
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
