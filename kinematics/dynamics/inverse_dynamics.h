#pragma once
// Inverse dynamics of a driven linkage at one pose: the reaction at every joint, the driver's
// generalized force (a crank's torque, an actuator's force, a path drive's force), and the
// shaking force and moment on the frame, from the Newton–Euler equations of all moving bodies
// (rigid_bodies.h) solved as one linear system. Seed 004 (Funsho) does this for a four-bar
// with a 9×9 matrix; this is the same method for any linkage the core solves. Derivation (SI
// throughout; × the scalar cross, ⊥ a CCW quarter turn; positions converted from the length
// unit with metresPerLengthUnit):
//
//   Kinematics, from the pose. A rigid body turns at ω, α: its first link's, else
//     ω = r×(v_b − v_a)/|r|², α = r×(a_b − a_a)/|r|² over two of its points a bar apart. A block
//     turns with the body it slides on. A mass element on link k (first point A, unit e along
//     the link, centre G = A + along·e + across·e⊥, r = G − A) accelerates at
//       a_G = a_A + α r⊥ − ω² r.
//     A block's centre of mass is its pin.
//   Unknowns, x (two per joint, then the driver's one or two):
//     revolute j at P between hub h and body c:  F_j = force on c from h (x, y; N); h feels −F_j.
//     prismatic between block k and guide body g, sliding along u, n = u⊥:  the normal force
//       N (on k from g, along n, at the pin C; N) and the couple M (on k from g; N·m, CCW +); g
//       feels −N·n at C and −M. The joint transmits nothing along u and lets nothing turn, so
//       its reactions do no work.
//     the driver's generalized force Q, which does the work of moving the input q:
//       crank: the torque T on the driven body from the ground (N·m, CCW +); the ground feels −T.
//       actuator from base B to C, u = (C − B)/|C − B|: the axial force f (N, + pushes C away
//         from B): f·u on the driven body at C and −f·u on the base's body at B (the ground's
//         share, if B is on it, is a frame reaction).
//       path: the force F (x, y; N) on the driven body at the point P from the ground, through
//         a massless carriage on the path; with t the path's unit tangent at s (path_shape.h),
//         F·t is the drive force and the rest the guide's reaction; the ground feels −F at P.
//   Equations, three per moving body b, with moments about a point R_b of the body (its
//     reference point, or the pin of a block) taken as fixed in space at this instant:
//       Σ F = Σ_i m_i (a_Gi − g)
//       Σ (P − R_b)×F + Σ couples = Σ_i [ I_i α + (G_i − R_b) × m_i (a_Gi − g) ]
//     over b's joint reactions, the driver's forces and external loads (gravity moved to the
//     right as −m g); this is ΣF = m a_G, ΣM_G = I_G α for each element, summed. Unknowns =
//     equations exactly when the Gruebler mobility equals the driver's unknowns (bodiesOf
//     checks it: 1 for a crank or an actuator, 2 for a path drive).
//   Solution. Moment rows are divided by the linkage's size L (m) and moment unknowns (M, T)
//     scaled by L, so every entry is O(1); an LU factorisation with partial pivoting solves it
//     (2.7× faster than the column-pivoting QR it replaced, the same numbers to 5e-14). If a
//     pivot of U is below kForceRankThreshold of the largest (a toggle position, a redundant
//     structure) the forces are not determined: the status is Singular and no numbers are given.
//   Frame reactions. The shaking force is the sum of the forces the moving bodies exert on the
//     ground through its joints, −Σ F_j (hub ground) − Σ N·n (guide ground), and through the
//     driver: −f·u at an actuator's ground base, −F at a path point. The shaking moment is
//     their moment about BodyModel::momentPoint (the crank pivot for a crank) plus the reaction
//     couples −M and the motor's −T. With no loads and no gravity they equal −Σ m a_G and
//     −Σ[I α + (G − O)×m a_G].
//   Power. Joint reactions do no net work, so the drive power plus Σ loads' power + Σ m g·v_G
//     = Σ (m v_G·a_G + I ω α): the rate of change of kinetic energy. The drive power is Q·q̇:
//     T·ω_driven for a crank, f·q̇ = f·u·(v_C − v_B) for an actuator, F·v_P = (F·t)·ṡ for a
//     path drive. The tests check this at every sample.
//   Joint torques of a serial arm (BodyModel::arm: ground pivot G, elbow E, tip P driven on
//     the path). With the joint coordinates θ (the upper link's angle) and φ (the forearm's
//     relative to it), δP = (P − G)⊥ δθ + (P − E)⊥ δφ, so the motors that move the chain the
//     same way with its tip free must do F's virtual work: τ = JᵀF,
//       τ_shoulder = (P − G) × F   (on the upper link from the ground),
//       τ_elbow    = (P − E) × F   (on the forearm from the upper link), N·m, CCW +.

