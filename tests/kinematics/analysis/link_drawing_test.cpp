// Tests kinematics/analysis/link_drawing.h: for every built-in example, every hole sits exactly on
// its solved joint and every joint of a moving body has one; the outlines are the offset of
// the joints' convex hull, so each hole lies inside its part with a web of (w − d)/2; a
// two-joint link is a stadium; bad hole and plate sizes are refused with the field, the value
// and the range; layer names are DXF-legal and unique.

#include "kinematics/analysis/link_drawing.h"

#include "kinematics/design/examples.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/motion_law.h"
#include "kinematics/solve/pose_solver.h"
#include "kinematics/solve/rigid_bodies.h"

#include "tests/support/catch.h"

#include <cmath>
#include <limits>
#include <set>

using namespace linkwright::kinematics;
using namespace linkwright::kinematics;

namespace {

// Points along a closed bulged outline, `perEdge` per edge (arcs sampled on their circle).
std::vector<Eigen::Vector2d> sampleOutline(const Outline& outline, int perEdge) {
  std::vector<Eigen::Vector2d> points;
  for (std::size_t i = 0; i < outline.size(); ++i) {
    const Eigen::Vector2d p = outline[i].point;
    const Eigen::Vector2d q = outline[(i + 1) % outline.size()].point;
    const double theta = 4.0 * std::atan(outline[i].bulge);
    const Eigen::Vector2d chord = q - p;
    const Eigen::Vector2d left(-chord.y(), chord.x());
    const Eigen::Vector2d centre = (p + q) / 2.0 + left / 2.0 / std::tan(theta / 2.0);
    for (int k = 0; k < perEdge; ++k) {
      const double t = static_cast<double>(k) / perEdge;
      if (theta == 0.0) {
        points.push_back(p + t * chord);
        continue;
      }
      const double a = t * theta;
      const Eigen::Vector2d r = p - centre;
      points.emplace_back(centre + Eigen::Vector2d(std::cos(a) * r.x() - std::sin(a) * r.y(),
                                                   std::sin(a) * r.x() + std::cos(a) * r.y()));
    }
  }
  return points;
}

// Winding number of a closed polygon around `c`.
int winding(const std::vector<Eigen::Vector2d>& polygon, const Eigen::Vector2d& c) {
  double turn = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Eigen::Vector2d a = polygon[i] - c;
    const Eigen::Vector2d b = polygon[(i + 1) % polygon.size()] - c;
    turn += std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
  }
  return static_cast<int>(std::lround(turn / (2.0 * kPi)));
}

// The example's pose where its design starts: its time base's first instant, else its grid's.
Pose startPose(const Example& e) {
  const double q = e.time                                       ? motionAt(e.time->law, e.time->fromTime).position
                   : inputKind(e.mechanism) == InputKind::Angle ? degToRad(e.fromDeg)
                                                                : e.fromDeg;
  auto pose = solvePose(e.mechanism, {q, 0.0, 0.0}, SolveRequest{false, false});
  REQUIRE(pose.ok());
  return *pose;
}

}  // namespace

TEST_CASE("every hole is on its solved joint and each part encloses its holes", "[link_drawing]") {
  for (const Example& e : examples()) {
    INFO(e.name);
    const Pose pose = startPose(e);
    const auto drawing = linkDrawing(e.mechanism, pose, {});
    REQUIRE(drawing.ok());
    const double d = drawing->holeDiameter;
    const double w = drawing->plateWidth;
    CHECK(w == 2.0 * d);
    const auto model = bodiesOf(e.mechanism);
    REQUIRE(model.ok());
    REQUIRE(drawing->layers.size() == model->bodies.size());
    CHECK(drawing->layers.front().name == "GROUND");
    std::set<std::size_t> drilled;
    for (const DrawingLayer& layer : drawing->layers) {
      INFO(layer.name);
      for (const Hole& h : layer.holes) {
        // The centre is the solved position itself: no arithmetic lies between them.
        CHECK((h.centre - pose.position[h.point.index]).norm() == 0.0);
        CHECK(h.diameter == d);
        drilled.insert(h.point.index);
      }
      if (layer.name == "GROUND" || layer.outlines.empty()) continue;
      const auto boundary = sampleOutline(layer.outlines.front(), 64);
      for (const Hole& h : layer.holes) {
        CHECK(winding(boundary, h.centre) == 1);
        double nearest = std::numeric_limits<double>::infinity();
        for (const Eigen::Vector2d& b : boundary) nearest = std::min(nearest, (b - h.centre).norm());
        // A slider block's pin is w/2 from its long sides; a plate's joint is at least w/2
        // from the offset hull. 1e-9 relative: the rounding of the offset.
        CHECK(nearest >= w / 2.0 * (1.0 - 1e-9));
      }
    }
    for (const Body& body : model->bodies)
      for (const PointId p : body.points) CHECK(drilled.count(p.index) == 1);
  }
}

