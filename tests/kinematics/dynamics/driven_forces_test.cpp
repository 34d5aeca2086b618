// Inverse dynamics of linkages driven other than by a crank (rigid_bodies.h, inverse_dynamics.h):
// the driver's unknowns and Gruebler count, the drive force along the input, the frame
// reactions, seed 004's arm's joint torques τ = JᵀF against the serial arm's own Newton–Euler
// equations, the force columns, and what forces still refuse. The power balance of the same
// cases is in force_sweep_test.cpp.

#include "kinematics/dynamics/force_columns.h"
#include "kinematics/dynamics/force_sweep.h"
#include "kinematics/dynamics/inverse_dynamics.h"
#include "kinematics/model/driven_linkages.h"
#include "kinematics/model/mechanism_check.h"
#include "kinematics/model/path_shape.h"
#include "kinematics/model/vec2.h"
#include "kinematics/solve/rigid_bodies.h"
#include "kinematics/solve/sweep.h"

#include "tests/kinematics/dynamics/dynamics_cases.h"
#include "tests/kinematics/dynamics/power_balance.h"

#include "tests/support/catch.h"

#include <algorithm>
#include <cmath>

using namespace linkwright::kinematics;
using linkwright::test::DynamicsCase;
using linkwright::test::poseAt;

namespace {

DynamicsCase drivenCase(const std::string& name) {
  for (DynamicsCase& c : linkwright::test::drivenDynamicsCases())
    if (c.name == name) return c;
  FAIL("no driven case " << name);
  return {};
}

std::vector<std::string> names(const std::vector<ForceColumn>& columns) {
  std::vector<std::string> out;
  for (const auto& c : columns) out.push_back(c.name);
  return out;
}

using Names = std::vector<std::string>;

// A mass element's centre and its acceleration (m, m/s²), as inverse_dynamics.h defines them.
struct Centre {
  Eigen::Vector2d position;
  Eigen::Vector2d acceleration;
};

Centre centreOf(const Mechanism& m, const Pose& pose, const LinkMass& l) {
  const double s = *metresPerLengthUnit(m.lengthUnit);
  const std::size_t k = m.findLink(l.link)->index;
  const Link& link = m.links[k];
  const Eigen::Vector2d a = s * pose.position[link.first.index];
  const Eigen::Vector2d e = s * pose.position[link.second.index] - a;
  const Eigen::Vector2d u = e.normalized();
  const LinkFramePoint c = l.centre.value_or(LinkFramePoint{0.5 * e.norm() / s, 0.0});
  const Eigen::Vector2d r = s * (c.along * u + c.across * perp(u));
  const double w = pose.linkOmega[k];
  return {a + r, s * pose.acceleration[link.first.index] + pose.linkAlpha[k] * perp(r) - w * w * r};
}

}  // namespace

TEST_CASE("bodiesOf: each driver's generalized force, and Gruebler's count with 1 or 2 unknowns",
          "[dynamics][driven]") {
  SECTION("the arm: the tip's drive force F (two unknowns) on the forearm; M = 2") {
    const Mechanism m = drivenCase("seed-arm").mechanism;
    const auto model = bodiesOf(m);
    REQUIRE(model.ok());
    CHECK(model->drive.kind == DriveKind::Path);
    CHECK(model->drive.point == PointId{1});
    CHECK(model->drive.body == model->linkBody[1]);  // the forearm
    CHECK(model->revolutes.size() == 2);             // O and the elbow
    CHECK(model->mobility() == 2);
    CHECK(model->unknowns() == 6);
    CHECK(model->equations() == 6);
    REQUIRE(model->arm);
    CHECK(model->arm->pivot == PointId{0});
    CHECK(model->arm->elbow == PointId{2});
    CHECK(model->momentPoint == PointId{0});
  }
  SECTION("the piston-driven slider-crank: the piston's drive force on the rod; crank and rod are a chain") {
    const auto model = bodiesOf(drivenCase("piston-driven").mechanism);
    REQUIRE(model.ok());
    CHECK(model->drive.kind == DriveKind::Path);
    CHECK(model->drive.body == model->linkBody[1]);  // the rod
    CHECK(model->mobility() == 2);
    CHECK(model->unknowns() == model->equations());
    REQUIRE(model->arm);
    CHECK(model->arm->elbow == PointId{2});  // B
  }
  SECTION("the boom: the cylinder's axial force f (one unknown) on the boom, from the ground at A; M = 1") {
    const auto model = bodiesOf(drivenCase("excavator-boom").mechanism);
    REQUIRE(model.ok());
    CHECK(model->drive.kind == DriveKind::Actuator);
    CHECK(model->drive.point == PointId{2});
    CHECK(model->drive.pivot == PointId{1});
    CHECK(model->drive.body == model->linkBody[0]);
    CHECK(model->drive.base == kGroundBody);
    CHECK(model->revolutes.size() == 1);  // O only: the cylinder is no body
    CHECK(model->mobility() == 1);
    CHECK(model->unknowns() == 3);
    CHECK(model->equations() == 3);
    CHECK_FALSE(model->arm);
  }
}

