// The spec reader: what it accepts, and that every mistake is an error naming its place.
#include <gtest/gtest.h>

#include <algorithm>

#include "campaign_error.hpp"
#include "campaign_spec.hpp"
#include "spec_texts.hpp"

using campaign::CampaignError;
using campaign::parse_spec;

namespace {

const std::string head = "system = \"sys.ssd\"\nruns = 4\nseed = 1\n";

using campaign_test::error_of;

}  // namespace

TEST(Spec, ReadsEveryKind) {
    const auto spec = parse_spec(head + R"(
stop_time = 60
paired = true
fmu_dirs = ["fmus"]
[set]
"est.sample_period" = 1
"plant.fidelity" = "averaged"
"env.albedo_enabled" = false
[[draw]]
kind = "uniform"
target = "a.x"
min = -1.5
max = 2
[[draw]]
kind = "normal"
target = "a.y"
mean = 0
sd = 0.1
max = 0.2
[[draw]]
kind = "choice"
target = "est.sun_method"
values = ["difference", "cones"]
weights = [1, 3]
[[draw]]
kind = "list"
target = "a.z"
values = [1, 2.5]
[[draw]]
kind = "quaternion"
target = "env.q0"
[[draw]]
kind = "tumble"
target = "env.omega0"
min = 0.01
max = 0.1
[[draw]]
kind = "epoch"
target = "env.epoch"
from = 2026-01-01
to = 2026-01-02T12:00:00+02:00
[[metric]]
name = "err"
kind = "quaternion_angle"
a = "env.q_true"
b = "est.q_est"
valid = "est.valid"
stats = ["p99.9", "mean"]
)",
                                 "/specs/test.toml");
    EXPECT_EQ(spec.system, "/specs/sys.ssd");
    EXPECT_EQ(spec.fmu_dirs.at(0), "/specs/fmus");
    EXPECT_EQ(spec.output, "test_results");
    EXPECT_EQ(*spec.stop_time, 60.0);
    EXPECT_TRUE(spec.paired);
    // A TOML table has no order: [set] comes out sorted by name (no variable can appear twice in it).
    EXPECT_EQ(spec.settings,
              (std::vector<std::string>{"env.albedo_enabled=false", "est.sample_period=1", "plant.fidelity=averaged"}));
    ASSERT_EQ(spec.draws.size(), 7u);
    EXPECT_EQ(spec.draws[0].min, -1.5);
    EXPECT_FALSE(spec.draws[1].truncated_below);
    EXPECT_TRUE(spec.draws[1].truncated_above);
    EXPECT_EQ(spec.draws[2].weights, (std::vector<double>{1, 3}));
    EXPECT_EQ(spec.draws[3].kind, campaign::DrawKind::grid);
    EXPECT_EQ(spec.draws[3].values[1].text, "2.5");
    // 2026-01-01 is day 20454 since 1970-01-01 (56 years, 14 of them leap: 56 * 365 + 14);
    // 12:00 at +02:00 is 10:00 UTC.
    EXPECT_EQ(spec.draws[6].epoch_from, 20454.0 * 86400.0);
    EXPECT_EQ(spec.draws[6].epoch_to, 20455.0 * 86400.0 + 10.0 * 3600.0);
    EXPECT_EQ(spec.metrics[0].stats, (std::vector<std::string>{"p99.9", "mean"}));
    EXPECT_EQ(spec.metrics[0].figure_stat, "p99.9");
}

