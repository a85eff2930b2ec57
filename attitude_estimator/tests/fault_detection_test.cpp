// Fault detection and isolation on board (fault_detection.hpp): hand-made measurements of a healthy and a
// faulty sensor, each with its expectation worked out here from the cosine law, the set/reset algebra or
// the definition of the test, never from the code under test.
#include "attitude_estimator/fault_detection.hpp"

#include <cmath>

#include "attitude_estimator/mekf.hpp"
#include "fault_test_support.hpp"
#include "test_support.hpp"

namespace attitude_estimator::test {
namespace {

template <class T>
class EstimatorCoreFaults : public ::testing::Test {};
TYPED_TEST_SUITE(EstimatorCoreFaults, Scalars, ScalarName);

// A lit scene: the sun in body axes at (0.8, 0.48, 0.36) (unit: 0.64 + 0.2304 + 0.1296 = 1), cosine panels,
// so faces +x, +y, +z read 0.8, 0.48, 0.36 of full sun and the others nothing.
template <class T>
struct Scene {
    panel_response::Response<T> cosine = panel_response::cosine<T>();
    Vec3<T> sun{T(0.8), T(0.48), T(0.36)};
    std::array<T, 6> r{T(0.8), T(0), T(0.48), T(0), T(0.36), T(0)};
    T i_norm = T(0.84754);  // A at full sun