#include "kinematics/dynamics/mass_properties.h"
#include "kinematics/model/mechanism.h"
#include "kinematics/model/result.h"
#include "kinematics/solve/pose.h"
#include "kinematics/solve/rigid_bodies.h"

#include <Eigen/Core>
#include <Eigen/LU>

#include <optional>
#include <vector>

namespace linkwright::kinematics {

/// Relative pivot of U below which the scaled Newton–Euler system counts as singular. The
/// pose solver flags toggles at |sin μ| < 1e-4 (rrr_dyad.h), where the smallest pivot is
/// still about 1e-4 of the largest; at an exact toggle it is round-off, ~1e-16.
inline constexpr double kForceRankThreshold = 1e-10;

/// Forces at one pose, world frame. Indices follow the BodyModel's joint lists.
struct PoseForces {
  std::vector<Eigen::Vector2d> revolute;  ///< N: force on joint.body from joint.hub
  std::vector<double> normal;             ///< N: on the block from the guide body, along n = u⊥
  std::vector<double> moment;             ///< N·m: couple on the block from the guide body, CCW +
  double driveTorque = 0.0;  ///< N·m: a crank's torque on the driven body from the ground, CCW +; 0 for other drivers
  /// N: a linear driver's generalized force, its component along the input: an actuator's
  /// axial force f (positive pushes C away from its base), a path drive's tangential force
  /// F·t (positive toward increasing s); 0 for a crank. The drive power is driveTorque·q̇ for a
  /// crank and driveAlong·q̇ for the others.
  double driveAlong = 0.0;
  /// N, world frame: the force a linear driver applies to the driven body at its point: f·u for
  /// an actuator, F for a path drive (its normal part is the guide's reaction); 0 for a crank.
  Eigen::Vector2d driveForce = Eigen::Vector2d::Zero();
  /// N·m, CCW +: a serial arm's (BodyModel::arm) equivalent joint torques τ = JᵀF: x the
  /// shoulder's, on the upper link from the ground; y the elbow's, on the forearm from the upper
  /// link. Zero without an arm.
  Eigen::Vector2d jointTorque = Eigen::Vector2d::Zero();
  Eigen::Vector2d shakingForce = Eigen::Vector2d::Zero();  ///< N: Σ forces the moving bodies exert on the ground
  /// N·m: their moment about BodyModel::momentPoint (the crank pivot), with the motor's reaction −T
  double shakingMoment = 0.0;
  bool operator==(const PoseForces&) const = default;
};

/// The Newton–Euler system of one mechanism and its dynamics, built once and solved at many
/// poses. Holds copies of both, resolved to ids, and the matrices it reuses.
class InverseDynamics {
public:
  /// Validates (checkMechanism, checkDynamics, a known length unit: metresPerLengthUnit) and
  /// finds the bodies (bodiesOf). Errors name the field.
  static Result<InverseDynamics> create(const Mechanism& mechanism, const LinkageDynamics& dynamics);

  const BodyModel& bodies() const { return m_bodies; }
  const Mechanism& mechanism() const { return m_mechanism; }

