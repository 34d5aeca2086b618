#pragma once
// What a user designs and saves: a four-bar (lengths, unit, branch, optional coupler point),
// how it is driven and the angle grid it is analysed on. The GUI edits one of these, the
// document file stores one, and buildMechanism / designSweepSpec turn it into solver input,
// so the GUI, the CLI and the files all mean the same linkage.

#include "kinematics/design/examples.h"
#include "kinematics/dynamics/mass_properties.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/result.h"
#include "kinematics/solve/sweep.h"

#include <optional>
#include <string>

namespace linkwright::kinematics {

struct FourBarDesign {
  FourBarLengths lengths{60.0, 25.0, 70.0, 45.0};
  std::string lengthUnit = "mm";
  Branch branch = Branch::Open;
  std::optional<CouplerPointSpec> couplerPoint;
  double omega = 1.0;         ///< crank, rad/s (CCW positive)
  double alpha = 0.0;         ///< crank, rad/s²
  double fromDeg = 0.0;       ///< analysis grid start, degrees
  double toDeg = 360.0;       ///< analysis grid end, degrees
  std::size_t samples = 721;  ///< grid points from fromDeg to toDeg inclusive (≥ 2)
  LinkageDynamics dynamics;   ///< masses and loads for forces (links "crank", "coupler", "rocker"); empty: none
  bool operator==(const FourBarDesign&) const = default;
};

/// Error naming the first invalid field ("lengths.coupler", "omega", "samples",
/// "dynamics.links[0].mass", ...).
std::optional<Error> checkDesign(const FourBarDesign& design);

/// The driver and grid rules every design shares: finite ω, α and angles, toDeg > fromDeg,
/// 2 ≤ samples ≤ 10 000 000. Fields "omega", "alpha", "fromDeg", "toDeg", "samples".
std::optional<Error> checkDriveAndGrid(double omega, double alpha, double fromDeg, double toDeg, std::size_t samples);

/// checkDynamics with "dynamics." before the field and the message.
std::optional<Error> checkDesignDynamics(const Mechanism& mechanism, const LinkageDynamics& dynamics);

/// Grid points every 0.5° from fromDeg to toDeg inclusive: how examples become designs.
std::size_t samplesEveryHalfDegree(double fromDeg, double toDeg);

/// The solver's mechanism for a valid design.
Result<Mechanism> buildMechanism(const FourBarDesign& design);

/// The design's analysis grid at its crank speed.
SweepSpec designSweepSpec(const FourBarDesign& design);

/// A built-in example as a design, sampled every 0.5° over its range.
FourBarDesign designFromExample(const FourBarExample& example);

}  // namespace linkwright::kinematics
