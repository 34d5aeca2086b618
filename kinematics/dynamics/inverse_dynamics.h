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
//   Link by link. Most linkages need no LU. Back from the output, some group of bodies has
//     exactly as many unknowns left as equations; once it is solved, its joints' forces are
//     known loads on the bodies before it (a four-bar: the coupler and the rocker together, then
//     the crank). create() looks for such an order of two kinds of group; where it finds one,
//     every pose is solved by it in closed form, on each body's load in SI (its inertia and
//     external loads: the resultant R and the moment M about its reference point O, less the
//     forces of joints already solved):
//       the crank: its pin P to the frame and the torque T. F = R on the crank, and
//         T = M − (P − O) × R.
//       a dyad: bodies 1 and 2 joined by a pin Q, each held by one more joint, J1 on body 1 and
//         J2 on body 2, each a pin P_k (a revolute joint, or a path drive's force, a pin to the
//         frame) or, if body k is a block, its slide along the unit u_k (a prismatic joint).
//         With G the pin's force on body k (±, as it is the joint's body or its hub), one
//         equation of body k leaves J_k out: its moments about P_k, (Q − P_k) × G = M_k −
//         (P_k − O_k) × R_k, or its forces along u_k, G·u_k = R_k·u_k. These two rows
//         a_k·G = c_k give G by Cramer's rule; the determinant a₁ × a₂ vanishes at the dyad's
//         toggle. Then J_k carries f_k = R_k − G on body k: a pin's force, or a slide's
//         N = f_k·n, and its couple M_k (every force on a block acts at its pin, which is O_k).
//     Dyad chains driven by a crank or along a path (four-bars, slider-cranks, a PRP yoke, the
//     Watt II, the arm, the slider-crank worked from its piston) have such an order. Others (a slide in the middle of a dyad as in the shaper, the
//     Stephenson II's triad, an actuator) use the LU, as does a pose where a dyad's |a₁ × a₂|
//     is below kChainMargin·|a₁||a₂|, the sine of the angle between its rows: within that band
//     of a toggle the LU decides whether it is Singular, so both ways agree on every pose but
//     in a band 1e4 times narrower than the LU's own. The numbers agree with the LU's to
//     round-off (tested at 1e-9 on every kind).
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

#include <array>
#include <optional>
#include <vector>

namespace linkwright::kinematics {

/// Relative pivot of U below which the scaled Newton–Euler system counts as singular. The
/// pose solver flags toggles at |sin μ| < 1e-4 (rrr_dyad.h), where the smallest pivot is
/// still about 1e-4 of the largest; at an exact toggle it is round-off, ~1e-16.
inline constexpr double kForceRankThreshold = 1e-10;

/// A dyad solved link by link whose 2×2 determinant is below this fraction of the product of its
/// rows' norms (the sine of the angle between them) goes to the LU, which decides whether the
/// pose is Singular.
inline constexpr double kChainMargin = 1e-6;

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

  /// Whether poses are solved link by link (header comment); if not, every one by the LU.
  bool solvesLinkByLink() const { return !m_chain.empty(); }

  /// Which way the last solve went: link by link, or the LU (always, or for a pose near a toggle).
  enum class Method { LinkByLink, Lu };
  Method lastMethod() const { return m_lastMethod; }

  /// Solves at `pose`, which must hold positions, velocities and accelerations (a pose the
  /// solver reported Ok). Returns Ok, or Singular (forces set to zero) when the system is rank
  /// deficient. Link by link where create() found an order, else by the LU; no allocation
  /// (buffers sized by create() and prepare()).
  /// `input` is the driver's coordinate q at this pose (DriverState::angle); only a path
  /// drive uses it, for the tangent its driveAlong is taken along. Without it the path
  /// coordinate is the one nearest the point between the path's ends (nearestPathCoordinate),
  /// which is the same unless the point has run past the end of an arc or sits where a
  /// polyline meets itself.
  PoseStatus solveInto(const Pose& pose, PoseForces& forces, std::optional<double> input = std::nullopt);

