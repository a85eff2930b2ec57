// One run of a campaign spec through the campaign library itself (its draws, settings and metrics), its metric
// cells by column name: for the end-to-end tests that hold a bundled campaign's runs.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include "campaign_run.hpp"
#include "campaign_spec.hpp"
#include "metric_observer.hpp"
#include "results_table.hpp"

namespace e2e {

// One run of `spec` with the --set `settings`: its metric cells by column name. Numbers only: a detection metric
// also gives text cells (the words declared), which read as NaN here.
inline std::map<std::string, double> run_spec(const campaign::CampaignSpec& spec, long index,
                                              const std::vector<std::string>& settings) {
    const campaign::CampaignSetup setup = campaign::prepare(spec, {PVATT_FMU_DIR}, settings);
    const campaign::RunResult r = campaign::run_one(setup, index);
    EXPECT_EQ(r.status, "ok") << r.message;
    const std::vector<std::string> names = campaign::metric_columns(spec);
    std::map<std::string, double> cells;
    for (std::size_t i = 0; i < names.size() && i < r.metric_cells.size(); ++i) {
        const std::string& text = r.metric_cells[i];
        char* end = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        cells[names[i]] = !text.empty() && end == text.c_str() + text.size() ? value : std::nan("");
    }
    return cells;
}

// An angle metric (quaternion_angle or vector_angle) between the column groups a and b, sampled while `valid` is
// true ("" = always).
inline campaign::Metric angle_metric(const std::string& name, campaign::MetricKind kind, const std::string& a,
                                     const std::string& b, const std::string& valid,
                                     const std::vector<std::string>& stats) {
    campaign::Metric m;
    m.name = name;
    m.kind = kind;
    m.a = a;
    m.b = b;
    m.valid = valid;
    m.stats = stats;
    return m;
}

}  // namespace e2e