TEST_CASE("the drive force along the input times the input's rate is the drive power", "[dynamics][driven]") {
  // driveAlong·q̇ (q̇ from the motion law) = f·u·(v_C − v_A) or F·v_P from the pose: the
  // tangent and the axis are those of the input, to round-off.
  for (const DynamicsCase& c : linkwright::test::drivenDynamicsCases()) {
    CAPTURE(c.name);
    const auto s = sweep(c.mechanism, c.spec).value();
    const auto f = sweepForces(c.mechanism, c.dynamics, s).value();
    std::size_t checked = 0;
    for (std::size_t j = 0; j < s.size(); ++j) {
      if (!f.ok(j)) continue;
      CAPTURE(j);
      const Pose pose = poseAt(c.mechanism, s, j);
      const double power = linkwright::test::drivePower(c.mechanism, pose, f.at(j));
      const double rate = sweepDriver(c.spec, j).velocity * *metresPerLengthUnit(c.mechanism.lengthUnit);
      CHECK(f.driveAlong[j] * rate == Approx(power).epsilon(1e-12).margin(1e-12 * std::abs(f.driveAlong[j] * rate)));
      CHECK(f.driveTorque[j] == 0.0);
      ++checked;
    }
    CHECK(checked == s.size());
  }
}

TEST_CASE("a path drive's force at a pose without its input: the tangent from the nearest path point",
          "[dynamics][driven]") {
  const DynamicsCase c = drivenCase("seed-arm");
  const auto s = sweep(c.mechanism, c.spec).value();
  const auto f = sweepForces(c.mechanism, c.dynamics, s).value();
  for (const std::size_t j : {std::size_t{1}, s.size() / 2, s.size() - 2}) {
    CAPTURE(j);
    const auto atPose = forcesAtPose(c.mechanism, c.dynamics, poseAt(c.mechanism, s, j));
    REQUIRE(atPose.ok());
    CHECK(atPose->driveForce == f.driveForce[j]);
    CHECK(atPose->driveAlong == Approx(f.driveAlong[j]).epsilon(1e-14));
  }
}

