#pragma once
// Six-bars that no order of dyads solves, built with free points (FreePoint) and distance
// constraints for the Newton solver (newton_group.h). Driven from the crank, each has a loop
// whose joints must be found at once:
//
//   Stephenson III, driven from the wrong link: ground ternary (O2, O4, O6); crank O2→B;
//     coupler B→C to a floating ternary (C, D, E); rocker4 O4→D; rocker6 O6→E. C, D and E
//     form a triad (one ternary and three binaries to known points): 6 unknowns, 6 distances.
//   Stephenson II: ground binary (pivots J0, J5) in the path of two binaries; crank J0→J1;
//     coupler ternary (J1, J2, J3); rocker ternary (J5, J4, J6) about J5; link5 J3→J4;
//     link6 J2→J6. J2, J3, J4, J6: 8 unknowns, 8 distances.
//
// The default dimensions (mm) are round numbers that assemble over the whole crank turn with
// J well conditioned throughout (smallest singular value of the row-normalized Jacobian 0.47
// and 0.35 over a turn in 0.1° steps); the guesses are the open assembly at crank angle 0,
// rounded to 1 mm. For the dyad six-bars see sixbar.h.

#include "kinematics/model/mechanism.h"
#include "kinematics/model/result.h"

#include <Eigen/Core>

#include <string>

namespace linkwright::kinematics {

/// Stephenson III driven at O2 (one length unit; O2 at the origin).
struct StephensonIIIGeometry {
  Eigen::Vector2d o4 = Eigen::Vector2d::Zero();      ///< ground pivot of rocker4
  Eigen::Vector2d o6 = Eigen::Vector2d::Zero();      ///< ground pivot of rocker6
  double crank = 0.0;                                ///< O2 to B, the driven input
  double coupler = 0.0;                              ///< B to C
  double cd = 0.0;                                   ///< C to D, a side of the floating ternary
  double ce = 0.0;                                   ///< C to E
  double de = 0.0;                                   ///< D to E
  double rocker4 = 0.0;                              ///< O4 to D
  double rocker6 = 0.0;                              ///< O6 to E
  Eigen::Vector2d guessC = Eigen::Vector2d::Zero();  ///< the assembly meant, at crank angle 0
  Eigen::Vector2d guessD = Eigen::Vector2d::Zero();
  Eigen::Vector2d guessE = Eigen::Vector2d::Zero();
  bool operator==(const StephensonIIIGeometry&) const = default;
};

/// Stephenson II driven at J0 (one length unit; J0 at the origin).
struct StephensonIIGeometry {
  Eigen::Vector2d j5 = Eigen::Vector2d::Zero();  ///< ground pivot of the rocker ternary
  double crank = 0.0;                            ///< J0 to J1, the driven input
  double j1j2 = 0.0;                             ///< sides of the coupler ternary (J1, J2, J3)
  double j1j3 = 0.0;
  double j2j3 = 0.0;
  double j5j4 = 0.0;  ///< sides of the rocker ternary (J5, J4, J6)
  double j5j6 = 0.0;
  double j4j6 = 0.0;
  double link5 = 0.0;                                 ///< J3 to J4
  double link6 = 0.0;                                 ///< J2 to J6
  Eigen::Vector2d guessJ2 = Eigen::Vector2d::Zero();  ///< the assembly meant, at crank angle 0
  Eigen::Vector2d guessJ3 = Eigen::Vector2d::Zero();
  Eigen::Vector2d guessJ4 = Eigen::Vector2d::Zero();
  Eigen::Vector2d guessJ6 = Eigen::Vector2d::Zero();
  bool operator==(const StephensonIIGeometry&) const = default;
};

/// A Stephenson III that turns fully: O4 (160, 0), O6 (40, 150), crank 25, coupler 110,
/// ternary 80/90/85, rocker4 135, rocker6 110 mm.
inline const StephensonIIIGeometry kStephensonIIINewton{{160.0, 0.0}, {40.0, 150.0}, 25.0,          110.0,
                                                        80.0,         90.0,          85.0,          135.0,
                                                        110.0,        {126.0, 43.0}, {83.0, 111.0}, {36.0, 40.0}};

/// A Stephenson II that turns fully: J5 (150, 0), crank 25, coupler ternary 95/105/45, rocker
/// ternary 85/75/50, link5 35, link6 65 mm.
inline const StephensonIIGeometry kStephensonIINewton{{150.0, 0.0}, 25.0,          95.0,         105.0,        45.0,
                                                      85.0,         75.0,          50.0,         35.0,         65.0,
                                                      {60.0, 88.0}, {102.0, 72.0}, {78.0, 46.0}, {122.0, 70.0}};

/// Fixed ids of the mechanism makeStephensonIIINewton builds.
namespace stephenson3 {
inline constexpr PointId kO2{0};
inline constexpr PointId kO4{1};
inline constexpr PointId kO6{2};
inline constexpr PointId kB{3};
inline constexpr PointId kC{4};  ///< C, D, E: free points, one Newton group
inline constexpr PointId kD{5};
inline constexpr PointId kE{6};
inline constexpr LinkId kCrank{0};    ///< O2→B
inline constexpr LinkId kCoupler{1};  ///< B→C
inline constexpr LinkId kTernary{2};  ///< C→D (E rides on it)
inline constexpr LinkId kRocker4{3};  ///< O4→D
inline constexpr LinkId kRocker6{4};  ///< O6→E
}  // namespace stephenson3

/// Fixed ids of the mechanism makeStephensonIINewton builds.
namespace stephenson2 {
inline constexpr PointId kJ0{0};
inline constexpr PointId kJ5{1};
inline constexpr PointId kJ1{2};
inline constexpr PointId kJ2{3};  ///< J2, J3, J4, J6: free points, one Newton group
inline constexpr PointId kJ3{4};
inline constexpr PointId kJ4{5};
inline constexpr PointId kJ6{6};
inline constexpr LinkId kCrank{0};    ///< J0→J1
inline constexpr LinkId kCoupler{1};  ///< J1→J2 (the ternary J1, J2, J3)
inline constexpr LinkId kRocker{2};   ///< J5→J4 (the ternary J5, J4, J6)
inline constexpr LinkId kLink5{3};    ///< J3→J4
inline constexpr LinkId kLink6{4};    ///< J2→J6
}  // namespace stephenson2

/// Builds the Stephenson III: points O2, O4, O6, B, C, D, E; links crank, coupler, ternary,
/// rocker4, rocker6; six constraints. Errors name the field ("cd", "guessE.x", …).
Result<Mechanism> makeStephensonIIINewton(const StephensonIIIGeometry& geometry = kStephensonIIINewton,
                                          const std::string& lengthUnit = "mm");

/// Builds the Stephenson II: points J0, J5, J1, J2, J3, J4, J6; links crank, coupler, rocker,
/// link5, link6; eight constraints. Errors name the field ("link5", "j5.y", …).
Result<Mechanism> makeStephensonIINewton(const StephensonIIGeometry& geometry = kStephensonIINewton,
                                         const std::string& lengthUnit = "mm");

}  // namespace linkwright::kinematics
