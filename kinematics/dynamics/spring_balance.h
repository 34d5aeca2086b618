#pragma once
// Spring balancing: the linear spring between two given points that makes the crank's driving
// torque smallest over a turn, in the RMS sense (a gravity-loaded arm, a boom, a lid). With the
// spring's tension F = k L − c (c = k L0 − preload) and L' = dL/dθ, the spring adds F L' to the
// torque the crank needs (virtual work, virtual_work.h), so over the turn
//   T(θ) = T0(θ) + k L L' − c L',
// linear in k and c: the RMS of T is least where the 2×2 normal equations of that least-squares
// problem hold (integrals by the trapezoidal rule over the turn's samples). T0 and L, L' come
// from the pose alone (L' from the velocities per unit crank rate). The spring is written with
// the free length c/k and no preload, or, where c/k would be negative, with free length 0 and
// the preload −c (a zero-length spring). A spring that only raises the RMS (k ≤ 0) is refused.

#include "kinematics/dynamics/mass_properties.h"
#include "kinematics/model/mechanism.h"
#include "kinematics/model/result.h"
#include "kinematics/solve/sweep.h"

#include <vector>

namespace linkwright::kinematics {

struct SpringBalance {
  Spring spring;                     ///< the spring found (stiffness, free length, preload)
  LinkageDynamics balanced;          ///< the dynamics with the spring among the loads
  std::vector<double> angle;         ///< rad, the turn's samples
  std::vector<double> torqueBefore;  ///< N·m
  std::vector<double> torqueAfter;   ///< N·m
  double rmsBefore = 0.0;            ///< N·m
  double rmsAfter = 0.0;             ///< N·m
};

/// The spring `name` from `first` to `second` (as in Spring) that minimises the RMS driving
/// torque over `turn` (one full turn of a crank at constant ω, as machine_duty.h's). Errors:
/// the turn's and the ends' (checkDynamics with the spring), or "spring" when no spring between
/// these points lowers the RMS.
Result<SpringBalance> balanceBySpring(const Mechanism& mechanism, const LinkageDynamics& dynamics,
                                      const SweepSpec& turn, const SpringEnd& first, const SpringEnd& second,
                                      const std::string& name = "balance");

/// The least-squares spring of the comment above for one placement: its L (m) and L' (m/rad)
/// and the torque T0 (N·m) at the turn's samples `angle` (rad). `sized` is false when the
/// spring's length barely changes over the turn.
struct SpringFit {
  bool sized = false;
  double stiffness = 0.0;  ///< k, N/m
  double pull = 0.0;       ///< c = k L0 − preload, N
  double rms = 0.0;        ///< N·m, the RMS torque with that spring
};
SpringFit fitSpring(const std::vector<double>& angle, const std::vector<double>& t0, const std::vector<double>& length,
                    const std::vector<double>& slope);

/// The RMS over the turn of `torque` sampled at `angle` (trapezoidal rule).
double rmsOverTurn(const std::vector<double>& angle, const std::vector<double>& torque);

}  // namespace linkwright::kinematics
