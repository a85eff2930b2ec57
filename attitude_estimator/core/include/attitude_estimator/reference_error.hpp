// The ground's figure for the reference field's error along the computer's own orbit (MekfConfig::mag_ref_rms),
// from what the uplink holds: the on-board field model, the computer's element set and its clock. Two parts, each
// rms per axis (docs/filter.md, "The reference's error by the orbit"):
// - the model's truncation: the degrees of IGRF-14 above the model's at the set's semi-major axis
//   (omitted_field_rms, their spectrum over the sphere): 40 nT per axis at 420 km, 28 nT at 650 km for degree 8;
// - the on-board orbit's error: a set propagated past its epoch carries the drag over its age that its mean
//   motion does not hold. SGP4 from the set with and without its B* differ by that along-track displacement
//   (for leo_orbit's sets made uplink_age older from the truth's, within 1 % of their distance from the truth's
//   orbit: 3.8 km at 420 km, 0.86 km at 570 km after 24 h), and the field the error moves is the on-board model
//   at the two positions, the rms of their difference per axis over one period from the clock's start.
// Configure time, in double but for the model's own evaluations (the caller's model, in its float type): no
// temporary larger than two SGP4 states, so the firmware's stack carries it; 2 × 72 SGP4 propagations and
// 2 × 72 field evaluations, and the turn's 3 × 3 normal equations.
#pragma once

#include <cstdint>

#include "attitude_estimator/onboard_clock.hpp"
#include "attitude_estimator/onboard_field.hpp"
#include "orbit/sgp4.hpp"

namespace attitude_estimator {

struct ReferenceFieldError {
    double truncation = 0.0;         // T per axis
    double position = 0.0;           // T per axis
    double drag_displacement = 0.0;  // m, rms over the period
    double rms = 0.0;                // T per axis, both in quadrature
    // The position part read as one turn (rad): the least-squares rotation that explains it against the on-board
    // field in inertial axes over the period. The lag turns the field pattern about the orbit's normal by about
    // twice its angle, 2 δs/r (0.062° at 420 km, 0.014° at 570 km after 24 h), and does so at every sample: what
    // the filter considers as MekfConfig::mag_ref_tilt. (The truncation's own least-squares turn over one
    // period, as large at 420 km, is another turn each orbit as the Earth turns under the track and averages over
    // a filter's memory: it is left to mag_ref_rms.)
    double turn = 0.0;
};

// All zero when SGP4 cannot propagate the set over the period from the clock's start (the caller has checked
// the set: the block's configure, the board's epoch check).
template <class T>
ReferenceFieldError reference_field_error(const FieldModel<T>& model, const CalendarInstant& clock_epoch,
                                          const orbit::MeanElements<double>& elements,
                                          double tle_epoch_julian_date) noexcept;

extern template ReferenceFieldError reference_field_error(const FieldModel<float>&, const CalendarInstant&,
                                                          const orbit::MeanElements<double>&, double) noexcept;
extern template ReferenceFieldError reference_field_error(const FieldModel<double>&, const CalendarInstant&,
                                                          const orbit::MeanElements<double>&, double) noexcept;

}  // namespace attitude_estimator
