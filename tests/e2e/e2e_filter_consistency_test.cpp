// Issues 27 and 30 end to end: the recursive filter tells the truth about itself in the bundled leo_orbit. One run
// of harness/systems/leo_orbit.ssd as bundled (read at test time) over two orbits through the master, its
// on-board computer `est` running the bundled sun method (difference). The test can run further methods as
// copies of `est` beside it on the same inputs (kMethods; the copies' set/reset commands stay unconnected: the
// schedule is the same for all, so each reads the magnetometer in the polarity it commanded); issue 39 cut it to
// the bundled method for CI's sake: with all four methods it took 99 s under the sanitizers, the longest in CI,
// with inverse_response and three_faces 71 s of CPU, with difference alone 48 s (the truth's blocks over two
// orbits are most of it; judging a shorter span does not hold: the eclipse before 5764 s is the first orbit's,
// NEES/dof 0.17). The other methods' figures: docs/filter.md. The normalized estimation error squared per degree
// of freedom, δθᵀ P_θθ⁻¹ δθ / 3, with P_θθ from the estimator's own attitude_cov_sqrt and δθ from the
// environment's true attitude (1 when the covariance is right; docs/filter.md), must lie
// - over the second orbit (after the start and the in-flight calibration), in [0.5, 1.5] sunlit and in
//   eclipse, the filter running throughout;
// - over the first orbit (the convergence, most of it before the calibration applies), at most 1.5: the
//   filter estimates the spacecraft's own field with the attitude (mekf.hpp, mag_hard_iron_sigma).
//   Without that (the field's 7 µT of hard iron weighed as white noise), NEES/dof 2.2 to 3.3.
// Beside it, the share of rows whose δθᵀ P_θθ⁻¹ δθ lies within χ²(3)'s 99 % point 11.34 (issue 39: 99 % when
// the covariance is right; the 3√(tr P) bound it replaces covers 99.9994 % of a consistent filter's errors and
// read 100 % for an overconfident one too), at least 95 % over the second orbit (issue 39's aim).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "analysis/run_measures.hpp"
#include "engine/execution.hpp"
#include "engine/system.hpp"
#include "engine/system_description.hpp"
#include "filter_nees.hpp"
#include "recorder.hpp"

namespace {

constexpr double kOrbit = 5764.0;  // s, leo_orbit's period (its DefaultExperiment)
constexpr std::array<const char*, 1> kMethods = {"difference"};

// The bundled system with a copy of `est` for each sun method after the first ("est_<method>").
cosim::SystemDescription with_every_sun_method() {
    cosim::SystemDescription d = cosim::read_system_description(PVATT_SYSTEMS_DIR "/leo_orbit.ssd");
    const cosim::ComponentDescription* est = nullptr;
    for (const auto& c : d.components)
        if (c.name == "est") est = &c;
    if (!est) throw std::runtime_error("leo_orbit.ssd has no est");
    const cosim::ComponentDescription original = *est;
    const std::vector<cosim::ConnectionDescription> connections = d.connections;
    const std::vector<cosim::ParameterFeed> feeds = d.feeds;  // the system parameters est receives
    bool bundled_difference = false;
    for (const auto& p : original.parameters)
        if (p.variable == "sun_method") bundled_difference = p.value == kMethods[0];
    if (!bundled_difference) throw std::runtime_error("leo_orbit.ssd's est no longer runs sun_method difference");
    for (std::size_t m = 1; m < kMethods.size(); ++m) {
        cosim::ComponentDescription copy = original;
        copy.name = std::string("est_") + kMethods[m];
        for (auto& p : copy.parameters)
            if (p.variable == "sun_method") p.value = kMethods[m];
        d.components.push_back(copy);
        for (const auto& c : connections)
            if (c.end_element == "est") {
                cosim::ConnectionDescription to_copy = c;
                to_copy.end_element = copy.name;
                d.connections.push_back(to_copy);
            }
        for (const auto& f : feeds)
            if (f.component == "est") {
                cosim::ParameterFeed to_copy = f;
                to_copy.component = copy.name;
                d.feeds.push_back(to_copy);
            }
    }
    return d;
}

// Reads one estimator's Real outputs and the truth at every output point and accumulates its normalized errors.
struct Consistency : cosim::Observer {
    struct Ref {
        std::size_t component;
        fmi2ValueReference vr;
    };
    std::vector<Ref> refs;
    // [0] second orbit sunlit, [1] second orbit in eclipse, [2] first orbit (filter running)
    double nees_sum[3] = {0, 0, 0};
    int rows[3] = {0, 0, 0};
    int covered[3] = {0, 0, 0};
    int invalid = 0;  // second-orbit rows without a running filter

    Consistency(cosim::System& system, const std::string& est) {
        std::vector<std::string> names = e2e::vec("env.q_true", 4);
        for (const auto& n : e2e::vec(est + ".q_filt", 4)) names.push_back(n);
        for (const auto& n : e2e::vec(est + ".attitude_cov_sqrt", 6)) names.push_back(n);
        names.push_back("env.irradiance");
        for (const auto& n : names) {
            const auto dot = n.find('.');
            const auto c = system.component_index(n.substr(0, dot));
            const auto* v = system.components()[c].description().find_variable(n.substr(dot + 1));
            if (!v) throw std::runtime_error("no variable " + n);
            refs.push_back({c, v->value_reference});
        }
    }

