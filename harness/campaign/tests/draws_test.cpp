// Draws: reproducible from (seed, run index) alone, independent of one another, and distributed as
// their spec says (checked with moments and Kolmogorov-Smirnov distances against closed forms).
#include <gtest/gtest.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <functional>
#include <map>
#include <numbers>

#include <optional>

#include "campaign_error.hpp"
#include "campaign_spec.hpp"
#include "draws.hpp"
#include "engine/value_text.hpp"

using campaign::CampaignSpec;
using campaign::draw_run;
using campaign::parse_spec;

namespace {

constexpr long samples = 20000;
// KS critical distance at the 0.1 % level: 1.95 / sqrt(n).
const double ks_limit = 1.95 / std::sqrt(static_cast<double>(samples));

CampaignSpec spec_of(const std::string& draws, const std::string& extra = "") {
    return parse_spec("system = \"s.ssd\"\nruns = 20000\nseed = 99\n" + extra + draws, "/t/spec.toml");
}

double number(const std::string& text) {
    double x = 0.0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), x);
    EXPECT_TRUE(ec == std::errc() && end == text.data() + text.size()) << text;
    return x;
}

// Largest distance between the empirical CDF of `x` and `cdf`.
double ks_distance(std::vector<double> x, const std::function<double(double)>& cdf) {
    std::sort(x.begin(), x.end());
    double d = 0.0;
    const double n = static_cast<double>(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) {
        const double f = cdf(x[i]);
        d = std::max({d, std::abs(f - static_cast<double>(i) / n), std::abs(static_cast<double>(i + 1) / n - f)});
    }
    return d;
}

}  // namespace

TEST(Draws, ReproducibleAndIndependentOfOtherDraws) {
    const auto one = spec_of("[[draw]]\nkind = \"uniform\"\ntarget = \"a.x\"\nmin = 0\nmax = 1\n");
    const auto two = spec_of(
        "[[draw]]\nkind = \"quaternion\"\ntarget = \"a.q\"\n[[draw]]\nkind = \"uniform\"\ntarget = \"a.x\"\nmin = "
        "0\nmax = 1\n");
    EXPECT_EQ(draw_run(one, 17).cells, draw_run(one, 17).cells);
    EXPECT_NE(draw_run(one, 17).cells, draw_run(one, 18).cells);
    // Adding a draw before it changes nothing of a.x.
    EXPECT_EQ(draw_run(one, 17).cells.at(0), draw_run(two, 17).cells.at(4));
    EXPECT_EQ(draw_run(one, 17).settings.at(0), "a.x=" + draw_run(one, 17).cells.at(0));
    // Another base seed, other values.
    auto other = one;
    other.seed = 100;
    EXPECT_NE(draw_run(one, 17).cells, draw_run(other, 17).cells);
}

// Table columns: quaternion and rate components are not plotted, the rate magnitude and epoch days
// are, and `figure = false` leaves a drawn quantity out of the figures.
TEST(Draws, ColumnsAndWhichArePlotted) {
    const auto spec = spec_of(
        "[[draw]]\nkind = \"quaternion\"\ntarget = \"e.q0\"\n[[draw]]\nkind = \"tumble\"\ntarget = \"e.w0\"\nmin = "
        "0\nmax = 1\n"
        "[[draw]]\nkind = \"epoch\"\ntarget = \"e.epoch\"\nfrom = 2026-01-01\nto = 2026-02-01\n"
        "[[draw]]\nkind = \"integer\"\ntarget = \"m.seed\"\nmin = 1\nmax = 9\nfigure = false\n");
    std::string names, plotted;
    for (const auto& c : campaign::draw_columns(spec)) {
        names += c.name + " ";
        if (c.plotted) plotted += c.name + " ";
    }
    EXPECT_EQ(names, "e.q0[1] e.q0[2] e.q0[3] e.q0[4] e.w0[1] e.w0[2] e.w0[3] e.w0.rate e.epoch e.epoch.days m.seed ");
    EXPECT_EQ(plotted, "e.w0.rate e.epoch.days ");
    EXPECT_EQ(draw_run(spec, 0).cells.size(), 11u);
}

