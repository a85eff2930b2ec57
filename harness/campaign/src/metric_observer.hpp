// The metrics of one run, measured while it runs (no per-run CSV): an observer that reads the named
// columns at every output point and keeps the values each metric samples, then reduces them to the
// statistics the spec asks for. Angle metrics compare two column groups: a[1..4] with b[1..4] as
// attitudes (sign-insensitive quaternion angle), or a[1..3] with b[1..3] as directions.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "campaign_spec.hpp"
#include "detection.hpp"
#include "engine/observer.hpp"

namespace campaign {

// A metric keeps at most this many samples per run (8 bytes each); a whole orbit at 20 Hz is 115,280.
inline constexpr std::size_t max_metric_samples = 20'000'000;

// The table columns of the metrics: "name.stat" for every metric and statistic, in spec order.
std::vector<std::string> metric_columns(const CampaignSpec& spec);

class MetricObserver : public cosim::Observer {
public:
    // Throws CampaignError naming a column the system does not have or that is not numeric. `run_case`:
    // the case the run takes (its onset and expectations for the detection metrics), or none.
    MetricObserver(const std::vector<Metric>& metrics, const cosim::System& system, const Case* run_case = nullptr);
    void sample(double t, cosim::System& system) override;
    // One cell per metric_columns() entry (round-trip text; "nan" where a metric sampled nothing).
    std::vector<std::string> cells() const;

private:
    struct Column {
        std::size_t component;
        const fmi_loader::ScalarVariable* variable;
    };
    struct Tracked {
        const Metric* metric = nullptr;
        std::vector<Column> a, b;
        std::optional<Column> valid, when, condition, start;
        std::optional<double> last_when;
        std::optional<double> started;  // when `start` (the metric's after_first) first held
        std::vector<double> values;
        // detection: the words and times of every element, what the case expects (each a column whose
        // value is an element of a group, or fixed elements), read at the first output point.
        std::vector<Column> times;
        std::vector<std::size_t> group_start, group_size;
        std::vector<std::pair<std::size_t, Column>> expect_variables;  // group, column
        std::vector<std::size_t> expected;
        std::optional<DetectionTracker> detection;
        std::vector<Column> covariance;  // normalized_error: the Cholesky factor's six columns
    };
    static Column resolve(const cosim::System& system, const std::string& name, const std::string& metric);
    static double read(cosim::System& system, const Column& c);

    std::vector<Tracked> tracked_;
    std::optional<Column> onset_;
    std::optional<double> onset_value_;
    // The case's observable (Observable): its variables, its column once they are read, when it first held.
    const Case* case_ = nullptr;
    std::vector<Column> observable_variables_;
    std::optional<Column> observable_;
    std::optional<double> observable_at_;
    bool first_ = true;
};

}  // namespace campaign
