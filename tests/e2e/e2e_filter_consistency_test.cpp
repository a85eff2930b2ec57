// Issue 27 end to end: the recursive filter tells the truth about itself in the bundled leo_orbit. For every
// sun method the bundled system can run (harness/systems/leo_orbit.ssd as bundled, read at test time, only
// est.sun_method set), two orbits through the master; over the second orbit (the first holds the start,
// the magnetometer's in-flight calibration and the field-and-dynamics convergence) the mean normalized
// estimation error squared per degree of freedom, δθᵀ P_θθ⁻¹ δθ / 3 with P_θθ from the filter's own
// est.attitude_cov_sqrt and δθ from the environment's true attitude, must lie in [0.5, 1.5] sunlit and in
// eclipse (1 when the covariance is right; docs/filter.md). The 3σ coverage is reported beside it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "engine/execution.hpp"
#include "engine/system.hpp"
#include "engine/system_description.hpp"
#include "recorder.hpp"

namespace {

constexpr double kOrbit = 5764.0;  // s, leo_orbit's period (its DefaultExperiment)

// Reads the named Real outputs at every output point and accumulates the normalized errors.
struct Consistency : cosim::Observer {
    struct Ref {
        std::size_t component;
        fmi2ValueReference vr;
    };
    std::vector<Ref> refs;
    double nees_sum[2] = {0, 0};  // [0] sunlit, [1] eclipse
    int rows[2] = {0, 0};
    int covered[2] = {0, 0};
    int invalid = 0;

    Consistency(cosim::System& system) {
        std::vector<std::string> names = e2e::vec("env.q_true", 4);
        for (const auto& n : e2e::vec("est.q_filt", 4)) names.push_back(n);
        for (const auto& n : e2e::vec("est.attitude_cov_sqrt", 6)) names.push_back(n);
        names.push_back("env.irradiance");
        names.push_back("est.attitude_bound");
        for (const auto& n : names) {
            const auto dot = n.find('.');
            const auto c = system.component_index(n.substr(0, dot));
            const auto* v = system.components()[c].description().find_variable(n.substr(dot + 1));
            if (!v) throw std::runtime_error("no variable " + n);
            refs.push_back({c, v->value_reference});
        }
    }

    void sample(double t, cosim::System& system) override {
        if (t < kOrbit - 1e-9) return;
        double x[17];
        for (std::size_t i = 0; i < refs.size(); ++i)
            x[i] = system.components()[refs[i].component].instance->get_real(refs[i].vr);
        const double* qt = x;
        const double* qf = x + 4;
        const double* l = x + 8;  // lower Cholesky factor of P_θθ by rows: L11, L21, L22, L31, L32, L33
        const int k = x[14] > 0.0 ? 0 : 1;
        ++rows[k];
        if (!(l[0] > 0 && l[2] > 0 && l[5] > 0)) {
            ++invalid;
            return;
        }
        // δq = q_true ⊗ q̂⁻¹ in Shuster's order (A(δq) = A_true Âᵀ = I − [δθ×]); δθ = 2 vec(δq), sign of δq₄.
        const double x1 = qt[0], y1 = qt[1], z1 = qt[2], w1 = qt[3];
        const double x2 = -qf[0], y2 = -qf[1], z2 = -qf[2], w2 = qf[3];
        double d[3] = {w1 * x2 + w2 * x1 - (y1 * z2 - z1 * y2), w1 * y2 + w2 * y1 - (z1 * x2 - x1 * z2),
                       w1 * z2 + w2 * z1 - (x1 * y2 - y1 * x2)};
        const double s = (w1 * w2 - (x1 * x2 + y1 * y2 + z1 * z2)) < 0 ? -2.0 : 2.0;
        for (double& v : d) v *= s;
        // |L⁻¹ δθ|² by forward substitution.
        const double z0 = d[0] / l[0];
        const double zz1 = (d[1] - l[1] * z0) / l[2];
        const double zz2 = (d[2] - l[3] * z0 - l[4] * zz1) / l[5];
        nees_sum[k] += (z0 * z0 + zz1 * zz1 + zz2 * zz2) / 3.0;
        covered[k] += std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) <= x[15];
    }
    double nees(int k) const { return rows[k] ? nees_sum[k] / rows[k] : NAN; }
    double coverage(int k) const { return rows[k] ? 100.0 * covered[k] / rows[k] : NAN; }
};

class E2eLeoFilterConsistency : public ::testing::TestWithParam<const char*> {};

TEST_P(E2eLeoFilterConsistency, NormalizedErrorNearOneSunlitAndInEclipse) {
    cosim::SystemOptions options;
    options.fmu_dirs = {PVATT_FMU_DIR};
    options.settings = {std::string("est.sun_method=") + GetParam()};
    cosim::System system(cosim::read_system_description(PVATT_SYSTEMS_DIR "/leo_orbit.ssd"), options);
    cosim::ExecutionOptions ex;
    ex.stop_time = 2.0 * kOrbit;
    ex.output_interval = 1.0;  // every 20th estimator sample: the mean over 5764 of them
    Consistency c(system);
    cosim::Execution(system, ex).run({&c});
    std::printf(
        "leo_orbit, sun_method %s, second orbit: NEES/dof sunlit %.3f (%d rows), eclipse %.3f (%d rows); "
        "3-sigma coverage sunlit %.2f %%, eclipse %.2f %%\n",
        GetParam(), c.nees(0), c.rows[0], c.nees(1), c.rows[1], c.coverage(0), c.coverage(1));
    RecordProperty("nees_sunlit", std::to_string(c.nees(0)));
    RecordProperty("nees_eclipse", std::to_string(c.nees(1)));
    RecordProperty("coverage_sunlit_percent", std::to_string(c.coverage(0)));
    ASSERT_GT(c.rows[0], 1000);  // both regimes are in the second orbit
    ASSERT_GT(c.rows[1], 1000);
    EXPECT_EQ(c.invalid, 0);  // the filter runs through the whole second orbit
    for (int k : {0, 1}) {
        EXPECT_GE(c.nees(k), 0.5) << (k ? "eclipse" : "sunlit");
        EXPECT_LE(c.nees(k), 1.5) << (k ? "eclipse" : "sunlit");
    }
}

INSTANTIATE_TEST_SUITE_P(EverySunMethod, E2eLeoFilterConsistency,
                         ::testing::Values("difference", "inverse_response", "cones", "three_faces"));

}  // namespace
