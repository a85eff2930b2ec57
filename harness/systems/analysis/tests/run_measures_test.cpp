// What a run reached (analysis/run_measures.hpp), on tables whose answers are known in closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include "analysis/run_measures.hpp"

namespace analysis {
namespace {

constexpr double kDeg = M_PI / 180.0;

// A filter whose error is k degrees about z at its k-th sample (k = 1 .. 4, every 10 s from t = 10), with
// an isotropic covariance of sigma = 1 deg per axis: epsilon = k^2 = 1, 4, 9, 16, so 3 of 4 samples are
// inside chi2(3)'s 99 % point 11.34 (75 %) and NEES/dof = (1 + 4 + 9 + 16) / 4 / 3 = 2.5 (overconfident).
// The 3-sigma bound 3 sqrt(tr P) = 3 sqrt(3) deg = 5.2 deg covers all four errors: it would read 100 %.
// Row 0 (t = 0): the filter running but not valid (bound 30 deg), its error not counted. Sunlit at t = 10,
// 20; eclipse at 30, 40. The calibration applies at t = 30. Face +y declared at 25 s, axis z at 35 s.
cosim::CsvTable overconfident_filter() {
    cosim::CsvTable t;
    t.names = {"time",
               "env.q_true[1]",
               "env.q_true[2]",
               "env.q_true[3]",
               "env.q_true[4]",
               "est.q_filt[1]",
               "est.q_filt[2]",
               "est.q_filt[3]",
               "est.q_filt[4]",
               "est.filter_valid",
               "est.attitude_bound",
               "env.irradiance",
               "est.mag_cal_valid"};
    for (int i = 1; i <= 6; ++i) t.names.push_back("est.attitude_cov_sqrt[" + std::to_string(i) + "]");
    for (int i = 1; i <= 6; ++i) t.names.push_back("est.fault_face_time[" + std::to_string(i) + "]");
    for (int i = 1; i <= 3; ++i) t.names.push_back("est.fault_mag_axis_time[" + std::to_string(i) + "]");
    t.columns.resize(t.names.size());
    for (int k = 0; k <= 4; ++k) {
        const double angle = (k == 0 ? 40.0 : k) * kDeg;
        const double sigma = (k == 0 ? 10.0 : 1.0) * kDeg;
        std::vector<double> row = {10.0 * k,
                                   0,
                                   0,
                                   0,
                                   1,
                                   0,
                                   0,
                                   std::sin(angle / 2),
                                   std::cos(angle / 2),
                                   k == 0 ? 0.0 : 1.0,
                                   3.0 * std::sqrt(3.0) * sigma,
                                   k <= 2 ? 1361.0 : 0.0,
                                   k >= 3 ? 1.0 : 0.0,
                                   sigma,
                                   0,
                                   sigma,
                                   0,
                                   0,
                                   sigma};
        for (int f = 0; f < 6; ++f) row.push_back(f == 2 && k >= 3 ? 25.0 : -1.0);
        for (int a = 0; a < 3; ++a) row.push_back(a == 2 && k >= 4 ? 35.0 : -1.0);
        for (std::size_t c = 0; c < row.size(); ++c) t.columns[c].push_back(row[c]);
    }
    return t;
}

TEST(RunMeasures, ChiSquareCoverageSeesAnOverconfidentFilterThatTheThreeSigmaBoundCovers) {
    const RunMeasures m = measure_run(overconfident_filter());
    ASSERT_EQ(m.estimates.size(), 1u);
    const auto& f = m.estimates[0];
    EXPECT_EQ(f.name, "filter q_filt");
    ASSERT_TRUE(f.overall.consistency);
    EXPECT_EQ(f.overall.consistency->samples, 4u);
    EXPECT_NEAR(f.overall.consistency->nees_per_dof, 2.5, 1e-9);
    EXPECT_NEAR(f.overall.consistency->chi2_coverage, 75.0, 1e-9);
    // Per phase, nearest rank: sunlit {1, 2} deg, eclipse {3, 4} deg.
    EXPECT_TRUE(m.phases);
    EXPECT_EQ(f.overall.sunlit.samples, 2u);
    EXPECT_NEAR(f.overall.sunlit.median, 2.0, 1e-9);
    EXPECT_NEAR(f.overall.eclipse.median, 4.0, 1e-9);
    EXPECT_NEAR(f.overall.all.p95, 4.0, 1e-9);
    // Converged: valid with the calibration applied, from t = 30 (eclipse samples 3 and 4 deg).
    ASSERT_TRUE(m.converged_from);
    EXPECT_EQ(*m.converged_from, 30.0);
    ASSERT_TRUE(f.converged);
    EXPECT_EQ(f.converged->all.samples, 2u);
    EXPECT_EQ(f.converged->sunlit.samples, 0u);
    EXPECT_NEAR(f.converged->consistency->chi2_coverage, 50.0, 1e-9);
    ASSERT_TRUE(f.first_valid);
    EXPECT_EQ(*f.first_valid, 10.0);
    EXPECT_NE(m.not_valid_reason.find("not valid until 10 s"), std::string::npos) << m.not_valid_reason;
    EXPECT_NE(m.not_valid_reason.find("52°"), std::string::npos) << m.not_valid_reason;  // 3 sqrt(3) 10 deg
    EXPECT_NE(m.not_valid_reason.find("calibration applied at 30 s"), std::string::npos) << m.not_valid_reason;
    ASSERT_EQ(m.declarations.size(), 2u);
    EXPECT_EQ(m.declarations[0].what, "panel face +y");
    EXPECT_EQ(m.declarations[0].time, 25.0);
    EXPECT_EQ(m.declarations[1].what, "magnetometer axis z");
}

TEST(RunMeasures, EndOfRunTextSaysEachPhaseTheCoverageAndTheFaults) {
    std::ostringstream out;
    print_measures(measure_run(overconfident_filter()), {{"mag", "stuck", "fault_stuck_axis = 3", 33.0}}, {}, out);
    const std::string s = out.str();
    EXPECT_NE(s.find("filter q_filt, whole run: sunlit 2° / 2° (2), eclipse 4° / 4° (2); NEES/dof 2.5, χ²(3) 99 % "
                     "coverage 75.0 %"),
              std::string::npos)
        << s;
    EXPECT_NE(s.find("fault injected: mag stuck (fault_stuck_axis = 3) from 33 s"), std::string::npos) << s;
    EXPECT_NE(s.find("fault declared: magnetometer axis z at 35 s"), std::string::npos) << s;
    // Each declaration after an onset says how long it took (the latest onset at or before it).
    EXPECT_NE(s.find("fault declared: magnetometer axis z at 35 s, 2 s after the onset of mag stuck"),
              std::string::npos)
        << s;
    EXPECT_NE(s.find("fault declared: panel face +y at 25 s\n"), std::string::npos) << s;  // before any onset
    // Only what the system asks for.
    std::ostringstream faults_only;
    print_measures(measure_run(overconfident_filter()), {}, {"faults"}, faults_only);
    EXPECT_EQ(faults_only.str().find("attitude error"), std::string::npos) << faults_only.str();
    EXPECT_NE(faults_only.str().find("panel face +y at 25 s"), std::string::npos);
}

// A CSV written by `cosim run` holds each injected fault's onset as a column: the same lines come from it.
TEST(RunMeasures, OnsetColumnsOfACsvGiveTheSameFaultLines) {
    auto t = overconfident_filter();
    t.names.push_back("mag.fault_stuck_onset");
    t.columns.push_back(std::vector<double>(t.rows(), 33.0));
    const RunMeasures m = measure_run(t);
    ASSERT_EQ(m.injected.size(), 1u);
    EXPECT_EQ(m.injected[0].component, "mag");
    EXPECT_EQ(m.injected[0].group, "stuck");
    EXPECT_EQ(m.injected[0].onset, 33.0);
    EXPECT_EQ(onset_columns(m.injected), std::vector<std::string>{"mag.fault_stuck_onset"});
    const auto lines = fault_lines(m);
    ASSERT_EQ(lines.size(), 3u);
    EXPECT_EQ(lines[0], "fault injected: mag stuck from 33 s");
    EXPECT_EQ(lines[1], "fault declared: panel face +y at 25 s");
    EXPECT_EQ(lines[2], "fault declared: magnetometer axis z at 35 s, 2 s after the onset of mag stuck");
}

TEST(RunMeasures, UnknownMeasureNameRefusedWithTheClosest) {
    try {
        check_measure_names({"attitude", "consistncy"}, "x.ssd");
        FAIL();
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find("did you mean 'consistency'"), std::string::npos) << e.what();
    }
}

TEST(RunMeasures, NoTruthNothingToSay) {
    cosim::CsvTable t;
    t.names = {"time", "plant.v_bus"};
    t.columns = {{0, 1}, {12, 12}};
    std::ostringstream out;
    print_measures(measure_run(t), out);
    EXPECT_EQ(out.str(), "");
}

}  // namespace
}  // namespace analysis
