#pragma once
// Built-in examples taken from the seed documents, shared by the CLI and the GUI: each a built
// mechanism with its speed and grid. An example may carry its links' masses and loads (seed
// 004's four-bar does) for forces.

#include "kinematics/dynamics/mass_properties.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/shaper.h"
#include "kinematics/model/sixbar.h"
#include "kinematics/model/slider_crank.h"
#include "kinematics/solve/sweep.h"

#include <optional>
#include <string>
#include <vector>

namespace linkwright::kinematics {

/// A linkage from a seed or a textbook, with the speed and the angle grid its published table
/// uses.
struct Example {
  std::string name;         ///< CLI name, e.g. "thesis-crank-rocker"
  std::string description;  ///< one line: what it is and where it comes from
  std::string kind;  ///< "four-bar", "slider-crank", "shaper", "whitworth", "watt-i", …: a label, as Design::kind
  Mechanism mechanism;
  double omega = 0.0;        ///< crank, rad/s
  double alpha = 0.0;        ///< crank, rad/s²
  double fromDeg = 0.0;      ///< default table start, degrees
  double toDeg = 360.0;      ///< default table end, degrees
  double stepDeg = 1.0;      ///< default table step, degrees
  LinkageDynamics dynamics;  ///< masses and loads, if the source gives them (else empty)
  /// A time base, when the example's driver follows a motion law (the angles above are then
  /// unused), analysed at `timeSamples` instants.
  std::optional<TimeBase> time;
  std::size_t timeSamples = 0;
  bool operator==(const Example&) const = default;
};

/// Every built-in example, in display order: the seeds' four-bars first, then the
/// slider-crank, the quick returns and the six-bars.
std::vector<Example> examples();

/// The example named `name`, if there is one.
std::optional<Example> findExample(const std::string& name);

/// LS3 engine (seed 003): stroke 92 mm, connecting rod 6.098 in.
inline const SliderCrankGeometry kLs3Engine{46.0, 6.098 * 25.4, 0.0, false};
/// Seed 003's shaper: crank 100, slotted rocker 400, link 150 mm; O4 at (40, −200), guide at 220.
inline const ShaperGeometry kSeedShaper{100.0, 400.0, 150.0, Eigen::Vector2d(40.0, -200.0), 220.0};

/// A Whitworth quick return: the seed shaper's crank with the slotted link's pivot inside the
/// crank circle at (0, −40) mm, slotted link 120, link 150 mm, ram guide through the pivot.
inline const ShaperGeometry kWhitworth{100.0, 120.0, 150.0, Eigen::Vector2d(0.0, -40.0), -40.0};

/// The thesis crank-rocker (seed 000): frame 60, crank 25, coupler 70, rocker 45 mm.
inline const FourBarLengths kThesisCrankRocker{60.0, 25.0, 70.0, 45.0};

/// The six-bar examples: the thesis crank-rocker with one more dyad.
inline const FourBarLengths kSixBarBase = kThesisCrankRocker;
inline const SixBarGeometry kWattISixBar{SixBarKind::WattI,       kSixBarBase, Branch::Open, {35.0, 25.0}, {60.0, 0.0},
                                         Eigen::Vector2d::Zero(), 70.0,        55.0,         Branch::Open};
inline const SixBarGeometry kWattIISixBar{SixBarKind::WattII,           kSixBarBase, Branch::Open, {60.0, 0.0}, {},
                                          Eigen::Vector2d(110.0, 20.0), 60.0,        45.0,         Branch::Open};
inline const SixBarGeometry kStephensonISixBar{
    SixBarKind::StephensonI, kSixBarBase, Branch::Open, {-20.0, 0.0}, {30.0, -15.0},
    Eigen::Vector2d::Zero(), 100.0,       75.0,         Branch::Open};
inline const SixBarGeometry kStephensonIIISixBar{
    SixBarKind::StephensonIII,    kSixBarBase, Branch::Open, {35.0, 30.0}, {},
    Eigen::Vector2d(100.0, 60.0), 75.0,        55.0,         Branch::Open};

/// Seed 004's (Funsho) masses and inertias, as its MATLAB code has them (the code produced
/// its published figures; its Table 1 differs: coupler 0.4 kg and 0.004 kg·m², rocker centre
/// 15 mm from C): crank 0.2 kg, 1e-5 kg·m²; coupler 0.6 kg, 4e-4 kg·m²; rocker 0.4 kg,
/// 8e-5 kg·m²; every centre of mass at its link's midpoint. No gravity, no load.
LinkageDynamics funshoFourBarDynamics();

}  // namespace linkwright::kinematics