TEST(Spec, MistakesAreErrorsWithTheirPlace) {
    EXPECT_NE(error_of(head + "sed = 3\n").find("unknown key 'sed'"), std::string::npos);
    // The line of the [[draw]] at fault.
    EXPECT_NE(error_of(head + "[[draw]]\nkind = \"uniform\"\ntarget = \"a.x\"\nmin = 1\nmax = 0\n")
                  .find("test.toml:4: draw 1: 'max' must be above 'min'"),
              std::string::npos);
    EXPECT_NE(error_of(head + "[[draw]]\nkind = \"gauss\"\ntarget = \"a.x\"\n").find("unknown kind 'gauss'"),
              std::string::npos);
    EXPECT_NE(error_of(head + "[[draw]]\nkind = \"uniform\"\ntarget = \"a.\"\nmin = 0\nmax = 1\n")
                  .find("not component.variable"),
              std::string::npos);
    EXPECT_NE(error_of(head + "[[draw]]\nkind = \"uniform\"\ntarget = \"x y\"\nmin = 0\nmax = 1\n")
                  .find("not component.variable"),
              std::string::npos);
    // [4, 5] sd 1 around 0: Phi(5) - Phi(4) = 3.2e-5, below the 1e-3 limit.
    EXPECT_NE(error_of(head + "[[draw]]\nkind = \"normal\"\ntarget = \"a.x\"\nmean = 0\nsd = 1\nmin = 4\nmax = 5\n")
                  .find("truncation interval"),
              std::string::npos);
    EXPECT_NE(
        error_of(
            head +
            "[[draw]]\nkind = \"quaternion\"\ntarget = \"a.q\"\n[[draw]]\nkind = \"quaternion\"\ntarget = \"a.q\"\n")
            .find("drawn twice"),
        std::string::npos);
    EXPECT_NE(error_of(head + "[[metric]]\nname = \"e\"\nkind = \"column\"\ncolumn = \"a.x\"\nstats = [\"p200\"]\n")
                  .find("unknown statistic 'p200'"),
              std::string::npos);
    EXPECT_NE(error_of("system = \"s.ssd\"\nruns = 0\nseed = 1\n").find("'runs' must be an integer"),
              std::string::npos);
    EXPECT_NE(error_of("runs = 3\nseed = 1\n").find("'system' is missing"), std::string::npos);
    EXPECT_NE(
        error_of(head + "[[draw]]\nkind = \"epoch\"\ntarget = \"env.epoch\"\nfrom = 2026-01-02\nto = 2026-01-01\n")
            .find("'to' must be after"),
        std::string::npos);
    EXPECT_NE(error_of(head + "x = [").find("test.toml:4"), std::string::npos);  // a TOML syntax error, with its line
}

// Draws whose arithmetic would leave the doubles (issue 24): refused in the spec, not drawn as inf.
TEST(Spec, DrawsThatOverflowAreRefused) {
    EXPECT_NE(error_of(head + "[[draw]]\nkind = \"uniform\"\ntarget = \"a.x\"\nmin = -1e308\nmax = 1e308\n")
                  .find("overflows a double"),
              std::string::npos);
    EXPECT_NE(error_of(head + "[[draw]]\nkind = \"tumble\"\ntarget = \"a.w\"\nmin = 0\nmax = 1.7e308\n" +
                       "[[draw]]\nkind = \"uniform\"\ntarget = \"a.y\"\nmin = -1.7e308\nmax = 1.7e308\n")
                  .find("overflows a double"),
              std::string::npos);
    EXPECT_NE(error_of(head + "[[draw]]\nkind = \"normal\"\ntarget = \"a.x\"\nmean = 0\nsd = 1e307\n")
                  .find("beyond the range of a double"),
              std::string::npos);
    EXPECT_NE(
        error_of(head + "[[draw]]\nkind = \"choice\"\ntarget = \"a.x\"\nvalues = [1, 2]\nweights = [1e308, 1e308]\n")
            .find("overflows a double"),
        std::string::npos);
}

// A metric's condition splits it by a regime (sunlit, eclipse; issue 31): "column OP number".
TEST(Spec, AMetricConditionIsAColumnAComparisonAndANumber) {
    const std::string metric = R"(
[[metric]]
name = "e"
kind = "quaternion_angle"
a = "env.q_true"
b = "est.q_filt"
)";
    const auto spec = parse_spec(head + metric + "condition = \"env.irradiance >= 1e-3\"\n", "/specs/test.toml");
    ASSERT_EQ(spec.metrics.size(), 1u);
    EXPECT_EQ(spec.metrics[0].condition_column, "env.irradiance");
    EXPECT_EQ(spec.metrics[0].condition_op, ">=");
    EXPECT_EQ(spec.metrics[0].condition_value, 1e-3);
    for (const char* bad : {"env.irradiance > sunny", "env.irradiance => 0", "env.irradiance", "irradiance > 0",
                            "env.irradiance > 0 and more"})
        EXPECT_NE(error_of(head + metric + "condition = \"" + bad + "\"\n").find("'condition'"), std::string::npos)
            << bad;
}

