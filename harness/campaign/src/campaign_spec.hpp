// A campaign as plain data: the system, the run count and seed, fixed settings, the quantities drawn
// per run and the metrics measured in each run. Read from a TOML file (README.md of this folder
// describes every key); every unknown key, wrong type or impossible range is an error naming the file,
// the entry and the cause, so a typo never silently leaves a quantity undrawn.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace campaign {

enum class DrawKind { uniform, normal, integer, choice, grid, quaternion, tumble, epoch, orbit };

// The orbit classes an `orbit` draw gives (orbit/orbit_classes.hpp).
enum class OrbitClass { sun_synchronous, iss_like, polar, low_inclination };

// A scalar value as the spec gives it: a number keeps its text for --set, a string is a string.
// The orbit draw's altitude range (m): orbit/orbit_classes.hpp's kMinOrbitAltitudeKm, kMaxOrbitAltitudeKm.
inline constexpr double orbit_min_altitude = 150e3;
inline constexpr double orbit_max_altitude = 2000e3;

struct SpecValue {
    std::string text;      // what is passed to the FMU ("0.5", "cones", "true")
    bool numeric = false;  // a TOML integer or float (plotted as a number)
    double number = 0.0;
};

struct Draw {
    DrawKind kind = DrawKind::uniform;
    std::string target;           // "component.variable" or, for quaternion/tumble/epoch, the variable prefix
    double min = 0.0, max = 0.0;  // uniform, integer (inclusive), tumble rate; normal truncation
    double mean = 0.0, sd = 0.0;  // normal
    bool truncated_below = false, truncated_above = false;  // normal
    std::vector<SpecValue> values;                          // choice, grid
    std::vector<double> weights;                            // choice (empty: equal)
    double epoch_from = 0.0, epoch_to = 0.0;                // epoch: seconds since 1970-01-01T00:00:00 UTC
    // epoch: the scenario moved with the date. `clocks`: prefixes of other _year.._second parameters set to
    // the same instant (the on-board clock); `element_sets`: element-set arrays ([1..8], orbit::TleElements)
    // re-epoched to it along SGP4's secular rates, from the system's set (base_elements, read by prepare()).
    std::vector<std::string> clocks, element_sets;
    // orbit: the classes drawn from (equally likely), the mean altitude range (m), the sun-synchronous
    // class's local time of the ascending node range (h); `target` and `copies` the element-set arrays that
    // receive the set. Its epoch is the epoch draw's instant, else the system's set's (base_elements).
    std::vector<OrbitClass> orbit_classes;
    double altitude_min = 0.0, altitude_max = 0.0, ltan_min = 0.0, ltan_max = 24.0;
    std::vector<std::string> copies;
    // The scenario's element set before the draws (epoch: element_sets[0]'s; orbit: target's), filled from
    // the system by read_scenario_base() (draws.hpp); empty until then.
    std::vector<double> base_elements;
    bool figure = true;  // draw the metrics against it (false for a noise seed)
    // The name its generator is seeded from (default: the target): draws of different targets that name
    // one stream draw the same numbers in a scene (a fault's onset shared by every case).
    std::string stream;
};

enum class MetricKind { quaternion_angle, vector_angle, column, detection, normalized_error };

// The cells of a detection metric, in table order (README.md of this folder says what each holds).
inline const std::vector<std::string> detection_cells = {"detected", "time",   "isolated", "declared",
                                                         "before",   "orbits", "which"};
// ... and after them in a spec where a case has an `observable`: when it first held after the onset (s after
// the onset) and the time to detect from then.
inline const std::vector<std::string> observable_cells = {"observable", "time_observable"};

struct Metric {
    std::string name;
    MetricKind kind = MetricKind::column;
    std::string a, b;  // angle metrics: the two column groups' prefixes; column: a is the column
    // normalized_error: a the true attitude's [1..4] prefix, b the estimate's, covariance the prefix of the
    // [1..6] lower Cholesky factor of its attitude covariance (L11, L21, L22, L31, L32, L33); each sample is
    // the 3-dof normalized error dtheta' inv(P) dtheta (analysis/derived_signals.hpp).
    std::string covariance;
    std::string valid;   // sample only while this column is true / nonzero ("" = always)
    std::string when;    // sample only where this column changed since the last output point
    double after = 0.0;  // ignore output points before this time (s)
    // sample only where `condition_column condition_op condition_value` holds ("env.irradiance > 0": sunlit;
    // "env.irradiance == 0": eclipse); empty column = always. Ops: <, <=, >, >=, ==, !=.
    std::string condition_column, condition_op;
    double condition_value = 0.0;
    // `after` counted from the first output point where `start_column start_op start_value` holds rather
    // than from 0 (after_first = "env.irradiance > 0": from the first sunlight; issue 39's 10 minutes for a
    // run that starts in eclipse, where the filter has no second vector); empty column = from 0. A run where
    // it never holds samples nothing.
    std::string start_column, start_op;
    double start_value = 0.0;
    std::vector<std::string> stats;  // mean, rms, min, max, final, count, pNN, per_dof, chi2_99
    std::string figure_stat;         // the per-run value plotted against the drawn quantities
    // detection: the fault words (each a column, or the prefix of a [1..n] group), the declaration times
    // beside them (same shapes; empty = the output point where the word became nonzero), the period a
    // declaration rate is given per (an orbit, s), and the summary's "within N s" of the onset.
    std::vector<std::string> words, times;
    double period = 0.0, within = 0.0;
};

