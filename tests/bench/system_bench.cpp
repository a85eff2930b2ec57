// Whole-system speed: the bundled systems run as a user runs them, each figure beside its reference
// measured in the same process run (this machine is shared: read the ratios, and the CPU-time column,
// which other processes disturb less than the wall clock). A timing program run by hand, not a test:
//   system_bench [--quick]      (--quick: shorter runs, for a smoke check)
// Prints a Markdown table and the ratios the speed aims are stated in:
//   1. seed_spin.ssd as bundled, 10 s: real-time factor, and its speed over ssr_plant.fmu alone driven
//      with the same kind of inputs (the seed spin, interpolated over the same 1 ms steps);
//   2. leo_orbit.ssd as bundled, one orbit: real-time factor;
//   and the reference execution (--reference of cosim run) of both systems, for the speed-up;
//   3. with PVATT_OMSIMULATOR naming an OMSimulator executable: OMSimulator against `cosim run` on the
//      packed archives (build/systems/*.ssp), each a child process, CPU from RUSAGE_CHILDREN, both writing
//      the same rows (OMSimulator through a Lua script setting its logging interval) and OMSimulator with
//      its default output (a row every step).
#include <sys/resource.h>
#include <time.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "engine/execution.hpp"
#include "engine/fmi2_instance.hpp"
#include "engine/run_defaults.hpp"
#include "engine/system.hpp"
#include "engine/system_description.hpp"
#include "fmi_loader/fmu.hpp"

