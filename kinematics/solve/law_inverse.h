#pragma once
// When a driver following a motion law (motion_law.h) is at a given position: the inverse of
// the law over a time base. The designer needs it to put a crank angle on a time axis (a
// rocker's limit positions), to move a timed crank to an angle (the angle slider, a drag), and
// to say when a driven point is where (a path's stretch outside an arm's reach). The law is
// sampled at evenly spaced instants and each crossing is refined by bisection on the law
// itself, so an instant is exact to round-off wherever the law is monotonic between two
// samples (every closed-form law is; a table between its rows, sampled finely enough).
//
// A crank's angle repeats every turn, so its positions are compared modulo `period` = 2π; a
// linear driver's (period 0) are compared as they are.

#include "kinematics/solve/sweep.h"

#include <cstddef>
#include <vector>

namespace linkwright::kinematics {

/// Intervals the time base is cut into to find crossings: fine enough that no closed-form law
/// turns back within one, cheap enough to run on every edit.
inline constexpr std::size_t kCrossingIntervals = 1024;

/// The instants in [time.fromTime, time.toTime], in time order, at which the law's position is
/// `q` (plus a whole number of `period`s when period > 0), at most `most` of them (the
/// earliest). Each is refined by bisection to the resolution of double.
std::vector<double> timesAtPosition(const TimeBase& time, double q, std::size_t most, double period = 0.0,
                                    std::size_t intervals = kCrossingIntervals);

/// The instant nearest `near` (s) at which the law is at `q` (any period); if it never is,
/// the sampled instant at which it comes nearest.
double timeNearestPosition(const TimeBase& time, double q, double near, double period = 0.0);

/// How far the law moves the driver over the time base (≥ 0): the sum of the position's
/// changes between the sampled instants.
double lawTravel(const TimeBase& time, std::size_t intervals = kCrossingIntervals);

}  // namespace linkwright::kinematics
