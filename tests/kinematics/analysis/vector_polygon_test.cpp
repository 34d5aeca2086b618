// Velocity and acceleration polygons against the pose solver: every arrow is checked against
// a value computed here from the solver's positions, point rates and link rates (ω × r,
// −ω² r, α × r, the slide rate d|O4B|/dt, 2ω × v_slide), every side of every equation closes
// on the solver's image of its point, and the relative vectors have the directions a student
// draws (⟂ the link, ∥ the guide). Examples: the thesis crank-rocker (seed 000), the Alvi
// four-bar (seed 001), the LS3 slider-crank and the crank-shaper (seed 003), at several crank
// angles and with a crank α, so the tangential terms are not zero.
//
// Tolerance: 1e-9 of the polygon's size (its largest image). The solver's rates are exact
// closed forms good to ~1e-15 relative; the polygon adds a few products to them.

#include "kinematics/analysis/vector_polygon.h"
#include "kinematics/design/examples.h"
#include "kinematics/model/driver.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/shaper.h"
#include "kinematics/model/slider_crank.h"
#include "kinematics/model/units.h"
#include "kinematics/model/vec2.h"
#include "kinematics/solve/sweep.h"
#include "tests/kinematics/dynamics/dynamics_cases.h"

#include "tests/support/catch.h"

#include <cmath>

using namespace linkwright::kinematics;