TEST_CASE("a two-joint link is a stadium around its joints", "[link_drawing]") {
  const Outline o = roundedHull({Eigen::Vector2d(0.0, 0.0), Eigen::Vector2d(10.0, 0.0)}, 2.0);
  REQUIRE(o.size() == 4);
  // Half circles (bulge tan(π/4) = 1) about each joint, joined by the two straight sides.
  CHECK(o[0].bulge == Approx(1.0).epsilon(1e-15));
  CHECK(o[1].bulge == 0.0);
  CHECK(o[2].bulge == Approx(1.0).epsilon(1e-15));
  CHECK(o[3].bulge == 0.0);
  CHECK((o[0].point - Eigen::Vector2d(0.0, 2.0)).norm() < 1e-15);
  CHECK((o[1].point - Eigen::Vector2d(0.0, -2.0)).norm() < 1e-15);
  CHECK((o[2].point - Eigen::Vector2d(10.0, -2.0)).norm() < 1e-15);
  CHECK((o[3].point - Eigen::Vector2d(10.0, 2.0)).norm() < 1e-15);
}

TEST_CASE("a three-joint plate is the triangle offset by the plate's half-width", "[link_drawing]") {
  const std::vector<Eigen::Vector2d> joints{{0.0, 0.0}, {30.0, 0.0}, {10.0, 20.0}};
  const Outline o = roundedHull(joints, 3.0);
  REQUIRE(o.size() == 6);
  double sweep = 0.0;
  for (const OutlineVertex& v : o) sweep += 4.0 * std::atan(v.bulge);
  // The arcs of a convex offset turn once around: 2π in all.
  CHECK(sweep == Approx(2.0 * kPi).epsilon(1e-14));
  for (const Eigen::Vector2d& b : sampleOutline(o, 32)) {
    double nearest = std::numeric_limits<double>::infinity();
    for (const Eigen::Vector2d& j : joints) nearest = std::min(nearest, (b - j).norm());
    CHECK(nearest >= 3.0 * (1.0 - 1e-12));
  }
}

TEST_CASE("hole and plate sizes outside their ranges are refused", "[link_drawing]") {
  const Example e = *findExample("thesis-crank-rocker");
  const Pose pose = startPose(e);
  const auto spacing = shortestJointSpacing(e.mechanism, pose);
  REQUIRE(spacing.ok());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  struct Case {
    DrawingOptions options;
    const char* field;
    const char* text;
  };
  const Case cases[] = {
      {{0.0, std::nullopt}, "holeDiameter", "positive and finite (got 0)"},
      {{-1.0, std::nullopt}, "holeDiameter", "(got -1)"},
      {{nan, std::nullopt}, "holeDiameter", "(got undefined)"},
      {{*spacing, std::nullopt}, "holeDiameter", "must be less than"},
      {{1.0, 1.0}, "plateWidth", "more than the hole diameter 1"},
      {{1.0, std::numeric_limits<double>::infinity()}, "plateWidth", "(got undefined)"},
  };
  for (const Case& c : cases) {
    const auto drawing = linkDrawing(e.mechanism, pose, c.options);
    REQUIRE_FALSE(drawing.ok());
    CHECK(drawing.error().field == c.field);
    CHECK_THAT(drawing.error().message, Catch::Contains(c.text));
  }
  CHECK(linkDrawing(e.mechanism, pose, {*spacing * 0.999, std::nullopt}).ok());
  CHECK_FALSE(linkDrawing(e.mechanism, Pose{}, {}).ok());
}

TEST_CASE("layer names are DXF-legal and unique", "[link_drawing]") {
  CHECK(dxfLayerName("crank") == "crank");
  CHECK(dxfLayerName("link 5/a:b") == "link_5_a_b");
  CHECK(dxfLayerName("") == "PART");
  Example e = *findExample("thesis-crank-rocker");
  for (Link& link : e.mechanism.links) link.name = "ground";  // every link clashes with GROUND
  const auto drawing = linkDrawing(e.mechanism, startPose(e), {});
  REQUIRE(drawing.ok());
  std::set<std::string> names;
  for (const DrawingLayer& layer : drawing->layers) CHECK(names.insert(layer.name).second);
  CHECK(names.count("GROUND") == 1);
  CHECK(names.count("ground_2") == 1);
}
