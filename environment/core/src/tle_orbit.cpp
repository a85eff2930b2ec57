#include "environment/tle_orbit.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "environment/constants.hpp"
#include "orbit/element_plausibility.hpp"
#include "orbit/frames.hpp"

namespace environment {

namespace {
// Minutes from the set's epoch to `epoch`: the whole days between their midnights (exact in a double) and
// the two day fractions apart.
double minutes_between(const orbit::Tle& tle, const UtcDate& epoch) {
    const double env_midnight = julian_date(UtcDate{epoch.year, epoch.month, epoch.day, 0, 0, 0.0});
    const double env_fraction = (epoch.hour * 3600.0 + epoch.minute * 60.0 + epoch.second) / kSecondsPerDay;
    const double tle_whole_day = std::floor(tle.epoch_day);
    const double tle_midnight = julian_date(UtcDate{tle.epoch_year, 1, 1, 0, 0, 0.0}) + (tle_whole_day - 1.0);
    const double tle_fraction = tle.epoch_day - tle_whole_day;
    return (env_midnight - tle_midnight) * 1440.0 + (env_fraction - tle_fraction) * 1440.0;
}
}  // namespace

TleOrbit::TleOrbit(const orbit::Tle& tle, const UtcDate& epoch)
    : tle_(tle), epoch_jd_(julian_date(epoch)), minutes_offset_(minutes_between(tle, epoch)) {
    const orbit::Sgp4Status status = sgp4_.initialize(tle.mean_elements<double>());
    if (status != orbit::Sgp4Status::ok) {
        throw std::invalid_argument("TleOrbit: element set " + std::to_string(tle.catalog_number) + ": " +
                                    orbit::describe(status));
    }
    // The rule the on-board computer's set obeys too (orbit/element_plausibility.hpp): no more than a year
    // between the set and t = 0, and SGP4 still propagating there.
    const std::string problem = orbit::element_set_problem_at(tle, epoch_jd_, "the environment's epoch (t = 0)");
    if (!problem.empty()) throw std::invalid_argument("TleOrbit: " + problem);
}

TleOrbit::State TleOrbit::state_eci(double t) const {
    const double minutes = minutes_offset_ + t / 60.0;
    orbit::OrbitState<double> teme;
    const orbit::Sgp4Status status = sgp4_.propagate(minutes, teme);
    if (status != orbit::Sgp4Status::ok) {
        throw std::domain_error("TleOrbit: at t = " + std::to_string(t) + " s (" + std::to_string(minutes) +
                                " min from the element set's epoch): " + orbit::describe(status));
    }
    // The rotation's date: TT taken as UTC (69 s, < 4 mm here; frames.hpp). Interpolated between nodes (header).
    Eigen::Matrix3d m;
    frame_.evaluate(
        t,
        [this](double t_node, double* out) {
            const Eigen::Matrix3d exact =
                orbit::j2000_from_teme(orbit::julian_centuries(epoch_jd_ + t_node / kSecondsPerDay));
            Eigen::Map<Eigen::Matrix3d>{out} = exact;
        },
        m.data());
    orbit::OrbitState<double> j2000;
    j2000.position_km = m * teme.position_km;
    j2000.velocity_km_s = m * teme.velocity_km_s;
    return {j2000.position_km * 1000.0, j2000.velocity_km_s * 1000.0};
}

}  // namespace environment
