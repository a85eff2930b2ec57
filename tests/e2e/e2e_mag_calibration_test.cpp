// Issue 27 end to end: the magnetometer calibrated in flight. The bundled leo_orbit with the estimator sampled
// at 1 Hz (one calibration equation per sample) for one orbit. The calibration sees only the readings and the
// reference field's magnitude; the test compares the field the estimator then uses (est.mag_field) with the
// environment's true body field. The magnetometer's sensor matrix is M = (1 − c) I + c J (c its cross_axis
// parameter, read from the system at test time, J the all-ones matrix; no misalignment), so uncorrected the
// field is off by (M − I) B = c (J − I) B; calibrated, only the 12-bit steps and the noise should remain.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "engine/execution.hpp"
#include "engine/system.hpp"
#include "engine/system_description.hpp"
#include "recorder.hpp"

TEST(E2eLeoMagCalibration, TheCalibratedFieldLosesTheCrossAxisCoupling) {
    cosim::SystemOptions options;
    options.fmu_dirs = {PVATT_FMU_DIR};
    // The spacecraft's own field is not read here: its currents' part follows the sun on the faces, so no
    // calibration removes it (with it read the calibrated field is 254 nT RMS off the true body field sunlit,
    // 75 nT in eclipse: docs/filter.md); what this test judges is the sensor's coupling, which it can remove.
    options.settings = {"est.sample_period=1", "mag.noise_sample_period=1", "est.mag_calibration=true",
                        "est.mag_calibration_every=1", "est.mag_calibration_min=600", "mag.read_spacecraft_field=false",
                        // Nor does the computer take out the strings' field the sensor does not read here.
                        "est.mag_string_field=false",
                        // The fault detection (on as bundled) is made for the bundled 20 Hz set/reset pairs: at
                        // 1 Hz it declared every axis spiking and biased once the calibration applied (open).
                        "est.detect_faults=false"};
    cosim::System system(cosim::read_system_description(PVATT_SYSTEMS_DIR "/leo_orbit.ssd"), options);
    cosim::ExecutionOptions ex;
    ex.stop_time = 5764.0;
    ex.output_interval = 1.0;  // = the estimator's sample period here: rows fall on sample instants
    auto cols = e2e::vec("est.mag_field", 3);
    for (const auto& n : e2e::vec("env.mag_body", 3)) cols.push_back(n);
    cols.push_back("est.mag_cal_valid");
    cols.push_back("est.mag_valid");
    cols.push_back("mag.cross_axis");
    e2e::Recorder rec(system, cols);
    cosim::Execution(system, ex).run({&rec});

    const std::size_t last = rec.time.size() - 1;
    const double c = rec["mag.cross_axis"][last];
    ASSERT_GT(c, 0.0);
    ASSERT_GT(rec["est.mag_cal_valid"][last], 0.5);
    EXPECT_LT(rec["est.mag_cal_valid"][599], 0.5);  // not before 600 equations
    // Over the last third of the orbit: the field's error against the truth, and the coupling's share of it.
    double err2 = 0.0, coupling2 = 0.0;
    int n = 0;
    for (std::size_t k = 2 * last / 3; k <= last; ++k) {
        if (rec["est.mag_valid"][k] < 0.5 || rec["est.mag_cal_valid"][k] < 0.5) continue;
        double b[3], e[3];
        for (int i = 0; i < 3; ++i) {
            b[i] = rec["env.mag_body[" + std::to_string(i + 1) + "]"][k];
            e[i] = rec["est.mag_field[" + std::to_string(i + 1) + "]"][k] - b[i];
        }
        for (int i = 0; i < 3; ++i) {
            const double coupling = c * (b[0] + b[1] + b[2] - b[i]);  // (c (J − I) B)_i
            coupling2 += coupling * coupling;
            err2 += e[i] * e[i];
        }
        ++n;
    }
    ASSERT_GT(n, 1000);
    const double rms_err = std::sqrt(err2 / n), rms_coupling = std::sqrt(coupling2 / n);
    std::printf(
        "leo_orbit, last third of one orbit at 1 Hz: calibrated field error %.1f nT rms, the coupling it "
        "removes %.1f nT rms\n",
        1e9 * rms_err, 1e9 * rms_coupling);
    // What is left is mostly the converter (0.122 µT steps: 0.061 µT rms over three axes; measured 0.083 µT
    // with the noise, the set/reset residue at 1 Hz and the calibration's own residue), about half the
    // coupling the calibration took out (uncorrected, the error would be √(coupling² + converter²)).
    EXPECT_LT(rms_err, 0.6 * rms_coupling);
    EXPECT_LT(rms_err, 100e-9);
}