// Uniform on [a, b): mean (a + b)/2 with standard error (b - a)/sqrt(12 n); KS against (x - a)/(b - a).
TEST(Draws, UniformCoversItsInterval) {
    const auto spec = spec_of("[[draw]]\nkind = \"uniform\"\ntarget = \"a.x\"\nmin = -2\nmax = 3\n");
    std::vector<double> x;
    for (long i = 0; i < samples; ++i) x.push_back(number(draw_run(spec, i).cells[0]));
    double mean = 0.0;
    for (double v : x) {
        ASSERT_GE(v, -2.0);
        ASSERT_LE(v, 3.0);
        mean += v / samples;
    }
    EXPECT_NEAR(mean, 0.5, 5.0 * 5.0 / std::sqrt(12.0 * samples));
    EXPECT_LT(ks_distance(x, [](double v) { return (v + 2.0) / 5.0; }), ks_limit);
}

// Normal(1, 2) truncated to [0, 6]: every value inside; KS against the truncated CDF
// (Phi((x - 1)/2) - Phi(-1/2)) / (Phi(5/2) - Phi(-1/2)).
TEST(Draws, TruncatedNormalFollowsItsDistribution) {
    const auto spec = spec_of("[[draw]]\nkind = \"normal\"\ntarget = \"a.x\"\nmean = 1\nsd = 2\nmin = 0\nmax = 6\n");
    auto phi = [](double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); };
    std::vector<double> x;
    for (long i = 0; i < samples; ++i) {
        x.push_back(number(draw_run(spec, i).cells[0]));
        ASSERT_GE(x.back(), 0.0);
        ASSERT_LE(x.back(), 6.0);
    }
    EXPECT_LT(ks_distance(x, [&](double v) { return (phi((v - 1.0) / 2.0) - phi(-0.5)) / (phi(2.5) - phi(-0.5)); }),
              ks_limit);
}

TEST(Draws, IntegerAndChoiceFrequencies) {
    const auto spec = spec_of(
        "[[draw]]\nkind = \"integer\"\ntarget = \"a.n\"\nmin = 3\nmax = 5\n"
        "[[draw]]\nkind = \"choice\"\ntarget = \"a.c\"\nvalues = [\"x\", \"y\", \"z\"]\nweights = [1, 0, 3]\n");
    std::map<std::string, long> n, c;
    for (long i = 0; i < samples; ++i) {
        const auto cells = draw_run(spec, i).cells;
        ++n[cells[0]];
        ++c[cells[1]];
    }
    ASSERT_EQ(n.size(), 3u);  // 3, 4 and 5, nothing else
    for (const char* k : {"3", "4", "5"})
        EXPECT_NEAR(n[k] / double(samples), 1.0 / 3.0, 5.0 * std::sqrt(2.0 / 9.0 / samples)) << k;
    EXPECT_EQ(c.count("y"), 0u);  // weight 0: never
    EXPECT_NEAR(c["z"] / double(samples), 0.75, 5.0 * std::sqrt(0.75 * 0.25 / samples));
}

// Two grid axes of 2 and 3 values: runs 0..5 walk the product, the first axis fastest, then repeat.
TEST(Draws, GridWalksTheProductAndPairedScenesShareRandomDraws) {
    const auto spec = spec_of(
        "[[draw]]\nkind = \"grid\"\ntarget = \"a.g\"\nvalues = [\"p\", \"q\"]\n"
        "[[draw]]\nkind = \"list\"\ntarget = \"a.h\"\nvalues = [1, 2, 3]\n"
        "[[draw]]\nkind = \"uniform\"\ntarget = \"a.x\"\nmin = 0\nmax = 1\n",
        "paired = true\n");
    const char* expected[][2] = {{"p", "1"}, {"q", "1"}, {"p", "2"}, {"q", "2"}, {"p", "3"}, {"q", "3"}, {"p", "1"}};
    for (long i = 0; i < 7; ++i) {
        const auto cells = draw_run(spec, i).cells;
        EXPECT_EQ(cells[0], expected[i][0]) << i;
        EXPECT_EQ(cells[1], expected[i][1]) << i;
    }
    // Paired: runs 0..5 are scene 0 (the same random value), run 6 starts scene 1.
    for (long i = 1; i < 6; ++i) EXPECT_EQ(draw_run(spec, i).cells[2], draw_run(spec, 0).cells[2]);
    EXPECT_NE(draw_run(spec, 6).cells[2], draw_run(spec, 0).cells[2]);
    auto unpaired = spec;
    unpaired.paired = false;
    EXPECT_NE(draw_run(unpaired, 1).cells[2], draw_run(unpaired, 0).cells[2]);
}

