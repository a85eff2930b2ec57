// What the fault-detection end-to-end tests share (e2e_fault_detection_test.cpp, e2e_panel_faults_test.cpp,
// e2e_mag_faults_test.cpp): the bundled leo_orbit run with the on-board fault detection on and recorded
// every second, the filter's attitude error at the recorded points, and a word at the run's last point.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "analysis/angle_error.hpp"
#include "engine/system_description.hpp"
#include "recorder.hpp"

namespace e2e {

// leo_orbit as bundled (the 3U under its disturbance torques, docs/design.md "The spacecraft") with `settings`
// and est.detect_faults, to stop_time, rows every 1 s.
inline Recorder run_leo_detecting(const std::vector<std::string>& settings, double stop_time,
                                  const std::vector<std::string>& columns) {
    cosim::SystemOptions options;
    options.fmu_dirs = {PVATT_FMU_DIR};
    options.settings = settings;
    options.settings.push_back("est.detect_faults=true");
    cosim::System system(cosim::read_system_description(PVATT_SYSTEMS_DIR "/leo_orbit.ssd"), options);
    cosim::ExecutionOptions ex;
    ex.stop_time = stop_time;
    ex.output_interval = 1.0;
    Recorder recorder(system, columns);
    cosim::Execution(system, ex).run({&recorder});
    return recorder;
}

// The filter's attitude error (deg, env.q_true against est.q_filt) at each recorded point i that keep(i)
// accepts (the columns env.q_true[1..4] and est.q_filt[1..4] recorded).
template <class Keep>
std::vector<double> filter_errors(const Recorder& r, Keep keep) {
    std::vector<double> e;
    for (std::size_t i = 0; i < r.time.size(); ++i) {
        if (!keep(i)) continue;
        double q_true[4], q_filt[4];
        for (int k = 0; k < 4; ++k) {
            const std::string s = "[" + std::to_string(k + 1) + "]";
            q_true[k] = r["env.q_true" + s][i];
            q_filt[k] = r["est.q_filt" + s][i];
        }
        e.push_back(analysis::attitude_error_degrees(q_true, q_filt));
    }
    return e;
}

// The 95th percentile (the sample at rank 0.95 (n − 1), rounded down); NaN for none.
inline double p95(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? NAN : v[static_cast<std::size_t>(0.95 * static_cast<double>(v.size() - 1))];
}

// Element k (from 1) of an array output at the run's last point (fault words are latched: it holds them all).
inline double last(const Recorder& r, const std::string& name, int k) {
    return r[name + "[" + std::to_string(k) + "]"].back();
}

}  // namespace e2e