TEST_CASE("driven linkages: with no loads the frame feels minus the rate of change of momentum", "[dynamics][driven]") {
  // Shaking force = −Σ m a_G and moment about the first ground point (the origin in all three)
  // = −Σ (I α + G×m a_G): the drive's reaction on the frame (−F at the path point, −f·u at the
  // cylinder's ground pin) is in it with the right sign.
  for (DynamicsCase c : linkwright::test::drivenDynamicsCases()) {
    CAPTURE(c.name);
    c.dynamics.loads = {};
    const auto s = sweep(c.mechanism, c.spec).value();
    const auto f = sweepForces(c.mechanism, c.dynamics, s).value();
    for (std::size_t j = 0; j < s.size(); j += 10) {
      CAPTURE(j);
      REQUIRE(f.ok(j));
      const Pose pose = poseAt(c.mechanism, s, j);
      const double metres = *metresPerLengthUnit(c.mechanism.lengthUnit);
      Eigen::Vector2d momentumRate = Eigen::Vector2d::Zero();
      double angularRate = 0.0;
      double scale = 0.0;
      for (const LinkMass& l : c.dynamics.links) {
        const Centre g = centreOf(c.mechanism, pose, l);
        const double alpha = pose.linkAlpha[c.mechanism.findLink(l.link)->index];
        const Link& link = c.mechanism.links[c.mechanism.findLink(l.link)->index];
        const double length = metres * (pose.position[link.second.index] - pose.position[link.first.index]).norm();
        const double inertia = l.inertia.value_or(l.mass * length * length / 12.0);
        momentumRate += l.mass * g.acceleration;
        angularRate += inertia * alpha + cross(g.position, l.mass * g.acceleration);
        scale += l.mass * g.acceleration.norm() * (1.0 + g.position.norm()) + std::abs(inertia * alpha);
      }
      CHECK((f.shakingForce[j] + momentumRate).norm() <= 1e-12 * scale);
      CHECK(std::abs(f.shakingMoment[j] + angularRate) <= 1e-12 * scale);
    }
  }
}

TEST_CASE("the arm's joint torques τ = JᵀF are the serial arm's own Newton–Euler torques", "[dynamics][driven][arm]") {
  // The arm moved by a shoulder and an elbow motor with its tip free, solved link by link from
  // the tip (recursive Newton–Euler, SI), in a vertical plane with a torch force F_L at the tip:
  //   forearm: R_E = m2 (a_G2 − g) − F_L (on it from the upper link at E),
  //            τ_elbow = I2 α2 + (G2 − E)×m2 (a_G2 − g) − (P − E)×F_L;
  //   upper:   τ_shoulder = τ_elbow + (E − O)×R_E + I1 α1 + (G1 − O)×m1 (a_G1 − g).
  // The path drive's F, found from the closed chain, must give the same torques through Jᵀ.
  const DynamicsCase c = drivenCase("seed-arm");
  const Mechanism& m = c.mechanism;
  const auto s = sweep(m, c.spec).value();
  const auto f = sweepForces(m, c.dynamics, s).value();
  const LinkMass& upper = c.dynamics.links[0];
  const LinkMass& forearm = c.dynamics.links[1];
  const Eigen::Vector2d g = *c.dynamics.loads.gravity;
  const Eigen::Vector2d load = c.dynamics.loads.forces[0].force;
  const PointId O{0}, tip{1}, elbow{2};
  double peakShoulder = 0.0;
  double peakElbow = 0.0;
  for (std::size_t j = 0; j < s.size(); ++j) {
    CAPTURE(j);
    REQUIRE(f.ok(j));
    const Pose pose = poseAt(m, s, j);
    const Eigen::Vector2d o = pose.position[O.index];
    const Eigen::Vector2d e = pose.position[elbow.index];
    const Eigen::Vector2d p = pose.position[tip.index];
    const Centre g1 = centreOf(m, pose, upper);
    const Centre g2 = centreOf(m, pose, forearm);
    const double alpha1 = pose.linkAlpha[0];
    const double alpha2 = pose.linkAlpha[1];
    const Eigen::Vector2d inertia2 = forearm.mass * (g2.acceleration - g);
    const Eigen::Vector2d inertia1 = upper.mass * (g1.acceleration - g);
    const Eigen::Vector2d reaction = inertia2 - load;
    const double elbowTorque = *forearm.inertia * alpha2 + cross(g2.position - e, inertia2) - cross(p - e, load);
    const double shoulderTorque =
        elbowTorque + cross(e - o, reaction) + *upper.inertia * alpha1 + cross(g1.position - o, inertia1);
    const double scale = std::abs(*forearm.inertia * alpha2) + (g2.position - e).norm() * inertia2.norm() +
                         (p - e).norm() * load.norm() + (e - o).norm() * reaction.norm() +
                         std::abs(*upper.inertia * alpha1) + (g1.position - o).norm() * inertia1.norm();
    CHECK(std::abs(f.jointTorque[j].x() - shoulderTorque) <= 1e-9 * scale);
    CHECK(std::abs(f.jointTorque[j].y() - elbowTorque) <= 1e-9 * scale);
    peakShoulder = std::max(peakShoulder, std::abs(shoulderTorque));
    peakElbow = std::max(peakElbow, std::abs(elbowTorque));
  }
  // The torques are those of a 3.5 kg arm with a 20 N torch held out about 0.3 m: a few N·m.
  CAPTURE(peakShoulder, peakElbow);
  CHECK(peakShoulder > 1.0);
  CHECK(peakShoulder < 50.0);
  CHECK(peakElbow > 0.1);
}

