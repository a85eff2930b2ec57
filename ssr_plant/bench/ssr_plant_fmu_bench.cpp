// Speed of the ssr_plant block alone on the 10 s seed scenario, as it runs inside the FMU in
// Co-Simulation (ModelRunner + CsSolver with CVODE), inputs from the seed formula updated every
// communication step. Prints wall time, real-time factor and the solver counts; run by hand.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string_view>

#include "fmu/cs_solver.hpp"
#include "fmu/model_runner.hpp"
#include "ssr_plant/ssr_plant_block.hpp"

int main(int argc, char** argv) {
    const double duration = argc > 1 ? std::atof(argv[1]) : 10.0;
    const double h = argc > 2 ? std::atof(argv[2]) : 0.5e-3;  // communication step: inputs every 0.5 ms
    const char* only = argc > 3 ? argv[3] : nullptr;
    for (const char* fidelity : {"switching", "averaged"}) {
        if (only && std::string_view(only) != fidelity) continue;
        fmu::ModelRunner runner{std::make_unique<ssr_plant::SsrPlantBlock>()};
        auto& d = static_cast<ssr_plant::SsrPlantBlock&>(runner.model()).data();
        d.fidelity.assign(fidelity);
        auto sun = [](double t) {
            const double phi = 1.26 * t, theta = 6.28 * t;
            return std::array<double, 3>{std::sin(phi) * std::sin(theta), std::cos(phi) * std::sin(theta), std::cos(theta)};
        };
        const auto start = std::chrono::steady_clock::now();
        d.sun_body = sun(0.0);
        runner.set_initializing(true);
        runner.ensure_evaluated();
        runner.set_initializing(false);
        fmu::CsSolver solver(runner, 1e-6);
        runner.event_iteration();
        const long steps = std::lround(duration / h);
        for (long k = 1; k <= steps; ++k) {
            d.sun_body = sun((k - 1) * h);
            runner.mark_changed();
            solver.invalidate();
            solver.advance(k * h);
        }
        const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const auto s = solver.statistics();
        std::printf("%-9s %.0f s simulated in %.3f s wall: real-time factor %.1f; communication steps %ld, time events %lld, "
                    "state events %lld, CVODE steps %lld, right-hand sides %lld, restarts %lld\n",
                    fidelity, duration, wall, duration / wall, steps, static_cast<long long>(s.time_events),
                    static_cast<long long>(s.state_events), static_cast<long long>(s.steps),
                    static_cast<long long>(s.rhs_evaluations), static_cast<long long>(s.restarts));
    }
}