// A detection metric of a spec where a case has an `observable` carries observable_cells after its own.
inline bool reports_observable(const Metric& m) {
    return m.kind == MetricKind::detection && m.stats.size() > detection_cells.size();
}

// What a case expects a detection metric to declare: the elements of the word group `words`, given by
// a variable of the run (its value is the element; 0: none) or listed.
struct Expectation {
    std::string words;
    std::string variable;        // "" when listed
    std::vector<long> elements;  // listed, 1-based
};

// When a case's fault can first be seen (the judge's truth, not the detector's): the first output point from
// the onset on where `column` is above (or below) `threshold`. The column may name variables in braces,
// "env.sun_face[{plant.fault_string_open_face}]": each is replaced by its value in the run (an integer), read
// at the first output point.
struct Observable {
    std::string column;                  // "" = none
    std::vector<std::string> variables;  // the names in braces, in order
    bool above = true;
    double threshold = 0.0;
};

// The observable's column with its {variables} replaced by `values`, in order (one per variable).
std::string observable_column(const Observable& o, const std::vector<std::string>& values);

// One of the named alternatives a campaign cycles through (a fault type, or the no-fault control): its
// own fixed settings and draws, and what its detection metrics are to find.
struct Case {
    std::string name;
    bool control = false;               // the paired reference of every other case (at most one)
    std::vector<std::string> settings;  // after the spec's [set], before the draws
    std::vector<Draw> draws;
    std::string onset;  // the variable holding the fault's onset (s), "" = none
    std::vector<Expectation> expect;
    Observable observable;  // detection metrics also count from it (README.md of this folder)
};

// What every run should reach ([[aim]]: aims.hpp judges them): a column of the results table (a metric's
// name.stat, or a measure.* column) below a bound, at least a bound, or within a range.
enum class AimKind { below, at_least, within };
struct Aim {
    std::string column;
    AimKind kind = AimKind::below;
    double low = 0.0, high = 0.0;  // below: value < high; at_least: value >= low; within: low <= value <= high
    bool skip_empty = false;       // a run with no value (no sample) is not judged by it, rather than missing it
};

struct CampaignSpec {
    std::filesystem::path file;
    std::filesystem::path system;     // .ssd, resolved against the spec's folder
    std::optional<double> stop_time;  // default: the .ssd's DefaultExperiment stopTime
    std::optional<double> output_interval, tolerance;
    long runs = 0;
    std::uint64_t seed = 0;
    bool paired = false;  // random draws per scene: every grid combination sees the same scenes
    std::vector<std::filesystem::path> fmu_dirs;
    std::filesystem::path output;  // default: "<spec name>_results" in the working directory
    // Parameter sets (.ssv) of every run, resolved against the spec's folder: after the system's own values,
    // before [set] (later files win); names are system parameters or component.variable.
    std::vector<std::filesystem::path> parameter_files;
    std::vector<std::string>
        settings;  // "component.variable=value" or "name=value" (a system parameter), before the draws
    std::vector<Draw> draws;
    std::vector<Metric> metrics;
    std::vector<Case> cases;  // empty: every run alike
    std::vector<Aim> aims;
    // What the system declares it reached (<ex:Measures>, analysis/run_measures.hpp), set by prepare():
    // each run records it and its table and summary get the measure columns (analysis::measure_columns).
    bool measures = false;
    std::vector<std::string> measure_report;
    std::optional<double> measures_converged_after;
};

// Limits, named in the errors that enforce them.
inline constexpr long max_runs = 100'000'000;
// The largest spec read (1 MiB: the bundled specs are about 2 kB).
inline constexpr std::uintmax_t max_spec_bytes = std::uintmax_t{1} << 20;
inline constexpr double min_truncated_normal_mass = 1e-3;  // rejection sampling stays cheap

CampaignSpec read_spec(const std::filesystem::path& file);
// The same from text (tests); `file` only names the source in errors and anchors relative paths.
CampaignSpec parse_spec(const std::string& text, const std::filesystem::path& file);

}  // namespace campaign
