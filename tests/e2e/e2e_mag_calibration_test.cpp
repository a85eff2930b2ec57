// Issue 27 end to end: the magnetometer calibrated in flight. The bundled leo_orbit with the estimator sampled
// at 1 Hz (one calibration equation per sample) for one orbit: the calibration, which sees only the readings and
// the reference field's magnitude, must recover the HMC2003 model's cross-axis coupling. The magnetometer's
// sensor matrix is M = (1 − c) I + c J (c = its cross_axis parameter, read from the system at test time, J the
// all-ones matrix; no misalignment), so the right correction is M⁻¹ = (I − c/(1 + 2c) J)/(1 − c) (by hand:
// J² = 3J).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "execution.hpp"
#include "recorder.hpp"
#include "system.hpp"
#include "system_description.hpp"

TEST(E2eLeoMagCalibration, RecoversTheCrossAxisCouplingFromTheFieldMagnitude) {
    cosim::SystemOptions options;
    options.fmu_dirs = {PVATT_FMU_DIR};
    options.settings = {"est.sample_period=1", "mag.noise_sample_period=1", "est.mag_calibration=true",
                        "est.mag_calibration_every=1", "est.mag_calibration_min=600"};
    cosim::System system(cosim::read_system_description(PVATT_SYSTEMS_DIR "/leo_orbit.ssd"), options);
    cosim::ExecutionOptions ex;
    ex.stop_time = 5764.0;
    ex.output_interval = 10.0;
    auto cols = e2e::vec("est.mag_cal_gain", 9);
    for (const auto& n : e2e::vec("est.mag_cal_offset", 3)) cols.push_back(n);
    cols.push_back("est.mag_cal_valid");
    cols.push_back("mag.cross_axis");
    e2e::Recorder rec(system, cols);
    cosim::Execution(system, ex).run({&rec});

    const std::size_t last = rec.time.size() - 1;
    ASSERT_GT(rec["est.mag_cal_valid"][last], 0.5);
    EXPECT_LT(rec["est.mag_cal_valid"][60], 0.5);  // not before 600 equations (600 s at 1 Hz)
    const double c = rec["mag.cross_axis"][last];
    ASSERT_GT(c, 0.0);
    const double diag = (1.0 - c / (1.0 + 2.0 * c)) / (1.0 - c), off = -c / ((1.0 + 2.0 * c) * (1.0 - c));
    double worst = 0.0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const double g = rec["est.mag_cal_gain[" + std::to_string(3 * i + j + 1) + "]"][last];
            worst = std::max(worst, std::abs(g - (i == j ? diag : off)));
        }
    double offset = 0.0;
    for (int i = 1; i <= 3; ++i)
        offset = std::hypot(offset, rec["est.mag_cal_offset[" + std::to_string(i) + "]"][last]);
    std::printf("leo_orbit, one orbit at 1 Hz: calibration gain within %.2e of M^-1 (coupling %.4f), offset %.2e T\n",
                worst, c, offset);
    // Within 15 % of the coupling after one orbit of 1 Hz equations (0.3e-3 at 20 Hz over two orbits,
    // docs/filter.md); uncalibrated, the error is the coupling itself.
    EXPECT_LT(worst, 0.15 * c);
    // The set/reset differencing leaves little offset (the bundled system pulses every sample; at 1 Hz the
    // field's second difference over a second stays in it).
    EXPECT_LT(offset, 60e-9);
}