TEST_CASE("force columns name each driver's force with its unit", "[dynamics][driven][io]") {
  const auto arm = bodiesOf(drivenCase("seed-arm").mechanism).value();
  CHECK(names(forceColumns(arm)) == Names{"F_O_x_N", "F_O_y_N", "F_O_N", "F_elbow_x_N", "F_elbow_y_N", "F_elbow_N",
                                          "tip_drive_fx_N", "tip_drive_fy_N", "tip_drive_force_N", "O_joint_torque_Nm",
                                          "elbow_joint_torque_Nm", "shaking_x_N", "shaking_y_N", "shaking_N",
                                          "shaking_moment_Nm"});
  const auto boom = bodiesOf(drivenCase("excavator-boom").mechanism).value();
  CHECK(names(forceColumns(boom)) == Names{"F_O_x_N", "F_O_y_N", "F_O_N", "actuator_force_N", "shaking_x_N",
                                           "shaking_y_N", "shaking_N", "shaking_moment_Nm"});
  // The short table keeps sizes, the drive's force along its input and the joint torques.
  Names summary;
  for (const auto& column : forceColumns(arm))
    if (column.isSummary()) summary.push_back(column.name);
  CHECK(summary ==
        Names{"F_O_N", "F_elbow_N", "tip_drive_force_N", "O_joint_torque_Nm", "elbow_joint_torque_Nm", "shaking_N"});
  // Values come from the sweep's columns.
  const DynamicsCase c = drivenCase("seed-arm");
  const auto s = sweep(c.mechanism, c.spec).value();
  const auto f = sweepForces(c.mechanism, c.dynamics, s).value();
  const auto columns = forceColumns(f.bodies);
  CHECK(columns[6].value(f, 5) == f.driveForce[5].x());
  CHECK(columns[7].value(f, 5) == f.driveForce[5].y());
  CHECK(columns[8].value(f, 5) == f.driveAlong[5]);
  CHECK(columns[9].value(f, 5) == f.jointTorque[5].x());
  CHECK(columns[10].value(f, 5) == f.jointTorque[5].y());
}

TEST_CASE("what forces still refuse for a driven linkage, with the reason", "[dynamics][driven][errors]") {
  SECTION("a mass on the path point's carriage") {
    const Mechanism m = drivenCase("piston-driven").mechanism;
    const auto e = checkDynamics(m, LinkageDynamics{{}, {{"C", 0, 0.3, 0.0}}, {}});
    REQUIRE(e);
    CHECK(e->field == "sliders[0].point");
    CHECK(e->message ==
          "sliders[0].point must name a slider's point (an rrp, rpr or prp point; got \"C\", which is driven along "
          "a path: its carriage is massless and takes no load; put the mass or load on a link that holds C)");
  }
  SECTION("a path point on no link drives nothing") {
    Mechanism m;
    m.lengthUnit = "m";
    m.points = {{"O", GroundPoint{}}, {"P", PathPoint{PolylinePath{{{0.0, 0.0}, {1.0, 0.0}}}}}};
    REQUIRE_FALSE(checkMechanism(m));
    const auto model = bodiesOf(m);
    REQUIRE_FALSE(model);
    CHECK(model.error().message == "forces need the point P driven along the path to lie on a link: it is on none");
  }
}