namespace {

constexpr double kCrankAlpha = 3.0;  // rad/s²: any nonzero value exercises the tangential terms

double sizeOf(const VectorPolygon& polygon) {
  double size = 0.0;
  for (const PolygonImage& im : polygon.images) size = std::max(size, im.position.norm());
  return size;
}

const PolygonVector& find(const VectorPolygon& polygon, const std::string& label) {
  for (const PolygonVector& v : polygon.vectors)
    if (v.label == label) return v;
  FAIL("no vector " << label);
  return polygon.vectors.front();
}

void checkNear(const Eigen::Vector2d& got, const Eigen::Vector2d& expected, double tolerance) {
  CAPTURE(got.x(), got.y(), expected.x(), expected.y(), tolerance);
  CHECK((got - expected).norm() <= tolerance);
}

// A side of an equation is a run of arrows of one point, each starting where the last ended;
// the run must end on an image (the point's, or a coincident point's on its way).
void checkSidesClose(const VectorPolygon& polygon) {
  const double tol = 1e-9 * sizeOf(polygon);
  const auto onImage = [&](const Eigen::Vector2d& p) {
    return std::any_of(polygon.images.begin(), polygon.images.end(),
                       [&](const PolygonImage& im) { return (im.position - p).norm() <= tol; });
  };
  for (std::size_t k = 0; k < polygon.vectors.size(); ++k) {
    const PolygonVector& v = polygon.vectors[k];
    CHECK(v.step == static_cast<int>(k) + 1);
    const bool last = k + 1 == polygon.vectors.size() || polygon.vectors[k + 1].point != v.point ||
                      (polygon.vectors[k + 1].from - v.to).norm() > tol;
    CAPTURE(v.label);
    // An arrow starts on an image or at the tip of the arrow before it (A^t after A^n).
    CHECK(((k > 0 && polygon.vectors[k - 1].to == v.from) || onImage(v.from)));
    if (last) CHECK(onImage(v.to));
  }
  for (const PolygonEquation& e : polygon.equations)
    for (const Eigen::Vector2d& end : e.ends) checkNear(end, e.solver, tol);
  for (const PolygonImage& im : polygon.images) {
    CHECK((im.position.array() >= polygon.lower.array() - tol).all());
    CHECK((im.position.array() <= polygon.upper.array() + tol).all());
  }
}

ClassroomPolygons polygonsOf(const Example& example, double deg) {
  const auto result = polygonsAt(example.mechanism, {degToRad(deg), example.omega, kCrankAlpha});
  REQUIRE(result);
  checkSidesClose(result->velocity);
  checkSidesClose(result->acceleration);
  return *result;
}

// Q relative to P on a body turning at ω, α: the velocity arrow and the two acceleration arrows.
void checkRigid(const ClassroomPolygons& p, const std::string& suffix, const Eigen::Vector2d& r, double omega,
                double alpha) {
  const double vTol = 1e-9 * sizeOf(p.velocity);
  const double aTol = 1e-9 * sizeOf(p.acceleration);
  CAPTURE(suffix);
  const PolygonVector v = find(p.velocity, "V_" + suffix);
  checkNear(v.value(), omega * perp(r), vTol);
  CHECK(std::abs(v.value().dot(r)) <= vTol * r.norm());
  CHECK(std::abs(v.value().norm() - std::abs(omega) * r.norm()) <= vTol);
  const PolygonVector n = find(p.acceleration, "A^n_" + suffix);
  checkNear(n.value(), -omega * omega * r, aTol);
  CHECK(std::abs(n.value().norm() - omega * omega * r.norm()) <= aTol);
  const PolygonVector t = find(p.acceleration, "A^t_" + suffix);
  CHECK(t.from == n.to);
  checkNear(t.value(), alpha * perp(r), aTol);
}

void checkFourBar(const Example& example, double deg) {
  CAPTURE(example.name, deg);
  const ClassroomPolygons p = polygonsOf(example, deg);
  const Pose& pose = p.pose;
  const Eigen::Vector2d o2 = pose.position[0], o4 = pose.position[1], b = pose.position[2], c = pose.position[3];
  const double vTol = 1e-9 * sizeOf(p.velocity);
  const double aTol = 1e-9 * sizeOf(p.acceleration);
  checkRigid(p, "B", b - o2, example.omega, kCrankAlpha);
  checkRigid(p, "CB", c - b, pose.linkOmega[1], pose.linkAlpha[1]);
  checkRigid(p, "C", c - o4, pose.linkOmega[2], pose.linkAlpha[2]);
  // V_C = V_B + V_CB: from b, ending at the solver's V_C; the rocker's arrow from the pole too.
  checkNear(find(p.velocity, "V_CB").from, pose.velocity[2], vTol);
  checkNear(find(p.velocity, "V_CB").to, pose.velocity[3], vTol);
  checkNear(find(p.velocity, "V_C").to, pose.velocity[3], vTol);
  checkNear(find(p.velocity, "V_CB").value(), pose.velocity[3] - pose.velocity[2], vTol);
  checkNear(find(p.acceleration, "A^t_CB").to, pose.acceleration[3], aTol);
  checkNear(find(p.acceleration, "A^t_C").to, pose.acceleration[3], aTol);
  checkNear(find(p.acceleration, "A^t_B").to, pose.acceleration[2], aTol);
  CHECK(p.velocity.equations[1].text == "V_C = V_B + V_CB");
  CHECK(p.acceleration.equations[1].text == "A_C = A_B + A^n_CB + A^t_CB = A^n_C + A^t_C");
  CHECK(p.velocity.equations[0].text == "V_B = ω × O2B");
}

}  // namespace

TEST_CASE("four-bar polygons: every arrow is the solver's relative motion", "[vector_polygon]") {
  const double deg = GENERATE(0.0, 30.0, 75.0, 150.0, 210.0, 300.0);
  checkFourBar(*findExample("thesis-crank-rocker"), deg);
  checkFourBar(*findExample("alvi-fourbar"), deg);
}