namespace {

double cpu_seconds() {
    timespec ts{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

std::string load_average() {
    std::ifstream in("/proc/loadavg");
    std::string a, b, c;
    in >> a >> b >> c;
    return a + " " + b + " " + c;
}

struct Row {
    std::string name;
    double simulated = 0, wall = 0, cpu = 0;
    cosim::RunStatistics stats;
    long co_simulation_steps = 0;
};

Row run_system(const std::string& name, const std::string& ssd, double stop, bool reference,
               std::vector<std::string> settings = {}) {
    cosim::SystemOptions options;
    options.fmu_dirs = {PVATT_FMU_DIR};
    options.model_exchange_only = reference;
    options.settings = std::move(settings);
    const auto description = cosim::read_system_description(PVATT_SYSTEMS_DIR "/" + ssd);
    const double cpu0 = cpu_seconds();
    const auto wall0 = std::chrono::steady_clock::now();
    cosim::System system(description, options);  // loading (extraction, dlopen) is part of a user's run
    cosim::ExecutionOptions ex;
    ex.stop_time = stop;
    const auto defaults = cosim::run_defaults(system, 0.0, stop);  // as `cosim run` without options
    ex.output_interval = defaults.output_interval;
    ex.relative_tolerance = defaults.tolerance;
    ex.reference = reference;
    Row r{name, stop, 0, 0, cosim::Execution(system, ex).run({}), 0};
    r.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
    r.cpu = cpu_seconds() - cpu0;
    for (const auto& c : r.stats.components) r.co_simulation_steps += c.steps;
    return r;
}

// ssr_plant.fmu alone in Co-Simulation with the seed scenario's parameters (from seed_spin.ssd), its
// sun input the seed's constant-rate spin s = (sin φ sin θ, cos φ sin θ, cos θ) with its exact time
// derivative over 1 ms steps, as the master gives it in the bundled system.
Row run_plant_alone(double stop) {
    const auto description = cosim::read_system_description(PVATT_SYSTEMS_DIR "/seed_spin.ssd");
    const double cpu0 = cpu_seconds();
    const auto wall0 = std::chrono::steady_clock::now();
    fmi_loader::Fmu fmu(std::string(PVATT_FMU_DIR) + "/ssr_plant.fmu");
    cosim::Fmi2Instance plant(fmu, fmi_loader::FmuKind::co_simulation, "plant");
    plant.setup_experiment(0.0, stop, std::nullopt);
    for (const auto& c : description.components)
        if (c.name == "plant")
            for (const auto& p : c.parameters) plant.apply(p);
    const auto& md = fmu.description();
    std::array<fmi2ValueReference, 4> vr{};
    for (int i = 0; i < 3; ++i) vr[i] = md.find_variable("sun_body[" + std::to_string(i + 1) + "]")->value_reference;
    vr[3] = md.find_variable("irradiance")->value_reference;
    const double irradiance = 1367.0 * 1.00876;  // 1 AU / 0.99565 AU squared: the seed epoch's sun distance
    auto inputs = [&](double t, std::array<double, 4>& u, std::array<double, 4>& du) {
        const double phi = 1.26 * t, theta = 6.28 * t;
        u = {std::sin(phi) * std::sin(theta), std::cos(phi) * std::sin(theta), std::cos(theta), irradiance};
        du = {1.26 * std::cos(phi) * std::sin(theta) + 6.28 * std::sin(phi) * std::cos(theta),
              -1.26 * std::sin(phi) * std::sin(theta) + 6.28 * std::cos(phi) * std::cos(theta), -6.28 * std::sin(theta),
              0.0};
    };
    std::array<double, 4> u{}, du{};
    inputs(0.0, u, du);
    plant.set_reals(vr, u);
    plant.enter_initialization_mode();
    plant.exit_initialization_mode();
    const double h = 1e-3;
    const long steps = std::lround(stop / h);
    for (long k = 0; k < steps; ++k) {
        const double t = static_cast<double>(k) * h;
        inputs(t, u, du);
        plant.set_reals(vr, u);
        plant.set_real_input_derivatives({vr.data(), 3}, {du.data(), 3});
        plant.do_step(t, h);
    }
    plant.terminate();
    Row r{"ssr_plant.fmu alone (CS, 1 ms, interpolated seed inputs)", stop, 0, 0, {}, steps};
    r.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
    r.cpu = cpu_seconds() - cpu0;
    return r;
}

double children_cpu_seconds() {
    rusage ru{};
    getrusage(RUSAGE_CHILDREN, &ru);
    return static_cast<double>(ru.ru_utime.tv_sec + ru.ru_stime.tv_sec) +
           1e-6 * static_cast<double>(ru.ru_utime.tv_usec + ru.ru_stime.tv_usec);
}

// CPU seconds of one shell command (its children included), or a negative value when it failed.
double child_cpu(const std::string& command) {
    const double before = children_cpu_seconds();
    const int status = std::system((command + " > /dev/null 2>&1").c_str());
    const double cpu = children_cpu_seconds() - before;
    return status == 0 ? cpu : -1.0;
}

// OMSimulator and `cosim run` on one packed archive for `stop` s; `interval` is cosim's row interval,
// which the Lua run of OMSimulator is given too.
void compare_omsimulator(const std::string& oms, const std::string& ssp, double stop, double interval) {
    const auto dir = std::filesystem::temp_directory_path() / "pvatt_system_bench_oms";
    std::filesystem::create_directories(dir);
    const std::string archive = std::string(PVATT_PACKED_DIR) + "/" + ssp;
    const auto lua = dir / "run.lua";
    {
        std::ofstream out(lua);
        out << "model = oms_importFile(\"" << archive << "\")\n"
            << "oms_setResultFile(model, \"" << (dir / "oms_rows.csv").string() << "\")\n"
            << "oms_setStopTime(model, " << stop << ")\noms_setLoggingInterval(model, " << interval << ")\n"
            << "oms_instantiate(model)\noms_initialize(model)\noms_simulate(model)\noms_terminate(model)\n"
            << "oms_delete(model)\n";
    }
    const std::string in_dir = "cd '" + dir.string() + "' && ";
    const double cosim =
        child_cpu(in_dir + "'" + PVATT_COSIM + "' run '" + archive + "' --stop-time " + std::to_string(stop) +
                  " --output-interval " + std::to_string(interval) + " --output cosim.csv");
    const double same_rows = child_cpu(in_dir + "'" + oms + "' '" + lua.string() + "'");
    const double dflt = child_cpu(in_dir + "'" + oms + "' '" + archive + "' --stopTime=" + std::to_string(stop) +
                                  " --resultFile=oms_default.csv");
    std::filesystem::remove_all(dir);  // the default result file is hundreds of MB
    std::printf("| %s, %.0f s | %.3f | %.3f | %.1f | %.3f | %.1f |\n", ssp.c_str(), stop, cosim, same_rows,
                same_rows / cosim, dflt, dflt / cosim);
}

void print(const Row& r) {
    const auto& s = r.stats;
    long events = 0;
    for (const auto& c : s.components) events += c.events;
    std::printf("| %s | %.0f | %.3f | %.3f | %.1f | %.1f | %ld | %ld | %ld | %ld | %ld | %ld |\n", r.name.c_str(),
                r.simulated, r.wall, r.cpu, r.simulated / r.wall, r.simulated / r.cpu, s.integrator_steps,
                s.rhs_evaluations, s.time_events, events, s.restarts, r.co_simulation_steps);
}

}  // namespace

int main(int argc, char** argv) {
    const bool quick = argc > 1 && std::string_view(argv[1]) == "--quick";
    const double seed_stop = quick ? 1.0 : 10.0, seed_reference_stop = quick ? 0.2 : 1.0;
    const double orbit = quick ? 600.0 : 5764.0, orbit_reference = quick ? 60.0 : 300.0;
    std::printf("load average before: %s\n\n", load_average().c_str());
    std::printf(
        "| run | simulated s | wall s | CPU s | RTF (wall) | RTF (CPU) | ME steps | RHS | time events | "
        "component events | restarts | CS steps |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    const Row plant = run_plant_alone(seed_stop);
    print(plant);
    const Row seed = run_system("seed_spin.ssd as bundled", "seed_spin.ssd", seed_stop, false);
    print(seed);
    const Row seed_ref = run_system("seed_spin.ssd, reference execution", "seed_spin.ssd", seed_reference_stop, true);
    print(seed_ref);
    const Row leo = run_system("leo_orbit.ssd as bundled", "leo_orbit.ssd", orbit, false);
    print(leo);
    const Row leo_ref = run_system("leo_orbit.ssd, reference execution", "leo_orbit.ssd", orbit_reference, true);
    print(leo_ref);
    auto rtf = [](const Row& r, bool cpu) { return r.simulated / (cpu ? r.cpu : r.wall); };
    // What the orbit's parts cost: each one switched back to its every-evaluation form, or off.
    const Row leo_albedo_every = run_system("leo_orbit.ssd, albedo integrated at every evaluation", "leo_orbit.ssd",
                                            orbit, false, {"env.albedo_interval=0"});
    print(leo_albedo_every);
    const Row leo_no_albedo =
        run_system("leo_orbit.ssd, no albedo", "leo_orbit.ssd", orbit, false, {"env.albedo_enabled=false"});
    print(leo_no_albedo);
    const Row leo_spin = run_system("leo_orbit.ssd with the spin-rate FFT (est.spin_window=512)", "leo_orbit.ssd",
                                    orbit, false, {"est.spin_window=512"});
    print(leo_spin);
    // A campaign's per-run overhead: loading and initializing a system (a run of zero length) against a run.
    const Row leo_setup = run_system("leo_orbit.ssd, load and initialize only", "leo_orbit.ssd", 1e-3, false);
    print(leo_setup);
    std::printf("\nload average after: %s\n\n", load_average().c_str());
    std::printf(
        "aim 1: seed_spin RTF %.1f (wall) / %.1f (CPU), aim >= 30; over the plant alone %.2f (wall) / %.2f (CPU), aim "
        ">= 0.6\n",
        rtf(seed, false), rtf(seed, true), rtf(seed, false) / rtf(plant, false), rtf(seed, true) / rtf(plant, true));
    std::printf("aim 2: leo_orbit RTF %.0f (wall) / %.0f (CPU), aim >= 3000\n", rtf(leo, false), rtf(leo, true));
    std::printf(
        "leo_orbit CPU ratios to as bundled: albedo every evaluation %.2f, no albedo %.2f, with the spin FFT "
        "%.2f; load and initialize %.1f %% of one orbit\n",
        leo_albedo_every.cpu / leo.cpu, leo_no_albedo.cpu / leo.cpu, leo_spin.cpu / leo.cpu,
        100.0 * leo_setup.cpu / leo.cpu);
    std::printf("speed-up over the reference execution: seed %.1fx, orbit %.1fx (CPU)\n",
                rtf(seed, true) / rtf(seed_ref, true), rtf(leo, true) / rtf(leo_ref, true));
    if (const char* oms = std::getenv("PVATT_OMSIMULATOR"); oms && *oms) {
        std::printf(
            "\n| packed archive | cosim run CPU s | OMSimulator, same rows, CPU s | ratio | OMSimulator, default "
            "output, CPU s | ratio |\n|---|---|---|---|---|---|\n");
        compare_omsimulator(oms, "seed_spin.ssp", seed_stop, 0.01);
        compare_omsimulator(oms, "leo_orbit.ssp", quick ? 60.0 : 600.0, 10.0);
    }
}