  /// As solveInto, always by the LU of the whole system: the reference link by link is tested against.
  PoseStatus solveByLuInto(const Pose& pose, PoseForces& forces, std::optional<double> input = std::nullopt);

private:
  struct MassElement {
    BodyId body;
    std::optional<LinkId> link;  ///< none for a block (centre at its pin)
    double mass = 0.0;           ///< kg
    double inertia = 0.0;        ///< kg·m²
    LinkFramePoint centre;       ///< length unit
    PointId first;               ///< the link's first point, or the block's pin
    PointId second;              ///< the link's second point, or the block's pin
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
  /// A spring's ends (kGroundBody for one on the frame), in SI.
  struct BodySpring {
    BodyId firstBody;
    PointId first;
    BodyId secondBody;
    PointId second;
    double stiffness = 0.0;   ///< N/m
    double freeLength = 0.0;  ///< m
    double preload = 0.0;     ///< N
  };
  /// A spring's pull on its first end at `pose` (N; the second end feels the opposite).
  Eigen::Vector2d springPull(const Pose& pose, const BodySpring& s) const;
  /// Where a body's ω, α and reference point come from (bodyRates).
  struct BodyRate {
    PointId reference;
    PointId second;
    std::optional<LinkId> link;            ///< its first link, if any
    std::optional<std::size_t> turnsWith;  ///< a block: the body it slides on
  };
  /// A joint's or the driver's unknowns as the link-by-link solve sees them: a pin's force (a
  /// revolute joint; a path drive's, from the frame), a slide's normal force and couple, or the
  /// crank's torque. Each acts with + on `body` and with − on `hub` (the frame for a drive).
  struct ChainUnknown {
    enum class Kind { Pin, Slide, Torque };
    Kind kind = Kind::Pin;
    Eigen::Index column = 0;  ///< its first entry in m_solution
    PointId point;            ///< where it acts (a slide: the block's pin)
    BodyId body;
    BodyId hub;
    std::size_t slide = 0;  ///< a slide's index in BodyModel::prismatics
    double sign(BodyId b) const { return b == body ? 1.0 : -1.0; }
  };
  /// One step of the link-by-link order (header comment): the crank (unknown[0] its pin,
  /// unknown[1] the torque) or a dyad (unknown[0] J1 on body[0], unknown[1] the pin between,
  /// unknown[2] J2 on body[1]); `passOn` the unknowns it solves that also load a later body.
  struct ChainStep {
    bool dyad = false;
    std::array<BodyId, 2> body;
    std::array<std::size_t, 3> unknown{};
    std::vector<std::pair<std::size_t, BodyId>> passOn;
  };

  InverseDynamics() = default;
  std::optional<Error> resolve(const LinkageDynamics& dynamics);
  void planChain();
  bool solveLinkByLink(const Pose& pose);
  bool solveDyad(const Pose& pose, const ChainStep& step);
  void passOn(const Pose& pose, const ChainUnknown& u, BodyId body);
  void bodyRates(const Pose& pose);
  void bodyLoads(const Pose& pose);
  void prismaticNormals(const Pose& pose);
  void assemble(const Pose& pose);
  void addJoints(const Pose& pose);
  void addDrive(const Pose& pose);
  void addForceColumn(BodyId body, const Eigen::Vector2d& point, const Eigen::Vector2d& direction, double sign,
                      Eigen::Index column);
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
  std::vector<BodySpring> m_springs;
  std::vector<BodyRate> m_rates;         ///< per body
  std::vector<ChainUnknown> m_unknowns;  ///< the link-by-link solve's, in column order
  std::vector<ChainStep> m_chain;        ///< empty: no link-by-link order, the LU always
  // Per-solve state, sized once.
  std::vector<double> m_omega;               ///< per body, rad/s
  std::vector<double> m_alpha;               ///< per body, rad/s²
  std::vector<Eigen::Vector2d> m_reference;  ///< per body, its reference point O, m
  std::vector<Eigen::Vector2d> m_load;       ///< per body, R: Σ m(a_G − g) less the external forces, N
  std::vector<double> m_loadMoment;          ///< per body, M about O likewise, N·m
  std::vector<Eigen::Vector2d> m_prismaticNormal;
  Eigen::Vector2d m_actuatorAxis = Eigen::Vector2d::Zero();  ///< u, base → C
  double m_scale = 1.0;                                      ///< L, m
  Eigen::MatrixXd m_matrix;
  Eigen::VectorXd m_rhs;
  Eigen::VectorXd m_solution;  ///< the unknowns in SI (N, N·m): the LU's are scaled back
  Eigen::PartialPivLU<Eigen::MatrixXd> m_lu;
  Method m_lastMethod = Method::Lu;
};

/// Forces at one pose (e.g. the GUI's arrows at the current crank angle). `pose` must hold
/// velocities and accelerations; `input` as for InverseDynamics::solveInto. Errors: invalid input (as InverseDynamics::create), or
/// ErrorCode::Singular when the forces are not determined at this pose.
Result<PoseForces> forcesAtPose(const Mechanism& mechanism, const LinkageDynamics& dynamics, const Pose& pose,
                                std::optional<double> input = std::nullopt);

}  // namespace linkwright::kinematics
