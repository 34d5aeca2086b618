#pragma once
// The input domain: the range of every number a user can give Linkwright, and the checks
// that every entrance applies (the core's builders and checks, the document reader, the CLI,
// and the GUI, whose edits go through the core). Each check returns an Error that names the
// field, the value and the accepted range.
//
// Why these ranges (docs/document_format.md, "Input domain", has the table):
// - Lengths and coordinates, in the linkage's own unit: lengths in [1e-6, 1e9], coordinates,
//   offsets and angles within ±1e9, and a linkage's largest dimension at most 1e6 times its
//   shortest link. tests/kinematics/stability_test.cpp measures full accuracy over that span:
//   links from 1e-6 (length ratios to 1e6) to 1.5e8 (the LS3 engine scaled by 1e6), positions
//   to 1e-15 of the longest link. The arithmetic is scale-free, so the absolute ends only keep
//   products away from overflow and underflow; the ratio is what accuracy needs: past 1e6
//   nothing has been measured, and at the far ends of the double range the branch tracker's
//   step halving (down to 1e-7 rad) meets distances that round to nothing and the sweep crawls.
// - Crank speed |ω| ≤ 1e6 rad/s (9.5 million rpm) and |α| ≤ 1e12 rad/s² = (1e6 rad/s)²: the
//   rates scale exactly with ω and ω² (the suite measures 1e-15 relative at 1e5 rad/s), so
//   the bound is set by what the numbers feed: accelerations reach L·(ω² + |α|) ≤ 2e21.
// - Dynamics, SI: masses ≤ 1e9 kg, inertias ≤ 1e27 kg·m² (1e9 kg at 1e9 m), forces ≤ 1e24 N,
//   torques ≤ 1e33 N·m, gravity ≤ 1e6 m/s². With every input at its bound the largest
//   derived number, a joint moment m·L²·(ω² + |α|) ≈ 2e39 N·m, and the squares the solver
//   and the force magnitudes form (≤ 1e79) stay more than 1e220 below DBL_MAX (1.8e308), so
//   no output can overflow, whatever the combination.
// - A sweep has at most 1e7 samples (about 3 GB of columns for a four-bar: a millidegree grid
//   over 28 turns), and its angles stay within ±1e6 degrees.

#include "kinematics/model/result.h"

#include <optional>
#include <string>

namespace linkwright::kinematics {

inline constexpr double kMinLength = 1e-6;      ///< shortest length, the linkage's unit
inline constexpr double kMaxLength = 1e9;       ///< longest length and largest |coordinate|
inline constexpr double kMaxLengthRatio = 1e6;  ///< largest dimension over the shortest link
inline constexpr double kMaxOmega = 1e6;        ///< |ω|, rad/s
inline constexpr double kMaxAlpha = 1e12;       ///< |α|, rad/s²
inline constexpr double kMaxAngleDeg = 1e6;     ///< |sweep angle|, degrees
inline constexpr long long kMaxSamples = 10'000'000;
inline constexpr double kMaxMass = 1e9;      ///< kg
inline constexpr double kMaxInertia = 1e27;  ///< kg·m²
inline constexpr double kMaxForce = 1e24;    ///< N
inline constexpr double kMaxTorque = 1e33;   ///< N·m
inline constexpr double kMaxGravity = 1e6;   ///< m/s²
inline constexpr double kMaxTime = 1e6;      ///< |t| of a time base, s (11.6 days)

/// Error unless `value` is finite and within ±kMaxLength: a coordinate, an offset, a point's
/// place on a link, an angle.
std::optional<Error> checkCoordinate(double value, const std::string& field);

/// Error unless `value` is a length in [kMinLength, kMaxLength] (`what` names it in the
/// message: "crank length must be …").
std::optional<Error> checkLength(double value, const std::string& field, const std::string& what = "length");

/// Error unless `value` is finite and |value| ≤ `max`; `unit` follows the bound in the
/// message ("omega must be finite and within ±1e6 rad/s (got 1e+160)").
std::optional<Error> checkMagnitude(double value, const std::string& field, double max, const std::string& unit);
/// As checkMagnitude, for a value the core computed from what was typed (a law's peak, its
/// angle at an instant), never printed as nan or inf as if typed: "FIELD would be 1e+13, beyond
/// ±1e12 rad/s²", or, where it overflows, "FIELD overflows for these inputs (beyond …)".
std::optional<Error> checkComputedMagnitude(double value, const std::string& field, double max,
                                            const std::string& unit);

/// Error unless `value` is finite, ≥ 0 and ≤ `max` (masses, inertias).
std::optional<Error> checkNonNegative(double value, const std::string& field, double max, const std::string& unit);

/// Error (field "lengths") unless `largest` ≤ kMaxLengthRatio · `shortest`; the message names
/// both dimensions.
std::optional<Error> checkScale(double shortest, const std::string& shortestName, double largest,
                                const std::string& largestName, const std::string& unit);

}  // namespace linkwright::kinematics