// after_first (issue 39): the same grammar as a condition, on a metric that is not a detection.
TEST(Spec, AMetricsAfterFirstIsAColumnAComparisonAndANumber) {
    const std::string metric = R"(
[[metric]]
name = "b"
kind = "column"
column = "est.attitude_bound"
after = 600.0
)";
    const auto spec = parse_spec(head + metric + "after_first = \"env.irradiance > 0\"\n", "/specs/test.toml");
    ASSERT_EQ(spec.metrics.size(), 1u);
    EXPECT_EQ(spec.metrics[0].start_column, "env.irradiance");
    EXPECT_EQ(spec.metrics[0].start_op, ">");
    EXPECT_EQ(spec.metrics[0].start_value, 0.0);
    EXPECT_EQ(spec.metrics[0].after, 600.0);
    for (const char* bad : {"env.irradiance > sunny", "env.irradiance", "irradiance > 0"})
        EXPECT_NE(error_of(head + metric + "after_first = \"" + bad + "\"\n").find("'after_first'"), std::string::npos)
            << bad;
}

// Issue 39: the filter's consistency as a metric, by its covariance factor; its keys checked like the others'.
TEST(Spec, ANormalizedErrorMetricNamesTheTruthTheEstimateAndTheCovarianceFactor) {
    const std::string metric = R"(
[[metric]]
name = "consistency"
kind = "normalized_error"
a = "env.q_true"
b = "est.q_filt"
)";
    const auto spec = parse_spec(head + metric + "covariance = \"est.attitude_cov_sqrt\"\n", "/specs/test.toml");
    ASSERT_EQ(spec.metrics.size(), 1u);
    EXPECT_EQ(spec.metrics[0].kind, campaign::MetricKind::normalized_error);
    EXPECT_EQ(spec.metrics[0].covariance, "est.attitude_cov_sqrt");
    EXPECT_EQ(spec.metrics[0].stats, (std::vector<std::string>{"per_dof", "chi2_99", "count"}));
    EXPECT_NE(error_of(head + metric).find("'covariance'"), std::string::npos) << error_of(head + metric);
    const std::string angle = R"(
[[metric]]
name = "e"
kind = "quaternion_angle"
a = "env.q_true"
b = "est.q_filt"
covariance = "est.attitude_cov_sqrt"
)";
    EXPECT_NE(error_of(head + angle).find("'covariance' belongs to kind normalized_error"), std::string::npos);
}

// Parameter sets (.ssv) for every run, relative to the spec, and system parameters (no '.') in [set].
TEST(Spec, ParameterFilesAndSystemParametersInSet) {
    const auto spec = parse_spec(head + R"(
parameters = ["orbits/iss_like.ssv", "/abs/date.ssv"]
[set]
epoch_month = 9
"tle_elements[2]" = 15.5
"est.sample_period" = 1
)",
                                 "/specs/test.toml");
    ASSERT_EQ(spec.parameter_files.size(), 2u);
    EXPECT_EQ(spec.parameter_files[0], "/specs/orbits/iss_like.ssv");
    EXPECT_EQ(spec.parameter_files[1], "/abs/date.ssv");
    ASSERT_EQ(spec.settings.size(), 3u);
    const auto has = [&](const std::string& s) {
        return std::find(spec.settings.begin(), spec.settings.end(), s) != spec.settings.end();
    };
    EXPECT_TRUE(has("epoch_month=9"));
    EXPECT_TRUE(has("tle_elements[2]=15.5"));
    EXPECT_TRUE(has("est.sample_period=1"));
    EXPECT_NE(error_of(head + "parameters = \"one.ssv\"\n").find("'parameters' must be an array"), std::string::npos);
    EXPECT_NE(error_of(head + "parameters = [1]\n").find("each of 'parameters'"), std::string::npos);
    EXPECT_NE(error_of(head + "[set]\n\"a b\" = 1\n").find("is not component.variable"), std::string::npos);
}
