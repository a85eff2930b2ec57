// Physical facts two blocks of this project must agree on, checked before a run (issue 31).
//
// The on-board computer (attitude_estimator) stands for flight software: it may not read the truth,
// so its beliefs about the spacecraft are parameters, as an uplink would give them. A connection from
// the environment would hand it the truth; a check here keeps the parameters and refuses a system in
// which they contradict the blocks they describe:
//   - est.angular_response is the panels' response the computer inverts: it must be the plant's
//     angular_response (and the environment's albedo_response, the response the albedo is weighed with,
//     when albedo is on);
//   - with reference_source = inputs, est.orbit_altitude sizes the Earth the cones method's albedo model
//     sees (the estimator's sphere of 6371 km): its orbit radius must be the truth's mean orbit radius (the
//     environment's circular altitude above 6378.137 km, or SGP4's mean semi-major axis of its element set)
//     within max_orbit_radius_difference. With reference_source = onboard the computer takes it from its
//     own element set, and its uplink is checked instead:
//   - its clock at t = 0 (clock_epoch_* + clock_offset) against the truth's epoch (env.epoch_*) within
//     max_clock_difference;
//   - its element set (tle_line1/2 or tle_elements, made uplink_age older) against the truth's: the epochs
//     within max_uplink_age_days, and SGP4's positions at t = 0 (each set at its own block's clock) within
//     max_orbit_position_difference (the same satellite in the same orbit).
// Components are recognized by their FMU's model identifier; a system without the blocks is not checked.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <ostream>

#include "engine/system.hpp"

namespace analysis {

// 20 km: the bundled orbit's radius swings +-8 km about its mean (eccentricity 0.0012); 20 km of
// altitude move the cones' Earth disc by 0.4 deg at 570 km.
inline constexpr double max_orbit_radius_difference = 20e3;  // m
// 10 s: a small satellite's clock without GPS drifts by seconds per day; 10 s move the computer's orbit by
// 75 km along the track, its field reference by about 0.5 deg. A larger clock_offset is a study: run it
// with --allow-mismatch.
inline constexpr double max_clock_difference = 10.0;  // s
// 7 days: an uplinked set is refreshed every day or few; a week-old LEO set is tens of kilometres off.
inline constexpr double max_uplink_age_days = 7.0;
// 100 km at t = 0: a day-old set is a few km off; 100 km (0.8 deg along a 7000 km orbit) is another orbit
// or satellite, not an old set of this one.
inline constexpr double max_orbit_position_difference = 100e3;  // m

// The period (s) of the truth's orbit: SGP4's period of the environment's element set (what the
// environment's orbit_period gives), or Kepler's for its circular orbit; nullopt without an environment.
std::optional<double> truth_orbit_period(const cosim::System& system);

// The stop time a run takes without --stop-time: the .ssd's <Stop orbits="N"/> times the truth's orbit
// period (derived, not written), else its stopTime; nullopt when it gives neither. Throws CosimError when
// the .ssd asks for orbits of a system with no orbit to derive them from.
std::optional<double> default_stop_time(const cosim::System& system);

// One line per contradiction found ("est.angular_response cosine but plant.angular_response kelly: ...").
std::vector<std::string> coupling_mismatches(const cosim::System& system);

// Refuses (CosimError listing every contradiction) unless `allow`, then writes them to `warn` instead.
void check_couplings(const cosim::System& system, bool allow, std::ostream& warn);

}  // namespace analysis
