#pragma once
// Velocity and acceleration polygons: the graphical method of every mechanisms course
// (Norton §6.2 and §7.2, Uicker §3.6 and §4.2), drawn from the exact solution at one solved
// pose. For each point in solve order (each dyad) the vector equation a student draws, each
// vector placed tip-to-tail in the polygon plane, the pole o being zero velocity
// (acceleration). Nothing is solved graphically: every vector is a term of the relative-motion
// equations evaluated with the solver's positions, point rates and link rates, so the polygon
// closes on the solver's values (to round-off) and a view only has to draw it.
//
// Two points P, Q of one rigid body turning at ω, α, with r = Q − P:
//   V_QP = ω × r                       (⟂ PQ, |V_QP| = |ω|·|PQ|)
//   A_QP = A^n_QP + A^t_QP = −ω² r + α × r   (normal towards P, tangential ⟂ PQ)
// A point C sliding along a guide fixed in a body turning at ω, α, with C' the body's point
// under C and u the guide's direction:
//   V_C = V_C' + V_CC'                  (V_CC' = ṡ u, the sliding velocity)
//   A_C = A_C' + A^c + A_CC'            (A^c = 2ω × V_CC' Coriolis, A_CC' = s̈ u)
// Each dyad type gives its pair of equations, both ending at the dyad point's image:
//   RRR C on P1, P2:        V_C = V_P1 + V_CP1 = V_P2 + V_CP2
//   RRP C on P1, guide g:   V_C = V_P1 + V_CP1 = V_C' + V_CC'   (C' on g's body; V_C' = 0 on ground)
//   PRP C on guides g1, g2: V_C = V_C1' + V_CC1' = V_C2' + V_CC2'
//   RPR D, slot about O through block P: V_P = V_P' + V_PP' (P' the slot's point under P,
//                           V_P' = V_O + ω × OP), then V_D = V_O + V_DO (the slotted link's image)
//   a point fixed on a link, a crank tip: V_Q = V_P + V_QP (the velocity image: the triangle of
//                           a link's images is similar to the link, turned by 90° for velocity)
// A ground reference drops out of the labels: V_B for V_BO2, A^n_C for A^n_CO4. Relative rates
// of a body come from its points as the solver gets link rates (ω = r × (vQ − vP)/|r|²);
// sliding terms are the projections on the guide of what is left, so a polygon that does not
// close to round-off would show a wrong solver, not a wrong drawing.

#include "kinematics/model/mechanism.h"
#include "kinematics/model/result.h"
#include "kinematics/solve/pose.h"

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

namespace linkwright::kinematics {

enum class PolygonKind {
  Velocity,      ///< length unit / s
  Acceleration,  ///< length unit / s²
};

/// What a polygon vector is.
enum class VectorTerm {
  Absolute,    ///< a point's whole velocity (acceleration) from the pole: a point on a path, a free point
  Relative,    ///< velocity of one point of a body relative to another: ω × r, ⟂ r
  Normal,      ///< −ω² r: normal (centripetal) acceleration, towards the reference point
  Tangential,  ///< α × r: tangential acceleration, ⟂ r
  Sliding,     ///< velocity (acceleration) of sliding along a guide or slot, parallel to it
  Coriolis,    ///< 2ω × V_slide: a slide along a guide that turns at ω
};

/// One arrow of a polygon, in the polygon plane (the pole o at the origin; velocity or
/// acceleration units). `to − from` is the vector.
struct PolygonVector {
  std::string label;  ///< "V_B", "V_CB", "A^n_CB", "A^t_C", "A^c_B", "V_BB'"
  VectorTerm term = VectorTerm::Relative;
  Eigen::Vector2d from = Eigen::Vector2d::Zero();
  Eigen::Vector2d to = Eigen::Vector2d::Zero();
  PointId point;               ///< the point whose equation it belongs to
  std::optional<LinkId> link;  ///< the mechanism's link the term belongs to, when there is one
  std::string meaning;         ///< one sentence: which points and body, and its direction rule
  int step = 0;                ///< the order a student draws it in (1-based, increasing)
  /// The vector itself (length unit / s or / s²).
  Eigen::Vector2d value() const { return to - from; }
  bool operator==(const PolygonVector&) const = default;
};

/// Where a point lands in the polygon (its velocity or acceleration as a position: the
/// image). Ground points all sit at the pole. Coincident points of a slide (B', the slotted
/// link's point under B) have images too, with `coincident` set.
struct PolygonImage {
  std::string label;  ///< the point's name in lower case: "b", "c", "o" for the pole, "b'"
  PointId point;      ///< the mechanism's point (for a coincident point: the point it lies under)
  Eigen::Vector2d position = Eigen::Vector2d::Zero();
  bool coincident = false;
  bool operator==(const PolygonImage&) const = default;
};

/// The vector equation of one point, as text ("V_C = V_B + V_CB"), with where each of its
/// sides ends in the polygon and the solver's value it must end on.
struct PolygonEquation {
  PointId point;    ///< the dyad point it belongs to
  PointId subject;  ///< the point on its left-hand side (an RPR dyad's block: its `through` point)
  std::string text;
  std::vector<Eigen::Vector2d> ends;                 ///< the tip of each side's last arrow (polygon units)
  Eigen::Vector2d solver = Eigen::Vector2d::Zero();  ///< the solver's velocity (acceleration) of `subject`
  bool operator==(const PolygonEquation&) const = default;
};

/// A whole polygon at one pose.
struct VectorPolygon {
  PolygonKind kind = PolygonKind::Velocity;
  std::string unit;                        ///< "mm/s" or "mm/s²" (the mechanism's length unit)
  std::vector<PolygonVector> vectors;      ///< in drawing order (step 1, 2, …)
  std::vector<PolygonImage> images;        ///< the pole first, then each point once
  std::vector<PolygonEquation> equations;  ///< one per point that has one, in solve order
  /// Bounding box of the pole, every image and every vector end (polygon units): a view
  /// picks its scale from it. Never NaN; a polygon at rest is the single point 0.
  Eigen::Vector2d lower = Eigen::Vector2d::Zero();
  Eigen::Vector2d upper = Eigen::Vector2d::Zero();
  bool operator==(const VectorPolygon&) const = default;
};

/// The velocity polygon of `mechanism` at `pose`, solved for it with velocities and every
/// point and link (the default request) and not singular (solvePose returned it).
VectorPolygon velocityPolygon(const Mechanism& mechanism, const Pose& pose);

/// The acceleration polygon at `pose` (solved with accelerations, as for velocityPolygon).
VectorPolygon accelerationPolygon(const Mechanism& mechanism, const Pose& pose);

/// Both polygons at one driver state, with the pose they draw.
struct ClassroomPolygons {
  Pose pose;
  VectorPolygon velocity;
  VectorPolygon acceleration;
};

/// Solves `mechanism` at `driver` and draws both polygons. Errors: those of solvePose; a pose
/// at a toggle is ErrorCode::Singular (its rates, hence its polygons, do not exist).
Result<ClassroomPolygons> polygonsAt(const Mechanism& mechanism, const DriverState& driver);

/// Error unless `mechanism` is driven by a crank, the one input polygons are drawn for;
/// `source` names it ("the example excavator-boom").
std::optional<Error> checkPolygonInput(const Mechanism& mechanism, const std::string& source);

}  // namespace linkwright::kinematics