// Uniform rotations: unit quaternions whose rotation angle theta = 2 acos|w| has the Haar density
// (1 - cos theta)/pi on [0, pi], CDF (theta - sin theta)/pi; and every axis equally likely (the x
// component's square has mean 1/4 by symmetry).
TEST(Draws, QuaternionsAreUniformRotations) {
    const auto spec = spec_of("[[draw]]\nkind = \"quaternion\"\ntarget = \"env.q0\"\n");
    EXPECT_EQ(draw_run(spec, 0).settings.at(3).rfind("env.q0[4]=", 0), 0u);
    std::vector<double> angle;
    double x2 = 0.0;
    for (long i = 0; i < samples; ++i) {
        const auto c = draw_run(spec, i).cells;
        const double q[4] = {number(c[0]), number(c[1]), number(c[2]), number(c[3])};
        ASSERT_NEAR(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3], 1.0, 1e-12);
        angle.push_back(2.0 * std::acos(std::min(1.0, std::abs(q[3]))));
        x2 += q[0] * q[0] / samples;
    }
    EXPECT_LT(ks_distance(angle, [](double t) { return (t - std::sin(t)) / std::numbers::pi; }), ks_limit);
    // Var(x^2) for a uniform point on S^3: E x^4 - (E x^2)^2 = 1/8 - 1/16 = 1/16.
    EXPECT_NEAR(x2, 0.25, 5.0 * 0.25 / std::sqrt(double(samples)));
}

// Tumble: |w| uniform in [0.02, 0.1] (KS), direction uniform on the sphere: w_z/|w| uniform in
// [-1, 1] (Archimedes), and the rate column equals |w|.
TEST(Draws, TumbleRatesHaveUniformDirections) {
    const auto spec = spec_of("[[draw]]\nkind = \"tumble\"\ntarget = \"env.omega0\"\nmin = 0.02\nmax = 0.1\n");
    std::vector<double> rate, z;
    for (long i = 0; i < samples; ++i) {
        const auto c = draw_run(spec, i).cells;
        ASSERT_EQ(c.size(), 4u);
        const double w[3] = {number(c[0]), number(c[1]), number(c[2])};
        const double r = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
        ASSERT_NEAR(r, number(c[3]), 1e-15);
        rate.push_back(r);
        z.push_back(w[2] / r);
    }
    EXPECT_LT(ks_distance(rate, [](double r) { return (r - 0.02) / 0.08; }), ks_limit);
    EXPECT_LT(ks_distance(z, [](double v) { return (v + 1.0) / 2.0; }), ks_limit);
}

// Epochs over the 48 h from 2024-02-28T12:00Z (a leap year: 29 February lies inside): the calendar
// fields follow from the offset in days alone, worked out here without the code's calendar.
TEST(Draws, EpochsAreCalendarDatesInTheirRange) {
    const auto spec = spec_of(
        "[[draw]]\nkind = \"epoch\"\ntarget = \"env.epoch\"\nfrom = 2024-02-28T12:00:00Z\nto = 2024-03-01T12:00:00Z\n");
    std::vector<double> days;
    for (long i = 0; i < 2000; ++i) {
        const auto d = draw_run(spec, i);
        ASSERT_EQ(d.settings.size(), 6u);
        const double offset = number(d.cells[1]);
        ASSERT_GE(offset, 0.0);
        ASSERT_LT(offset, 2.0);
        days.push_back(offset);
        const double hours = 12.0 + offset * 24.0;  // since 2024-02-28T00:00Z
        const int day_index = static_cast<int>(hours / 24.0);
        const char* dates[] = {"env.epoch_day=28", "env.epoch_day=29", "env.epoch_day=1"};
        EXPECT_EQ(d.settings[0], "env.epoch_year=2024");
        EXPECT_EQ(d.settings[1], day_index == 2 ? "env.epoch_month=3" : "env.epoch_month=2");
        EXPECT_EQ(d.settings[2], dates[day_index]);
        EXPECT_EQ(d.settings[3], "env.epoch_hour=" + std::to_string(static_cast<int>(hours) % 24));
        const double seconds_of_minute = std::fmod(offset * 86400.0, 60.0);
        EXPECT_NEAR(number(d.settings[5].substr(d.settings[5].find('=') + 1)), seconds_of_minute, 2e-3);
        EXPECT_EQ(d.cells[0].substr(0, 8), "2024-0" + std::string(day_index == 2 ? "3" : "2") + "-");
    }
    EXPECT_LT(ks_distance(days, [](double v) { return v / 2.0; }), 1.95 / std::sqrt(2000.0));
}

