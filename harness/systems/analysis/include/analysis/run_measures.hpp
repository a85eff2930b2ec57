// What a run of the bundled systems reached, said at once (issue 40): for every attitude estimate the run
// holds (the single-frame q_est, the filter q_filt) its error against the truth at its own samples while
// valid, overall and split sunlit / eclipse, over the whole run and after convergence; for the filter its
// normalized error ε = δθᵀ P⁻¹ δθ (from its Cholesky factor attitude_cov_sqrt) per degree of freedom and
// its χ²(3) 99 % coverage (the share of samples with ε below 11.34, 99 % for a consistent filter: the
// 3√(tr P) bound covers 99.9994 % of a consistent filter's errors and reads 100 % for an overconfident one
// as well, issue 39); when the filter first became valid and what it was waiting for; and every fault the
// on-board computer declared (its fault_*_time outputs).
//
// Computed from a table of columns named `component.variable` (a results CSV read back, or the columns a
// run recorded in memory: MeasureRecorder), so `cosim run`, `cosim plot`, the tests and Python (through
// the C API) print the same numbers from one definition. Rows are taken where the estimate changed (the
// on-board computer took a sample) while it is valid, as the figures take them.
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "engine/csv_table.hpp"
#include "engine/observer.hpp"

namespace analysis {

// χ²(3) at 99 %: P(ε ≤ 11.3449) = 0.99 for ε the sum of three squared unit normals (the 3-dof normalized
// error of a consistent filter). scipy.stats.chi2.ppf(0.99, 3) = 11.344866730144373.
inline constexpr double chi2_3dof_99 = 11.344866730144373;

// The p-quantile of v (0 <= p <= 1) by the nearest rank (no interpolation); NaN for an empty v. The one
// definition of the figures' legends, the results page, the end of a run and pvatt.analysis.
double error_percentile(std::vector<double> v, double p);

// The median and 95th percentile of an error (degrees) over some samples; NaN when there are none.
struct ErrorStats {
    std::size_t samples = 0;
    double median = 0.0, p95 = 0.0;
};

// The filter's covariance against its error over some samples: mean ε / 3 and the share (%) with ε ≤ 11.34.
struct Consistency {
    std::size_t samples = 0;
    double nees_per_dof = 0.0, chi2_coverage = 0.0;
};

// One span of the run (the whole run, or after convergence) of one estimate.
struct SpanMeasures {
    ErrorStats all, sunlit, eclipse;
    std::optional<Consistency> consistency;  // the filter only (when the CSV holds its covariance factor)
};

struct EstimateMeasures {
    std::string name;  // "filter q_filt", "single-frame q_est"
    std::string key;   // "filter", "single_frame", "sun_vector": its columns' names (measure_columns)
    SpanMeasures overall;
    std::optional<SpanMeasures> converged;  // after `converged_from`, when that is inside the run
    std::optional<double> first_valid;      // the first sample it was valid at (s)
};

// A fault the on-board computer declared: "face +y (word 1) declared at 1234.5 s".
struct FaultDeclaration {
    std::string what;
    double time = 0.0;
};

// A fault injected through a block's parameters (fault_onsets below, or a CSV's onset columns).
struct FaultOnset {
    std::string component, group;  // "mag", "stuck"
    std::string settings;          // "fault_stuck_axis = 2" (empty when read from a CSV's onset column)
    double onset = 0.0;
};

struct RunMeasures {
    std::vector<EstimateMeasures> estimates;
    // The measured sun vector (sun_meas, unit, body axes) against the truth's (sun_body) at the on-board
    // computer's samples while sun_valid: the angle between them (deg); no consistency.
    std::vector<EstimateMeasures> sun_vectors;
    // Where "after convergence" starts (s): the .ssd's declaration, else when the filter was valid with the
    // in-flight magnetometer calibration applied (both columns present), else nothing.
    std::optional<double> converged_from;
    std::string converged_because;
    // Why the filter was not valid from the start: its 3σ bound at its first sample and when it came down.
    std::string not_valid_reason;
    std::vector<FaultDeclaration> declarations;
    std::vector<FaultOnset> injected;  // from the table's onset columns (onset_columns), by onset
    bool phases = false;               // the table had an irradiance column: sunlit and eclipse are split
};

struct MeasureOptions {
    // "After convergence" from this time (s) on, as the system declares it (<ex:Measures convergedAfter>).
    std::optional<double> converged_after;
};

// Empty `estimates` when the table holds no truth with an estimate (a system that is not one of these).
RunMeasures measure_run(const cosim::CsvTable& table, const MeasureOptions& options = {});

// The end of `cosim run`: a few lines, nothing when there is nothing to say.
void print_measures(const RunMeasures& m, std::ostream& out);

// The same as one JSON object (numbers null where NaN), for pvatt.analysis through the C API:
// {"estimates": [{"name", "first_valid", "overall": SPAN, "converged": SPAN|null}], "sun_vectors": [the same],
//  "converged_from",
//  "converged_because", "not_valid_reason", "phases", "declarations": [{"what", "time"}], "injected": [{"component", "group", "onset"}]} with SPAN
// {"all"|"sunlit"|"eclipse": {"samples", "median", "p95"}, "consistency": {"samples", "nees_per_dof",
//  "chi2_coverage"}|null}.
std::string measures_json(const RunMeasures& m);

// The same as HTML tables for the results page.
std::string measures_html(const RunMeasures& m);

// What a system's <ex:Measures report=".."/> may name: what the end of a run prints.
//   attitude     the error of each estimate, sunlit / eclipse (median, p95), whole run and after convergence
//   consistency  the filter's NEES/dof and chi2(3) 99 % coverage beside its errors
//   first_valid  when each estimate was first valid, and why the filter was not valid before
//   faults       the faults injected (the blocks' fault_* parameters) and those the on-board computer declared
//   sun_vector   the error of the measured sun vector (sun_meas against sun_body), median and p95 as attitude
inline const std::vector<std::string> measure_names = {"attitude", "consistency", "first_valid", "faults",
                                                       "sun_vector"};

// The declared measures as numbers, one column each, for a campaign's results table and summary: named
// "measure.<estimate>.<span>.<phase>.<stat>" (estimate filter, single_frame or sun_vector; span run or
// converged; phase all, sunlit or eclipse; stat p50 or p95), "measure.filter.<span>.nees_per_dof" and
// ".chi2_99" (consistency), "measure.<estimate>.first_valid" (first_valid). The columns depend on `report`
// alone (all when empty; faults has none: a campaign measures them with its detection metrics), so that
// every run of a campaign has the same; measure_values gives a run's, NaN where it has none.
std::vector<std::string> measure_columns(const std::vector<std::string>& report);
std::vector<double> measure_values(const RunMeasures& m, const std::vector<std::string>& report);

// Throws CosimError naming a report item that is not one of measure_names (with the closest one).
void check_measure_names(const std::vector<std::string>& report, const std::string& where);

// A fault injected through a block's parameters: group G of `component` is injected when a parameter
// fault_G_* other than its onset and end differs from the FMU's start value; its onset is fault_G_onset.
// Read from the values the run gives (System::initial_value: its bindings, parameter files, --set), so
// before the run as well as after it.
std::vector<FaultOnset> fault_onsets(const cosim::System& system);

// The columns `cosim run` adds to its CSV for the faults it injects ("mag.fault_stuck_onset"), so that the
// CSV alone gives `cosim plot` (measure_run) each onset.
std::vector<std::string> onset_columns(const std::vector<FaultOnset>& injected);

// The faults of a run, one line each, the one text of the end of `cosim run` and of the results page:
// "fault injected: mag stuck (fault_stuck_axis = 2) from 3000 s", "fault declared: magnetometer axis y
// (fault word 4) at 3012.5 s, 12.5 s after the onset of mag stuck" (the latest onset at or before it),
// "no fault declared by the on-board computer" when faults were injected and none declared.
std::vector<std::string> fault_lines(const RunMeasures& m);

// The end of `cosim run` for a system that declares its measures: the items of `report` only (all but
// sun_vector when empty), faults injected (`injected`, with their settings, in place of m.injected) beside those declared.
void print_measures(const RunMeasures& m, const std::vector<FaultOnset>& injected,
                    const std::vector<std::string>& report, std::ostream& out);

// Records, at every output point, only the columns measure_run reads (every other output is left out, so
// that a long run without a CSV costs a few columns of memory): the truth q_true, the estimates and their
// validity, the filter's covariance factor and bound, irradiance, the calibration flag, the fault outputs.
class MeasureRecorder : public cosim::Observer {
public:
    explicit MeasureRecorder(const cosim::System& system);
    void sample(double t, cosim::System& system) override;
    const cosim::CsvTable& table() const { return table_; }

private:
    std::vector<cosim::OutputColumn> columns_;
    cosim::CsvTable table_;
};

}  // namespace analysis
