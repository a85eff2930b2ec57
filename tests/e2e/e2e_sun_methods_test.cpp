// Issue 8 end to end: the LEO system (tumbling, Earth albedo on, Kelly-cosine panels) with each of the
// estimator's sun methods chosen by a setting, as a user does with `cosim run --set est.sun_method=...`.
// The measured sun direction (est.sun_meas) is scored against the truth (env.sun_body) in the sunlit first
// 1800 s of the orbit (the eclipse begins near 1900 s). Thresholds come from the physics, stated beside
// each check; the numbers themselves are printed for the record (and in the closing note).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "execution.hpp"
#include "recorder.hpp"
#include "system.hpp"
#include "system_description.hpp"

namespace {

struct SunScore {
    int lit = 0;          // rows with direct sun
    int valid = 0;        // of those, rows with a valid sun vector
    double median = 0.0;  // degrees, over the valid rows
    double p95 = 0.0;
};

SunScore run_leo(const std::string& method) {
    cosim::SystemOptions options;
    options.fmu_dirs = {PVATT_FMU_DIR};
    options.settings = {"est.sample_period=1", "mag.noise_sample_period=1", "est.sun_method=" + method};
    cosim::System system(cosim::read_system_description(PVATT_SYSTEMS_DIR "/leo_orbit.ssd"), options);
    cosim::ExecutionOptions ex;
    ex.stop_time = 1800.0;
    ex.output_interval = 10.0;
    ex.relative_tolerance = 1e-6;
    auto cols = e2e::columns();
    cols.push_back("est.sun_valid");
    e2e::Recorder rec(system, cols);
    cosim::Execution(system, ex).run({&rec});

    SunScore score;
    std::vector<double> errors;
    for (std::size_t k = 1; k < rec.time.size(); ++k) {
        if (rec["env.irradiance"][k] <= 0.0) continue;
        ++score.lit;
        if (rec["est.sun_valid"][k] < 0.5) continue;
        ++score.valid;
        const double real[3] = {rec["env.sun_body[1]"][k], rec["env.sun_body[2]"][k], rec["env.sun_body[3]"][k]};
        const double meas[3] = {rec["est.sun_meas[1]"][k], rec["est.sun_meas[2]"][k], rec["est.sun_meas[3]"][k]};
        errors.push_back(e2e::angle_deg(real, meas));
    }
    std::sort(errors.begin(), errors.end());
    if (!errors.empty()) {
        score.median = errors[errors.size() / 2];
        score.p95 = errors[std::min(errors.size() - 1, errors.size() * 95 / 100)];
    }
    std::printf("LEO 0-1800 s, sun_method %s: %d lit rows, %d valid; sun error median %.2f deg, p95 %.2f deg\n",
                method.c_str(), score.lit, score.valid, score.median, score.p95);
    return score;
}

TEST(E2eLeoSunMethods, EverySunMethodRunsAndTheResponseInversionRemovesTheKellyBias) {
    const SunScore difference = run_leo("difference");
    const SunScore inverse = run_leo("inverse_response");
    const SunScore cones = run_leo("cones");
    const SunScore three = run_leo("three_faces");
    ASSERT_GT(difference.lit, 150);  // 180 rows, all before the eclipse
    // Albedo never reaches half of full sun on a face, so eq. 5's |s| and the face methods' norms stay
    // above min_sun_norm whenever the sun is up: (nearly) every lit row is valid.
    EXPECT_GE(difference.valid, difference.lit * 95 / 100);
    EXPECT_GE(inverse.valid, inverse.lit * 90 / 100);
    EXPECT_GE(cones.valid, cones.lit * 90 / 100);
    // three_faces needs one lit face on every axis: about two thirds of the sphere with Kelly panels
    // (the dark band of each axis removes about 3 × 11.7 % plus the overlaps), and with albedo it refuses
    // axes where both faces read light (the Monte-Carlo: 33 % valid), so only a fraction of the rows.
    EXPECT_GT(three.valid, three.lit / 10);
    // eq. 5 on Kelly panels errs by degrees (4.4° median over the sphere, docs/sun_methods.md); inverting the
    // response removes that bias, so its median must be well below eq. 5's.
    EXPECT_GT(difference.median, 2.0);
    EXPECT_LT(inverse.median, 0.75 * difference.median);
    EXPECT_LT(three.median, 0.75 * difference.median);
    RecordProperty("difference_median_deg", std::to_string(difference.median));
    RecordProperty("inverse_response_median_deg", std::to_string(inverse.median));
    RecordProperty("cones_median_deg", std::to_string(cones.median));
    RecordProperty("three_faces_median_deg", std::to_string(three.median));
}

}  // namespace