namespace {

// The bundled leo_orbit's set as the system gives it (harness/systems/leo_orbit.ssd).
const std::vector<double> kLeoSet = {2461119.5, 14.98524078, 0.0012, 64.9, 0.0, 90.0, 270.0, 1.5e-4};

std::optional<std::string> leo_values(const std::string& name) {
    for (const char* set : {"env.tle_elements[", "est.tle_elements["})
        if (name.rfind(set, 0) == 0)
            return cosim::format_real(kLeoSet.at(std::stoul(name.substr(std::string(set).size())) - 1));
    if (name.find("tle_line") != std::string::npos) return std::string();
    return std::nullopt;
}

std::map<std::string, std::string> settings_of(const campaign::RunDraws& d) {
    std::map<std::string, std::string> out;
    for (const auto& s : d.settings) out[s.substr(0, s.find('='))] = s.substr(s.find('=') + 1);
    return out;
}

double jd_of(int year, int month, int day, double hours) {
    // Meeus ch. 7, written out here (not the orbit library's) for an independent check.
    if (month <= 2) {
        year -= 1;
        month += 12;
    }
    const int a = year / 100, b = 2 - a + a / 4;
    return std::floor(365.25 * (year + 4716)) + std::floor(30.6001 * (month + 1)) + day + b - 1524.5 + hours / 24.0;
}

const char* kScenarioEpoch =
    "[[draw]]\nkind = \"epoch\"\ntarget = \"env.epoch\"\nfrom = 2026-01-01T00:00:00Z\nto = 2027-01-01T00:00:00Z\n"
    "clocks = [\"est.clock_epoch\"]\nelement_sets = [\"env.tle_elements\", \"est.tle_elements\"]\n";

}  // namespace

// #37: an epoch draw moves the whole scenario: the truth's date, the on-board clock, and both element sets
// moved to the drawn date along the secular rates (not propagated months from their epoch).
TEST(Draws, EpochMovesTheWholeScenario) {
    auto spec = spec_of(kScenarioEpoch);
    campaign::read_scenario_base(spec, leo_values);
    double largest_move = 0.0;
    for (long run = 0; run < 50; ++run) {
        const auto d = draw_run(spec, run);
        auto s = settings_of(d);
        for (const char* f : {"_year", "_month", "_day", "_hour", "_minute", "_second"})
            EXPECT_EQ(s.at(std::string("est.clock_epoch") + f), s.at(std::string("env.epoch") + f)) << f;
        const double jd = jd_of(std::stoi(s.at("env.epoch_year")), std::stoi(s.at("env.epoch_month")),
                                std::stoi(s.at("env.epoch_day")),
                                std::stoi(s.at("env.epoch_hour")) + std::stoi(s.at("env.epoch_minute")) / 60.0 +
                                    number(s.at("env.epoch_second")) / 3600.0);
        for (const char* set : {"env.tle_elements", "est.tle_elements"}) {
            auto e = [&](int k) { return number(s.at(std::string(set) + "[" + std::to_string(k) + "]")); };
            EXPECT_NEAR(e(1), jd, 1e-8);  // the set's epoch is the drawn date
            EXPECT_EQ(e(2), kLeoSet[1]);  // n, e, i, B* kept
            EXPECT_EQ(e(3), kLeoSet[2]);
            EXPECT_EQ(e(4), kLeoSet[3]);
            EXPECT_EQ(e(8), kLeoSet[7]);
            // The node turned at J2's rate, -3/2 n J2 (R/p)^2 cos i (-3.13 deg/day for 570 km at 64.9 deg;
            // SGP4's J2^2 and J4 terms add 0.1 %).
            const double pi = std::numbers::pi, n = kLeoSet[1] * 2.0 * pi / 86400.0;  // rad/s
            const double a = std::cbrt(398600.8 / (n * n)), p = a * (1.0 - kLeoSet[2] * kLeoSet[2]);
            const double rate = -1.5 * kLeoSet[1] * 360.0 * 0.001082616 * std::pow(6378.135 / p, 2) *
                                std::cos(kLeoSet[3] * pi / 180.0);  // deg/day
            const double days = jd - kLeoSet[0];
            const double expected = std::fmod(std::fmod(rate * days, 360.0) + 360.0, 360.0);
            const double off = std::abs(e(5) - expected);
            EXPECT_LT(std::min(off, 360.0 - off), 0.005 * std::abs(rate * days) + 1e-6) << days;
            largest_move = std::max(largest_move, std::abs(days));
        }
    }
    EXPECT_GT(largest_move, 100.0);  // the draws do reach months away
    // Without the base set read from the system the draw cannot move the sets.
    EXPECT_THROW(draw_run(spec_of(kScenarioEpoch), 0), campaign::CampaignError);
    // A system that gives its set as text would ignore the drawn numbers: refused.
    auto lines = spec_of(kScenarioEpoch);
    EXPECT_THROW(campaign::read_scenario_base(lines,
                                              [](const std::string& name) -> std::optional<std::string> {
                                                  if (name == "env.tle_line1") return std::string("1 90001U ...");
                                                  return leo_values(name);
                                              }),
                 campaign::CampaignError);
}