    void sample(double t, cosim::System& system) override {
        double x[17];
        for (std::size_t i = 0; i < refs.size(); ++i)
            x[i] = system.components()[refs[i].component].instance->get_real(refs[i].vr);
        const double* qt = x;
        const double* qf = x + 4;
        const double* l = x + 8;  // lower Cholesky factor of P_θθ by rows: L11, L21, L22, L31, L32, L33
        const bool second = t >= kOrbit - 1e-9;
        const int k = second ? (x[14] > 0.0 ? 0 : 1) : 2;
        const bool running = l[0] > 0 && l[2] > 0 && l[5] > 0;
        if (!running) {
            invalid += second;
            return;
        }
        ++rows[k];
        const double nees = e2e::nees_per_dof(qt, qf, l);
        nees_sum[k] += nees;
        covered[k] += 3.0 * nees <= analysis::chi2_3dof_99;
    }
    double nees(int k) const { return rows[k] ? nees_sum[k] / rows[k] : NAN; }
    double coverage(int k) const { return rows[k] ? 100.0 * covered[k] / rows[k] : NAN; }
};

TEST(E2eLeoFilterConsistency, NormalizedErrorNearOneForTheBundledSunMethodAndBoundedWhileConverging) {
    cosim::SystemOptions options;
    options.fmu_dirs = {PVATT_FMU_DIR};
    cosim::System system(with_every_sun_method(), options);
    cosim::ExecutionOptions ex;
    ex.stop_time = 2.0 * kOrbit;
    ex.output_interval = 1.0;  // every 20th estimator sample: the mean over 5764 of them per orbit
    std::vector<Consistency> checks;
    for (std::size_t m = 0; m < kMethods.size(); ++m)
        checks.emplace_back(system, m == 0 ? std::string("est") : std::string("est_") + kMethods[m]);
    std::vector<cosim::Observer*> observers;
    for (auto& c : checks) observers.push_back(&c);
    cosim::Execution(system, ex).run(observers);
    for (std::size_t m = 0; m < kMethods.size(); ++m) {
        const Consistency& c = checks[m];
        const std::string method = kMethods[m];
        std::printf(
            "leo_orbit, sun_method %s: first orbit NEES/dof %.3f (%d rows, chi2(3) 99 %% coverage %.2f %%); second "
            "orbit NEES/dof sunlit %.3f (%d rows), eclipse %.3f (%d rows); chi2(3) 99 %% coverage sunlit %.2f %%, "
            "eclipse %.2f %%\n",
            method.c_str(), c.nees(2), c.rows[2], c.coverage(2), c.nees(0), c.rows[0], c.nees(1), c.rows[1],
            c.coverage(0), c.coverage(1));
        RecordProperty("nees_first_orbit_" + method, std::to_string(c.nees(2)));
        RecordProperty("nees_sunlit_" + method, std::to_string(c.nees(0)));
        RecordProperty("nees_eclipse_" + method, std::to_string(c.nees(1)));
        RecordProperty("chi2_coverage_sunlit_" + method, std::to_string(c.coverage(0)));
        RecordProperty("chi2_coverage_eclipse_" + method, std::to_string(c.coverage(1)));
        EXPECT_GT(c.rows[0], 1000) << method;  // both regimes are in the second orbit
        EXPECT_GT(c.rows[1], 1000) << method;
        EXPECT_GT(c.rows[2], 5000) << method;  // the filter runs within minutes of the start
        EXPECT_EQ(c.invalid, 0) << method;     // and through the whole second orbit
        for (int k : {0, 1}) {
            EXPECT_GE(c.nees(k), 0.5) << method << (k ? " eclipse" : " sunlit");
            EXPECT_LE(c.nees(k), 1.5) << method << (k ? " eclipse" : " sunlit");
            // Issue 39's aim: at least 95 % of the second orbit's samples within chi2(3)'s 99 % point. Met by the
            // bundled method (difference: 100 % sunlit and in eclipse with the drag on board as tuned, NEES/dof 0.630 /
            // 0.606, first orbit 0.569; 97.0 % sunlit, NEES/dof 1.07 / 0.51 before); three_faces reaches 94.75 % sunlit
            // (before the drag tuning: its sun error on the tumbling 3U is the largest, and one calibrated field sigma serves sunlit and
            // eclipse: 15 uT instead of 14 brings it to 95.0 % and the eclipse NEES/dof to 0.500), so the face-based
            // copies are held at 94 %, the measured figure, until the field noise is split by phase (issue 39, open).
            EXPECT_GE(c.coverage(k), m == 0 ? 95.0 : 94.0) << method << (k ? " eclipse" : " sunlit");
        }
        EXPECT_LE(c.nees(2), 1.5) << method << " first orbit";
    }
}

}  // namespace