    FaultObservation<T> observation(T t) const { return face_observation(cosine, sun, r, i_norm, t); }
};

// Runs n samples from t0; returns the time of the first declaration on face k (−1 if none).
template <class T, class Make>
T run_faces(FaultDetectionState<T>& s, int n, double t0, const Make& make, std::size_t k) {
    const auto c = enabled<T>();
    for (int i = 0; i < n; ++i) fault_detect(s, make(T(t0 + i * kPeriod)), c);
    return s.face_time[k];
}

TYPED_TEST(EstimatorCoreFaults, HealthyFacesWithAlbedoAndPenumbraDeclareNothing) {
    using T = TypeParam;
    const Scene<T> scene;
    FaultDetectionState<T> s;
    // Albedo adds light: 0.35 of full sun on the dark −z face (toward nadir) and 0.2 on top of +y.
    run_faces(
        s, 2000, 0.0,
        [&](T t) {
            auto o = scene.observation(t);
            o.face_r[5] = T(0.35);
            o.face_r[2] += T(0.2);
            for (std::size_t k = 0; k < 6; ++k) o.i_face[k] = o.face_r[k] * scene.i_norm;
            for (std::size_t k = 0; k < 3; ++k) o.i_sh[k] = o.i_face[2 * k] - o.i_face[2 * k + 1];
            return o;
        },
        0);
    // Penumbra: every face at 55 % of its sunlit reading (the others show 0.55 ≥ 0.5: tested, and passing
    // since +x reads 0.55 × 0.8 = 0.44 > 0.55 × 0.8 − 0.3); then eclipse (nothing lit: not tested).
    run_faces(
        s, 2000, 100.0,
        [&](T t) {
            auto o = scene.observation(t);
            for (auto& v : o.face_r) v *= T(0.55);
            for (auto& v : o.i_face) v *= T(0.55);
            for (auto& v : o.i_sh) v *= T(0.55);
            return o;
        },
        0);
    run_faces(
        s, 2000, 200.0,
        [&](T t) {
            auto o = scene.observation(t);
            o.face_r = {};
            o.i_face = {};
            o.i_sh = {};
            return o;
        },
        0);
    for (std::size_t k = 0; k < 6; ++k) {
        EXPECT_EQ(s.face_word[k], 0u) << "face " << k;
        EXPECT_EQ(s.face_time[k], T(-1));
    }
    EXPECT_EQ(excluded_faces(s), 0);
}

TYPED_TEST(EstimatorCoreFaults, AnOpenStringIsDeclaredAfterTheConfirmationTimeOnThatFaceOnly) {
    using T = TypeParam;
    const Scene<T> scene;
    FaultDetectionState<T> s;
    // +x's string opens at t = 10 s: it reads 0 (its Hall channel too, so i_sh[x] = −i(−x) = 0 stays
    // consistent) where the cosine law says 0.8; the others (+y, +z) show full sun. Failing from the first
    // sample at t = 10 s, 5 s of evidence is the 100th failing sample: t = 10 + 99 × 0.05 = 14.95 s.
    const T declared = run_faces(
        s, 600, 0.0,
        [&](T t) {
            auto o = scene.observation(t);
            if (t >= T(10) - T(1e-4)) {
                o.face_r[0] = T(0);
                o.i_face[0] = T(0);
                o.i_sh[0] = T(0);
            }
            return o;
        },
        0);
    EXPECT_NEAR(declared, 14.95, 0.051);
    EXPECT_EQ(s.face_word[0], kFaultFaceDeficit);
    for (std::size_t k = 1; k < 6; ++k) EXPECT_EQ(s.face_word[k], 0u) << "face " << k;
    EXPECT_EQ(excluded_faces(s), 1);
}

TYPED_TEST(EstimatorCoreFaults, AnOpenFaceDoesNotLowerTheBarForTheOthers) {
    using T = TypeParam;
    const Scene<T> scene;
    FaultDetectionState<T> s;
    // +x open, and the Earth adds 0.35 of full sun on +y (0.48 + 0.35 = 0.83). The sun is as bright as
    // ever: +y's excess test compares 0.83 with 0.48 + 0.6 = 1.08 and passes, and +x alone is declared.
    // (Scaled by the irradiance the other faces show — (0 + 0.36)/(0.8 + 0.36) = 0.31 with +x dark — the
    // bar would be 0.31 × 0.48 + 0.6 = 0.75 and +y would be declared as well.)
    run_faces(
        s, 400, 0.0,
        [&](T t) {
            auto o = scene.observation(t);
            o.face_r[0] = T(0);
            o.face_r[2] = T(0.83);
            for (std::size_t k = 0; k < 6; ++k) o.i_face[k] = o.face_r[k] * scene.i_norm;
            for (std::size_t k = 0; k < 3; ++k) o.i_sh[k] = o.i_face[2 * k] - o.i_face[2 * k + 1];
            return o;
        },
        0);
    EXPECT_EQ(s.face_word[0], kFaultFaceDeficit);
    EXPECT_EQ(excluded_faces(s), 0b000001);
}

TYPED_TEST(EstimatorCoreFaults, APassBeforeTheConfirmationTimeClearsTheEvidence) {
    using T = TypeParam;
    const Scene<T> scene;
    FaultDetectionState<T> s;
    // +x reads nothing for 4 s out of every 4.05 s (80 failing samples, then one healthy): never 5 s in a row.
    run_faces(
        s, 4000, 0.0,
        [&](T t) {
            auto o = scene.observation(t);
            const long i = std::lround(static_cast<double>(t) / kPeriod);
            if (i % 81 != 80) {
                o.face_r[0] = T(0);
                o.i_face[0] = T(0);
                o.i_sh[0] = T(0);
            }
            return o;
        },
        0);
    EXPECT_EQ(s.face_word[0], 0u);
}

TYPED_TEST(EstimatorCoreFaults, AFaceTurnedAwayNeitherConfirmsNorClears) {
    using T = TypeParam;
    Scene<T> scene;
    FaultDetectionState<T> s;
    // +x open throughout. 3 s with the sun on it (failing), 60 s with the sun at (0, 0.8, 0.6) (+x edge-on:
    // not tested), 2 s back on it: 5 s of failing in all → declared at the last of them.
    const auto open = [](FaultObservation<T> o) {
        o.face_r[0] = T(0);
        o.i_face[0] = T(0);
        o.i_sh[0] = T(0);
        return o;
    };
    run_faces(
        s, 60, 0.0, [&](T t) { return open(scene.observation(t)); }, 0);
    Scene<T> away;
    away.sun = {T(0), T(0.8), T(0.6)};
    away.r = {T(0), T(0), T(0.8), T(0), T(0.6), T(0)};
    run_faces(
        s, 1200, 3.0, [&](T t) { return open(away.observation(t)); }, 0);
    EXPECT_EQ(s.face_word[0], 0u);
    const T declared = run_faces(
        s, 40, 63.0, [&](T t) { return open(scene.observation(t)); }, 0);
    EXPECT_NEAR(declared, 63.0 + 39 * kPeriod, 0.051);
}

TYPED_TEST(EstimatorCoreFaults, AHallChannelThatDisagreesWithItsFacesMarksThePair) {
    using T = TypeParam;
    const Scene<T> scene;
    FaultDetectionState<T> s;
    // i_sh[y] 50 mA off (beyond the 20 mA tolerance): both y faces get the bus bit after 5 s; x and z stay.
    run_faces(
        s, 200, 0.0,
        [&](T t) {
            auto o = scene.observation(t);
            o.i_sh[1] += T(0.05);
            return o;
        },
        2);
    EXPECT_EQ(s.face_word[2], kFaultFaceBus);
    EXPECT_EQ(s.face_word[3], kFaultFaceBus);
    EXPECT_EQ(excluded_faces(s), 0b001100);
    // 15 mA off is within tolerance (two 12-bit converters' quantization is below 2 mA).
    FaultDetectionState<T> ok;
    run_faces(
        ok, 200, 0.0,
        [&](T t) {
            auto o = scene.observation(t);
            o.i_sh[1] += T(0.015);
            return o;
        },
        2);
    EXPECT_EQ(excluded_faces(ok), 0);
}

TYPED_TEST(EstimatorCoreFaults, AStuckHallReadingFullCurrentIsAnExcess) {
    using T = TypeParam;
    const Scene<T> scene;
    FaultDetectionState<T> s;
    // −x (dark by the cosine law) reads 1.0 of full sun: more than sun (0) + the 0.6 albedo allowance.
    run_faces(
        s, 200, 0.0,
        [&](T t) {
            auto o = scene.observation(t);
            o.face_r[1] = T(1);
            o.i_face[1] = scene.i_norm;
            o.i_sh[0] = o.i_face[0] - o.i_face[1];
            return o;
        },
        1);
    EXPECT_EQ(s.face_word[1], kFaultFaceExcess);
    EXPECT_EQ(excluded_faces(s), 0b000010);
}

// The magnetometer: field B = (25, −20, 20) µT in body axes, offset 20 mV, 1 V/gauss = 1e4 V/T; readings
// alternate set (p = +1) and reset (p = −1): v − v_ref = p S B + v_os.
template <class T>
struct Field {
    Vec3<T> b{T(25e-6), T(-20e-6), T(20e-6)};
    T s = T(1e4), v_os = T(0.02);
    FaultObservation<T> observation(int i) const {
        FaultObservation<T> o;
        o.t = T(i * kPeriod);
        o.sample_period = T(kPeriod);
        o.predicted = true;
        o.prediction_valid = true;
        o.sun_body = {T(1), T(0), T(0)};
        o.field_body = b;
        o.polarity = i % 2 == 0 ? T(1) : T(-1);
        o.sensitivity = s;
        for (std::size_t k = 0; k < 3; ++k) o.mag_reading[k] = o.polarity * s * b[k] + v_os;
        o.field_usable = true;
        o.field = b;
        o.field_ref_norm = std::sqrt(T(25e-6 * 25e-6 + 2 * 20e-6 * 20e-6));
        return o;
    }
};

template <class T, class Make>
void run_axes(FaultDetectionState<T>& s, int n, const Make& make) {
    const auto c = enabled<T>();
    for (int i = 0; i < n; ++i) fault_detect(s, make(i), c);
}

TYPED_TEST(EstimatorCoreFaults, AHealthyMagnetometerDeclaresNothing) {
    using T = TypeParam;
    const Field<T> f;
    FaultDetectionState<T> s;
    // With a 7 µT field of the spacecraft's own along −x (the leo_orbit dipole is 7.3 µT at the sensor):
    // x flips by 25 − 7 = 18 µT ≥ 0.25 × 25; the norm moves by less than 12 µT.
    run_axes(s, 2000, [&](int i) {
        auto o = f.observation(i);
        o.mag_reading[0] -= o.polarity * f.s * T(7e-6);
        o.field[0] -= T(7e-6);
        return o;
    });
    EXPECT_EQ(excluded_axes(s), 0);
    EXPECT_EQ(s.norm_word, 0u);
}

TYPED_TEST(EstimatorCoreFaults, AnAxisStuckAtItsLastValueDoesNotFlip) {
    using T = TypeParam;
    const Field<T> f;
    FaultDetectionState<T> s;
    // y freezes at sample 100 (t = 5 s) at the reading it had then: its half difference is 0 where 20 µT
    // is predicted. Flip tests from sample 101 on; the 100th failing one is sample 200 (t = 10 s).
    const int stuck = 100;
    const T frozen = f.observation(stuck).mag_reading[1];
    run_axes(s, 400, [&](int i) {
        auto o = f.observation(i);
        if (i >= stuck) o.mag_reading[1] = frozen;
        return o;
    });
    EXPECT_EQ(s.axis_word[1], kFaultAxisNoFlip);
    EXPECT_NEAR(s.axis_time[1], 10.0, 0.051);
    EXPECT_EQ(s.axis_word[0], 0u);
    EXPECT_EQ(s.axis_word[2], 0u);
    EXPECT_EQ(excluded_axes(s), 0b010);
}

TYPED_TEST(EstimatorCoreFaults, AFailedStrapIsDeclaredOnceAndKeepsTheFieldInTheStuckPolarity) {
    using T = TypeParam;
    const Field<T> f;
    FaultDetectionState<T> s;
    // The strap fails after sample 99 (a reset, p = −1): from sample 100 on every reading is −S B + v_os
    // whatever the polarity commanded. The set/reset mean follows the stuck readings (here at once, the
    // worst case): the offset offered from sample 100 on is −S B + v_os.
    const int onset = 100;
    run_axes(s, 400, [&](int i) {
        auto o = f.observation(i);
        o.mag_offset = {f.v_os, f.v_os, f.v_os};
        if (i >= onset)
            for (std::size_t k = 0; k < 3; ++k) {
                o.mag_reading[k] = -f.s * f.b[k] + f.v_os;
                o.mag_offset[k] = o.mag_reading[k];
            }
        return o;
    });
    // From sample 100 the half difference of the three axes is 0, where the field left without its largest
    // component is √(20² + 20²) = 28.3 µT ≥ 15 µT: the 100th failing sample is 199 (t = 9.95 s). Every axis
    // would fail its own flip test as well, but none is blamed: the strap is common to the three.
    for (std::size_t k = 0; k < 3; ++k) {
        EXPECT_EQ(s.axis_word[k], kFaultAxisStrap);
        EXPECT_NEAR(s.axis_time[k], 9.95, 1e-3);
    }
    EXPECT_EQ(excluded_axes(s), 0);
    EXPECT_TRUE(s.strap_failed);
    // The film stayed reset; the offset is the one offered at the last pass (sample 99), v_os.
    EXPECT_EQ(s.strap_polarity, T(-1));
    for (std::size_t k = 0; k < 3; ++k) EXPECT_NEAR(s.strap_offset[k], 0.02, 1e-7);
}

TYPED_TEST(EstimatorCoreFaults, AStuckAxisAlongTheFieldIsNotTakenForTheStrap) {
    using T = TypeParam;
    Field<T> f;
    // The field almost along x, (40, 5, 5) µT: y and z together show √50 = 7.1 µT < 15 µT, so the strap
    // test cannot tell a stuck x from a failed strap and does not run; x's own flip test (40 ≥ 15 µT) does.
    f.b = {T(40e-6), T(5e-6), T(5e-6)};
    FaultDetectionState<T> s;
    const int stuck = 100;
    const T frozen = f.observation(stuck).mag_reading[0];
    run_axes(s, 400, [&](int i) {
        auto o = f.observation(i);
        o.field_ref_norm = std::sqrt(T(40e-6 * 40e-6 + 2 * 5e-6 * 5e-6));
        if (i >= stuck) o.mag_reading[0] = frozen;
        return o;
    });
    EXPECT_EQ(s.axis_word[0], kFaultAxisNoFlip);
    EXPECT_NEAR(s.axis_time[0], 10.0, 0.051);
    EXPECT_FALSE(s.strap_failed);
    EXPECT_EQ(excluded_axes(s), 0b001);
}

TYPED_TEST(EstimatorCoreFaults, WithTheCalibrationsHardIronInThePredictionAWeakerFieldIsTested) {
    using T = TypeParam;
    Field<T> f;
    // y sees 8 µT: below the 15 µT bar of an uncalibrated prediction, above a 5 µT bar once the
    // calibration's hard iron is in it. y freezes at sample 100: failing from sample 101, declared at the
    // 100th failing sample, 200 (t = 10 s), only with the calibrated prediction.
    f.b = {T(25e-6), T(-8e-6), T(20e-6)};
    auto c = enabled<T>();
    c.flip_min_field_calibrated = T(5e-6);
    const int stuck = 100;
    const T frozen = f.observation(stuck).mag_reading[1];
    for (const bool calibrated : {false, true}) {
        FaultDetectionState<T> s;
        for (int i = 0; i < 400; ++i) {
            auto o = f.observation(i);
            o.field_ref_norm = std::sqrt(T(25e-6 * 25e-6 + 8e-6 * 8e-6 + 20e-6 * 20e-6));
            o.field_calibrated = calibrated;
            if (i >= stuck) o.mag_reading[1] = frozen;
            fault_detect(s, o, c);
        }
        EXPECT_EQ(s.axis_word[1], calibrated ? kFaultAxisNoFlip : 0u);
        if (calibrated) {
            EXPECT_NEAR(s.axis_time[1], 10.0, 0.051);
        }
        EXPECT_EQ(s.axis_word[0] | s.axis_word[2], 0u);
        EXPECT_FALSE(s.strap_failed);
    }
    // Healthy, the same weak axis flips by its 8 µT ≥ 0.25 × 8: nothing declared.
    FaultDetectionState<T> healthy;
    for (int i = 0; i < 2000; ++i) {
        auto o = f.observation(i);
        o.field_ref_norm = std::sqrt(T(25e-6 * 25e-6 + 8e-6 * 8e-6 + 20e-6 * 20e-6));
        o.field_calibrated = true;
        fault_detect(healthy, o, c);
    }
    EXPECT_EQ(excluded_axes(healthy), 0);
}

TYPED_TEST(EstimatorCoreFaults, AnAxisAtARailIsDeclaredAndAWrongNormIsSeen) {
    using T = TypeParam;
    const Field<T> f;
    FaultDetectionState<T> s;
    run_axes(s, 200, [&](int i) {
        auto o = f.observation(i);
        o.at_rail[2] = true;
        // The norm test only runs on a complete field: with z at a rail it is not offered.
        o.field_usable = false;
        return o;
    });
    EXPECT_EQ(s.axis_word[2] & kFaultAxisRail, kFaultAxisRail);
    EXPECT_EQ(s.norm_word, 0u);
    // 20 µT more along x: |B| = √(45² + 20² + 20²) = 53.2 µT against |B_ref| = √(25² + 20² + 20²) = 37.7 µT,
    // 15.4 µT over the 12 µT tolerance: the norm test fails, naming no axis.
    FaultDetectionState<T> n;
    run_axes(n, 200, [&](int i) {
        auto o = f.observation(i);
        o.field[0] += T(20e-6);
        o.mag_reading[0] += o.polarity * f.s * T(20e-6);
        return o;
    });
    EXPECT_EQ(n.norm_word, 1u);
    EXPECT_EQ(excluded_axes(n), 0);
}

// The face tests judge the readings against the filter's prediction only while the filter calls itself valid
// (FaultObservation::prediction_valid). A filter lost from its start predicts the sun at the opposite corner,
// (−0.8, −0.48, −0.36), while the faces read the true sun at (0.8, 0.48, 0.36): +x reads 0.8 where nothing is
// predicted, above the excess bar 0 + 0.6. Called valid, that wrong prediction declares the healthy +x face in
// the confirmation time (5 s); not valid, 20 s of it declare nothing, and the healthy faces stay in use.
TYPED_TEST(EstimatorCoreFaults, TheFaceTestsWaitForAValidFilter) {
    using T = TypeParam;
    const Scene<T> scene;
    const auto lost = [&](bool valid) {
        return [&scene, valid](T t) {
            auto o = scene.observation(t);
            for (auto& v : o.sun_body) v = -v;
            o.prediction_valid = valid;
            return o;
        };
    };
    FaultDetectionState<T> believed;
    const T declared = run_faces(believed, 400, 0.0, lost(true), 0);
    EXPECT_NEAR(double(declared), enabled<T>().confirm_time - kPeriod, 1e-4);
    EXPECT_EQ(believed.face_word[0] & kFaultFaceExcess, kFaultFaceExcess);
    FaultDetectionState<T> waited;
    EXPECT_LT(run_faces(waited, 400, 0.0, lost(false), 0), T(0));
    EXPECT_EQ(excluded_faces(waited), 0);
    for (std::size_t k = 0; k < 6; ++k) EXPECT_EQ(waited.face_word[k], 0u) << "face " << k;
}

TYPED_TEST(EstimatorCoreFaults, NothingIsTestedWhenDisabledOrWithoutAPrediction) {
    using T = TypeParam;
    const Scene<T> scene;
    FaultDetectionState<T> s;
    FaultDetectionConfig<T> off;  // enabled = false
    for (int i = 0; i < 400; ++i) {
        auto o = scene.observation(T(i * kPeriod));
        o.face_r[0] = T(0);
        fault_detect(s, o, off);
    }
    EXPECT_EQ(excluded_faces(s), 0);
    // Enabled, no filter prediction: the open face cannot be told from a face turned away.
    const auto on = enabled<T>();
    for (int i = 0; i < 400; ++i) {
        auto o = scene.observation(T(i * kPeriod));
        o.predicted = false;
        o.face_r[0] = T(0);
        o.i_face[0] = T(0);
        o.i_sh[0] = T(0);
        fault_detect(s, o, on);
    }
    EXPECT_EQ(excluded_faces(s), 0);
}

TYPED_TEST(EstimatorCoreFaults, AnExcludedAxisLeavesTheFilterAsIfItWereNotThere) {
    using T = TypeParam;
    // One field update on a started filter: with z excluded, a z reading 30 µT off and an exact one give
    // the same state bit for bit; with every axis in, the wrong one moves the attitude.
    MekfConfig<T> c;
    MekfState<T> start;
    mekf_start(start, Quaternion<T>{}, Vec3<T>{}, T(0), c);
    const Vec3<T> ref{T(20e-6), T(-10e-6), T(30e-6)};  // identity attitude: body = reference
    const Vec3<T> wrong{ref[0], ref[1], ref[2] + T(30e-6)};
    MekfState<T> a = start, b = start, all = start;
    mekf_update_field(a, ref, ref, T(1), c, 0b011);
    mekf_update_field(b, ref, wrong, T(1), c, 0b011);
    EXPECT_EQ(a.q.x, b.q.x);
    EXPECT_EQ(a.q.y, b.q.y);
    EXPECT_EQ(a.q.z, b.q.z);
    EXPECT_EQ(a.q.w, b.q.w);
    for (std::size_t i = 0; i < a.p.size(); ++i) EXPECT_EQ(a.p[i], b.p[i]);
    c.gate = T(1e30);  // take the wrong reading whatever its NIS
    mekf_update_field(all, ref, wrong, T(1), c, 0b111);
    EXPECT_GT(std::abs(all.q.x - a.q.x) + std::abs(all.q.y - a.q.y), T(1e-3));
}

}  // namespace
}  // namespace attitude_estimator::test