TEST_CASE("the velocity image of a coupler point is the coupler turned by 90° and scaled by ω3", "[vector_polygon]") {
  const Mechanism m = makeFourBar(kThesisCrankRocker, Branch::Open, "mm", CouplerPointSpec{30.0, 20.0}).value();
  const double deg = GENERATE(20.0, 135.0, 260.0);
  CAPTURE(deg);
  const auto p = polygonsAt(m, {degToRad(deg), 2.0, kCrankAlpha});
  REQUIRE(p);
  const Pose& pose = p->pose;
  const auto image = [&](const std::string& label) {
    for (const PolygonImage& im : p->velocity.images)
      if (im.label == label) return im.position;
    FAIL("no image " << label);
    return Eigen::Vector2d(0, 0);
  };
  const Eigen::Vector2d b = image("b"), c = image("c"), q = image("p");
  const double w3 = pose.linkOmega[fourbar::kCoupler.index];
  const double tol = 1e-9 * sizeOf(p->velocity);
  checkNear(q - b, w3 * perp(pose.position[4] - pose.position[2]), tol);
  checkNear(c - b, w3 * perp(pose.position[3] - pose.position[2]), tol);
  checkNear(find(p->velocity, "V_PB").to, pose.velocity[4], tol);
  checkSidesClose(p->velocity);
  checkSidesClose(p->acceleration);
}

TEST_CASE("slider-crank polygons: the piston slides along the guide", "[vector_polygon]") {
  const Example example = *findExample("ls3-engine");
  const double deg = GENERATE(0.0, 45.0, 90.0, 200.0, 330.0);
  CAPTURE(deg);
  const ClassroomPolygons p = polygonsOf(example, deg);
  const Pose& pose = p.pose;
  const Eigen::Vector2d o2 = pose.position[0], b = pose.position[1], c = pose.position[2];
  checkRigid(p, "B", b - o2, example.omega, kCrankAlpha);
  checkRigid(p, "CB", c - b, pose.linkOmega[1], pose.linkAlpha[1]);
  const PolygonVector vc = find(p.velocity, "V_C");
  CHECK(vc.term == VectorTerm::Sliding);
  CHECK(vc.from == Eigen::Vector2d::Zero());
  checkNear(vc.to, pose.velocity[2], 1e-9 * sizeOf(p.velocity));
  CHECK(std::abs(vc.value().y()) <= 1e-9 * sizeOf(p.velocity));
  const PolygonVector ac = find(p.acceleration, "A_C");
  checkNear(ac.to, pose.acceleration[2], 1e-9 * sizeOf(p.acceleration));
  CHECK(p.velocity.equations[1].text == "V_C = V_B + V_CB");
  CHECK(p.acceleration.equations[1].text == "A_C = A_B + A^n_CB + A^t_CB");
}

TEST_CASE("crank-shaper polygons: the block slides in the turning slot, with Coriolis", "[vector_polygon]") {
  const Example example = *findExample("shaper");
  const double deg = GENERATE(0.0, 60.0, 120.0, 240.0, 300.0);
  CAPTURE(deg);
  const ClassroomPolygons p = polygonsOf(example, deg);
  const Pose& pose = p.pose;
  using namespace shaper;
  const Eigen::Vector2d o4 = pose.position[kO4.index], b = pose.position[kB.index], d = pose.position[kD.index];
  const double w = pose.linkOmega[kRocker.index];
  const double vTol = 1e-9 * sizeOf(p.velocity);
  const double aTol = 1e-9 * sizeOf(p.acceleration);
  checkRigid(p, "B'", b - o4, w, pose.linkAlpha[kRocker.index]);
  checkRigid(p, "D", d - o4, w, pose.linkAlpha[kRocker.index]);
  // The slide rate is how fast B moves away from O4: d|O4B|/dt = e·V_B.
  const Eigen::Vector2d e = (b - o4).normalized();
  const Eigen::Vector2d slide = e.dot(pose.velocity[kB.index]) * e;
  const PolygonVector vs = find(p.velocity, "V_BB'");
  checkNear(vs.value(), slide, vTol);
  checkNear(vs.to, pose.velocity[kB.index], vTol);
  const PolygonVector cor = find(p.acceleration, "A^c_B");
  CHECK(cor.term == VectorTerm::Coriolis);
  checkNear(cor.value(), 2.0 * w * perp(slide), aTol);
  const PolygonVector as = find(p.acceleration, "A_BB'");
  CHECK(std::abs(cross(as.value(), e)) <= aTol);
  checkNear(as.to, pose.acceleration[kB.index], aTol);
  checkRigid(p, "RD", pose.position[kRam.index] - d, pose.linkOmega[kLink.index], pose.linkAlpha[kLink.index]);
  checkNear(find(p.velocity, "V_R").to, pose.velocity[kRam.index], vTol);
  CHECK(p.velocity.equations[1].text == "V_B = V_B' + V_BB'");
  CHECK(p.acceleration.equations[1].text == "A_B = A^n_B' + A^t_B' + A^c_B + A_BB'");
  CHECK(p.velocity.equations[2].text == "V_D = ω × O4D");
  CHECK(p.acceleration.equations[2].text == "A_D = A^n_D + A^t_D");
}