// #37: orbit classes as element sets, at the scenario's date.
TEST(Draws, OrbitClassesAsElementSets) {
    auto spec = spec_of(std::string(kScenarioEpoch).substr(0, std::string(kScenarioEpoch).find("element_sets")) +
                        "[[draw]]\nkind = \"orbit\"\ntarget = \"env.tle_elements\"\ncopies = [\"est.tle_elements\"]\n"
                        "classes = [\"sun_synchronous\", \"iss_like\", \"polar\", \"low_inclination\"]\n"
                        "min_altitude = 450e3\nmax_altitude = 650e3\nmin_ltan = 9\nmax_ltan = 11\n");
    campaign::read_scenario_base(spec, leo_values);
    std::map<std::string, int> counts;
    const double mu = 398600.8, radius = 6378.135, j2 = 0.001082616, pi = std::numbers::pi;
    for (long run = 0; run < 400; ++run) {
        const auto d = draw_run(spec, run);
        const auto s = settings_of(d);
        const std::string cls = d.cells.at(2);
        ++counts[cls];
        const double altitude = number(d.cells.at(3)), inclination = number(d.cells.at(4)),
                     ltan = number(d.cells.at(5));
        EXPECT_EQ(s.at("env.tle_elements[4]"), s.at("est.tle_elements[4]"));
        EXPECT_NEAR(number(s.at("env.tle_elements[4]")), inclination, 1e-9);
        // The set's epoch is the epoch draw's date.
        const double jd = jd_of(std::stoi(s.at("env.epoch_year")), std::stoi(s.at("env.epoch_month")),
                                std::stoi(s.at("env.epoch_day")),
                                std::stoi(s.at("env.epoch_hour")) + std::stoi(s.at("env.epoch_minute")) / 60.0 +
                                    number(s.at("env.epoch_second")) / 3600.0);
        EXPECT_NEAR(number(s.at("env.tle_elements[1]")), jd, 1e-8);
        if (cls == "iss_like") {
            EXPECT_EQ(inclination, 51.6);
            EXPECT_NEAR(altitude, 420.0, 1e-6);
        } else {
            EXPECT_GE(altitude, 450.0 - 1e-6);
            EXPECT_LE(altitude, 650.0 + 1e-6);
        }
        if (cls == "polar") {
            EXPECT_EQ(inclination, 90.0);
        }
        if (cls == "low_inclination") {
            EXPECT_EQ(inclination, 20.0);
        }
        if (cls == "sun_synchronous") {
            // J2 alone: cos i = -2 rho a^{7/2} / (3 J2 R^2 sqrt(mu)), rho the mean sun's 360 deg per 365.2422 days.
            const double a = radius + altitude, rho = 2.0 * pi / (365.2422 * 86400.0);
            EXPECT_NEAR(
                inclination,
                std::acos(-2.0 * rho * std::pow(a, 3.5) / (3.0 * j2 * radius * radius * std::sqrt(mu))) * 180 / pi,
                0.05);
            EXPECT_GE(ltan, 9.0 - 1e-9);
            EXPECT_LE(ltan, 11.0 + 1e-9);
        }
    }
    for (const char* c : {"sun_synchronous", "iss_like", "polar", "low_inclination"})
        EXPECT_GT(counts[c], 70) << c;  // 100 expected of each; 70 is 3.5 sigma below
    // The orbit draw's set must not also be re-epoched by the epoch draw.
    EXPECT_THROW(spec_of(std::string(kScenarioEpoch) +
                         "[[draw]]\nkind = \"orbit\"\ntarget = \"env.tle_elements\"\nclasses = [\"polar\"]\n"
                         "min_altitude = 450e3\nmax_altitude = 650e3\n"),
                 campaign::CampaignError);
    EXPECT_THROW(spec_of("[[draw]]\nkind = \"orbit\"\ntarget = \"env.tle_elements\"\nclasses = [\"geo\"]\n"
                         "min_altitude = 450e3\nmax_altitude = 650e3\n"),
                 campaign::CampaignError);
    EXPECT_THROW(spec_of("[[draw]]\nkind = \"orbit\"\ntarget = \"env.tle_elements\"\nclasses = [\"polar\"]\n"
                         "min_altitude = 50e3\nmax_altitude = 650e3\n"),
                 campaign::CampaignError);
}
