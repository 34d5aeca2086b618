#pragma once
// The driver's generalized force by virtual work: an independent check of the Newton–Euler
// solve (inverse_dynamics.h), which needs no joint reactions at all. Ideal joints do no work,
// so for a virtual motion δq of the input, with every point moving δr = v̂ δq and every body
// turning δφ = ω̂ δq (v̂, ω̂: the velocities per unit input rate, from the pose's positions),
//   Q = Σ_masses [ m (a_G − g)·v̂_G + I α ω̂ ] − Σ_torques τ ω̂ − Σ_forces F·v̂_P
//       − Σ_springs P·(v̂_1 − v̂_2)    (P the spring's pull on its first end)
// (SI; a crank's Q is its torque T in N·m). With v̂ = v/q̇ this is the power balance
// Q q̇ + loads' power + gravity's power = dE/dt; with the unit-rate velocities it also holds at
// rest (q̇ = 0), where the power balance says nothing. A link mass's centre moves as
// v_G = v_A + ω (G − A)⊥, a_G = a_A + α (G − A)⊥ − ω² (G − A) from its link's first point A; a
// slider block's mass sits at its pin and turns with the body it slides on.

#include "kinematics/dynamics/mass_properties.h"
#include "kinematics/model/mechanism.h"
#include "kinematics/model/result.h"
#include "kinematics/solve/pose.h"

namespace linkwright::kinematics {

/// The terms of the virtual work at a pose, each per unit input rate (W per unit q̇), and the
/// sum of their sizes (the scale a difference is measured against).
struct VirtualWork {
  double inertial = 0.0;  ///< Σ m a_G·v̂_G + I α ω̂
  double gravity = 0.0;   ///< Σ m g·v̂_G
  double loads = 0.0;     ///< Σ τ ω̂ + Σ F·v̂_P + Σ P·(v̂_1 − v̂_2)
  double scale = 0.0;
  /// Q, the driver's generalized force: inertial − gravity − loads.
  double generalizedForce() const { return inertial - gravity - loads; }
};

/// The virtual work with the accelerations of `motion` and the velocities of `rates` (the same
/// positions; its velocities per unit input rate, or `motion` itself for the power balance).
/// The mechanism and dynamics must have passed checkMechanism and checkDynamics, with a known
/// length unit.
VirtualWork virtualWork(const Mechanism& mechanism, const LinkageDynamics& dynamics, const Pose& motion,
                        const Pose& rates);

/// A crank's driving torque by virtual work, sample by sample: the model's names resolved once,
/// so sweepForces can give it beside the Newton–Euler torque at every sample
/// (ForceSweep::virtualWorkTorque) for the cost of a sum over the masses and loads.
class CrankVirtualWork {
public:
  /// Error naming "driver" for a linkage not driven by a crank. The mechanism and dynamics must
  /// have passed checkMechanism and checkDynamics, with a known length unit; both must outlive
  /// this object.
  static Result<CrankVirtualWork> create(const Mechanism& mechanism, const LinkageDynamics& dynamics);

  /// The driving torque (N·m) at `motion`, an assembled pose with velocities and accelerations
  /// at crank angle `inputAngle` (rad). The velocities per unit crank rate are the pose's own
  /// divided by its rate, or solved afresh at rate 1 on the same branches when the crank is at rest.
  double torque(const Pose& motion, double inputAngle);

private:
  CrankVirtualWork(const Mechanism& mechanism, const LinkageDynamics& dynamics, PointId tip, PointId pivot);
  const Mechanism* m_mechanism;
  const LinkageDynamics* m_dynamics;
  PointId m_tip, m_pivot;
  Pose m_rates;  ///< scratch for the unit-rate solve at rest
};

}  // namespace linkwright::kinematics