TEST_CASE("a polygon at a toggle does not exist, and says why", "[vector_polygon]") {
  // The thesis linkage's coupler and rocker can fold in line only if it is not Grashof; a
  // change-point linkage (2 + 4 = 3 + 3) folds flat at crank angle 0.
  const Mechanism m = makeFourBar({3.0, 2.0, 3.0, 4.0}, Branch::Open).value();
  const auto p = polygonsAt(m, {0.0, 1.0, 0.0});
  REQUIRE_FALSE(p);
  CHECK(p.error().code == ErrorCode::Singular);
}

TEST_CASE("a pin on a turning guide (PRP yoke): the slide and its Coriolis term in closed form", "[vector_polygon]") {
  // C = (50, 50 tan θ) on the crank's line: s = |O2C| = 50 / cos θ, so ṡ = 50 sin θ / cos² θ · ω,
  // and the Coriolis term is 2ω ṡ e⊥ with e along the crank.
  const Mechanism m = linkwright::test::prpYoke();
  const double deg = GENERATE(-50.0, -10.0, 25.0, 60.0);
  CAPTURE(deg);
  const double theta = degToRad(deg), omega = 3.0;
  const auto p = polygonsAt(m, {theta, omega, kCrankAlpha});
  REQUIRE(p);
  checkSidesClose(p->velocity);
  checkSidesClose(p->acceleration);
  const Eigen::Vector2d e(std::cos(theta), std::sin(theta));
  const double sDot = 50.0 * std::sin(theta) / (std::cos(theta) * std::cos(theta)) * omega;
  const PolygonVector slide = find(p->velocity, "V_CC'");
  checkNear(slide.value(), sDot * e, 1e-9 * sizeOf(p->velocity));
  checkNear(find(p->acceleration, "A^c_C").value(), 2.0 * omega * sDot * perp(e), 1e-9 * sizeOf(p->acceleration));
  CHECK(p->velocity.equations[1].text == "V_C = V_C' + V_CC'");
}

TEST_CASE("every built-in example's polygons close on the solver", "[vector_polygon]") {
  // Six-bars, Newton-solved triads (absolute arrows), a path-driven arm and an actuator-driven
  // boom (its cylinder turns while it extends: a Coriolis term) included.
  for (const Example& ex : examples()) {
    CAPTURE(ex.name);
    SweepSpec spec{degToRad(ex.fromDeg), degToRad(ex.toDeg), 7, ex.omega, kCrankAlpha};
    if (ex.time) spec = SweepSpec{0.0, 0.0, 7, 0.0, 0.0, ex.time};
    if (inputKind(ex.mechanism) != InputKind::Angle && !ex.time) continue;
    const auto s = sweep(ex.mechanism, spec);
    REQUIRE(s);
    int drawn = 0;
    for (std::size_t j = 0; j < s->size(); ++j) {
      if (!s->ok(j)) continue;
      const auto p = polygonsAt(ex.mechanism, sweepDriver(spec, j));
      REQUIRE(p);
      checkSidesClose(p->velocity);
      checkSidesClose(p->acceleration);
      ++drawn;
    }
    CHECK(drawn > 0);
  }
}
