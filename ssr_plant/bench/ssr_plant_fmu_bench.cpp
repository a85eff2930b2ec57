// Speed of the ssr_plant block alone on the 10 s seed scenario, as it runs inside the FMU in
// Co-Simulation (ModelRunner + CsSolver with CVODE, rtol 1e-6 as the DefaultExperiment). The inputs are
// the seed's constant-rate spin, s = (sin φ sin θ, cos φ sin θ, cos θ), φ̇ = 1.26 rad/s, θ̇ = 6.28 rad/s,
// 1367 W/m², set at every communication point as a master does (each change restarts CVODE); "held"
// keeps the sun fixed (no input changes: the solver alone). Prints wall time (best of 3), real-time
// factor and the counts behind it. A timing program run by hand, not a test:
//   ssr_plant_fmu_bench [duration=10] [step: 0 = the table below] [switching|averaged|all] [seed|held]
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string_view>
#include <vector>

#include "fmu/cs_solver.hpp"
#include "fmu/model_runner.hpp"
#include "fmu/testing/block_driver.hpp"
#include "ssr_plant/ssr_plant_block.hpp"

namespace {

std::array<double, 3> seed_sun(double t) {
    const double phi = 1.26 * t, theta = 6.28 * t;
    return {std::sin(phi) * std::sin(theta), std::cos(phi) * std::sin(theta), std::cos(theta)};
}

struct Run {
    double wall = 0.0;
    long communication_steps = 0;
    fmu::SolverStatistics stats;
};

Run run_once(const char* fidelity, double duration, double h, bool held) {
    const auto start = std::chrono::steady_clock::now();
    fmu::testing::BlockDriver<ssr_plant::SsrPlantBlock> plant(1e-6);
    auto& d = plant.data();
    plant.set_choice("fidelity", fidelity);
    plant.set_choice("angular_response", "cosine");
    d.sun_body = seed_sun(held ? 0.3 : 0.0);
    plant.start();
    auto& runner = plant.runner;
    auto& solver = *plant.solver;
    Run r;
    r.communication_steps = std::lround(duration / h);
    for (long k = 1; k <= r.communication_steps; ++k) {
        if (!held) {
            d.sun_body = seed_sun(static_cast<double>(k - 1) * h);
            runner.mark_changed();
            solver.invalidate();  // what the runtime does when a master sets an input
        }
        solver.advance(static_cast<double>(k) * h);
    }
    r.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    r.stats = solver.statistics();
    return r;
}

void report(const char* fidelity, double duration, double h, bool held) {
    Run best;
    for (int i = 0; i < 3; ++i) {
        const Run r = run_once(fidelity, duration, h, held);
        if (i == 0 || r.wall < best.wall) best = r;
    }
    const auto& s = best.stats;
    std::printf(
        "%-9s %-5s step %-7g %5.1f s in %8.4f s wall  RTF %8.1f  | comm steps %6ld  PWM (time) events %6lld  "
        "state events %lld  CVODE steps %7lld  RHS %7lld  restarts %6lld\n",
        fidelity, held ? "held" : "seed", h, duration, best.wall, duration / best.wall, best.communication_steps,
        static_cast<long long>(s.time_events), static_cast<long long>(s.state_events), static_cast<long long>(s.steps),
        static_cast<long long>(s.rhs_evaluations), static_cast<long long>(s.restarts));
}

}  // namespace

int main(int argc, char** argv) {
    const double duration = argc > 1 ? std::atof(argv[1]) : 10.0;
    const double step = argc > 2 ? std::atof(argv[2]) : 0.0;
    const std::string_view which = argc > 3 ? argv[3] : "all";
    const bool held = argc > 4 && std::string_view(argv[4]) == "held";
    const std::vector<double> steps =
        step > 0.0 ? std::vector<double>{step} : std::vector<double>{0.5e-3, 1e-3, 1e-2, 0.1};
    for (const char* fidelity : {"switching", "averaged"}) {
        if (which != "all" && which != fidelity) continue;
        for (double h : steps) report(fidelity, duration, h, held);
        if (step <= 0.0) report(fidelity, duration, 1e-3, true);  // and the solver alone
    }
}