  /// Sizes `forces` for this mechanism (then solveInto does not resize it).
  void prepare(PoseForces& forces) const;

  /// Solves at `pose`, which must hold positions, velocities and accelerations (a pose the
  /// solver reported Ok). Returns Ok, or Singular (forces set to zero) when the system is rank
  /// deficient. Works in buffers sized by create() and prepare(); the only heap use left is
  /// inside Eigen's QR factorization, one small temporary per column (its rank-1 updates).
  /// `input` is the driver's coordinate q at this pose (DriverState::angle); only a path
  /// drive uses it, for the tangent its driveAlong is taken along. Without it the path
  /// coordinate is the one nearest the point between the path's ends (nearestPathCoordinate),
  /// which is the same unless the point has run past the end of an arc or sits where a
  /// polyline meets itself.
  PoseStatus solveInto(const Pose& pose, PoseForces& forces, std::optional<double> input = std::nullopt);

private:
  struct MassElement {
    BodyId body;
    std::optional<LinkId> link;  ///< none for a block (centre at its pin)
    double mass = 0.0;           ///< kg
    double inertia = 0.0;        ///< kg·m²
    LinkFramePoint centre;       ///< length unit
  };
  struct BodyTorque {
    BodyId body;
    double torque = 0.0;
  };
  struct BodyForce {
    BodyId body;
    PointId point;
    Eigen::Vector2d force = Eigen::Vector2d::Zero();
  };

  InverseDynamics() = default;
  std::optional<Error> resolve(const LinkageDynamics& dynamics);
  void bodyRates(const Pose& pose);
  void assemble(const Pose& pose);
  void addJoints(const Pose& pose);
  void addDrive(const Pose& pose);
  void addForceColumn(const Pose& pose, BodyId body, const Eigen::Vector2d& point, const Eigen::Vector2d& direction,
                      double sign, Eigen::Index column);
  void addRightHandSide(const Pose& pose);
  void extract(const Pose& pose, std::optional<double> input, PoseForces& forces) const;
  void extractDrive(const Pose& pose, std::optional<double> input, PoseForces& forces) const;
  Eigen::Vector2d momentOrigin(const Pose& pose) const;
  Eigen::Vector2d at(const Pose& pose, PointId p) const { return m_metres * pose.position[p.index]; }

  Mechanism m_mechanism;
  BodyModel m_bodies;
  double m_metres = 1.0;  ///< metres per length unit
  std::optional<Eigen::Vector2d> m_gravity;
  std::vector<MassElement> m_masses;
  std::vector<BodyTorque> m_torques;
  std::vector<BodyForce> m_forces;
  // Per-solve state, sized once.
  std::vector<double> m_omega;  ///< per body, rad/s
  std::vector<double> m_alpha;  ///< per body, rad/s²
  std::vector<Eigen::Vector2d> m_prismaticNormal;
  Eigen::Vector2d m_actuatorAxis = Eigen::Vector2d::Zero();  ///< u, base → C
  double m_scale = 1.0;                                      ///< L, m
  Eigen::MatrixXd m_matrix;
  Eigen::VectorXd m_rhs;
  Eigen::VectorXd m_solution;
  Eigen::VectorXd m_work;       ///< Qᵀb, then R⁻¹Qᵀb
  Eigen::VectorXd m_workspace;  ///< for applying Q (one column)
  Eigen::PartialPivLU<Eigen::MatrixXd> m_lu;
};

/// Forces at one pose (e.g. the GUI's arrows at the current crank angle). `pose` must hold
/// velocities and accelerations; `input` as for InverseDynamics::solveInto. Errors: invalid input (as InverseDynamics::create), or
/// ErrorCode::Singular when the forces are not determined at this pose.
Result<PoseForces> forcesAtPose(const Mechanism& mechanism, const LinkageDynamics& dynamics, const Pose& pose,
                                std::optional<double> input = std::nullopt);

}  // namespace linkwright::kinematics
