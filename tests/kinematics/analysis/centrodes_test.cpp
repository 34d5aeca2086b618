// The centrodes checked against the solver's exact rates, not against the centres they are
// made of: at every sample the coupler's point at I13 is at rest (v_B + ω3 ẑ×(I13 − B) = 0),
// the moving centrode placed with the coupler touches the fixed one there, and the two roll
// without slipping (equal arc lengths); the same for a shaper's link. A parallelogram's
// coupler only translates: no centrode; a linkage with no floating body is refused.

#include "kinematics/analysis/centrodes.h"
#include "kinematics/design/design.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/shaper.h"
#include "kinematics/model/slider_crank.h"
#include "kinematics/model/units.h"
#include "kinematics/model/vec2.h"
#include "kinematics/solve/pose_solver.h"

#include "tests/support/catch.h"

#include <cmath>

using namespace linkwright::kinematics;

namespace {

constexpr std::size_t kSamples = 3601;  // 0.1°: the arc lengths' chords agree to ~1e-6

SweepResult turn(const Mechanism& m) {
  return sweep(m, SweepSpec{0.0, 2.0 * kPi, kSamples, 1.0, 0.0}, SolveRequest{true, false}).value();
}

double length(const std::vector<Eigen::Vector2d>& run) {
  double total = 0.0;
  for (std::size_t i = 1; i < run.size(); ++i) total += (run[i] - run[i - 1]).norm();
  return total;
}

// Every run's samples, checked against the sweep at the samples they came from: I13 is where
// the coupler is at rest, and the moving centrode, carried by the coupler, is on the fixed one.
void checkAgainstSolver(const Mechanism& m, PointId b, PointId c, LinkId coupler, double scale) {
  const SweepResult s = turn(m);
  const auto curves = centrodes(m, s);
  REQUIRE(curves);
  REQUIRE_FALSE(curves->fixed.empty());
  REQUIRE(curves->fixed.size() == curves->moving.size());
  std::size_t j = 0, checked = 0;
  for (std::size_t r = 0; r < curves->fixed.size(); ++r) {
    REQUIRE(curves->fixed[r].size() == curves->moving[r].size());
    for (std::size_t i = 0; i < curves->fixed[r].size(); ++i) {
      // Find the sample this point came from: the next one where the coupler's velocity field
      // vanishes at it (runs skip only samples whose I13 is out of reach).
      const Eigen::Vector2d centre = curves->fixed[r][i];
      for (;; ++j) {
        REQUIRE(j < s.size());
        const Eigen::Vector2d vb = s.velocity[b.index][j];
        const Eigen::Vector2d rest = vb + s.linkOmega[coupler.index][j] * perp(centre - s.position[b.index][j]);
        if (rest.norm() <= 1e-9 * scale) break;
      }
      const Eigen::Vector2d pb = s.position[b.index][j], pc = s.position[c.index][j];
      const CouplerFrame frame{pb, std::atan2(pc.y() - pb.y(), pc.x() - pb.x())};
      CHECK((frame.toWorld(curves->moving[r][i]) - centre).norm() <= 1e-9 * scale);
      ++checked;
      ++j;
    }
    // Rolling without slipping: the two curves are equally long between the same samples.
    CHECK(length(curves->moving[r]) == Approx(length(curves->fixed[r])).epsilon(1e-4));
  }
  CHECK(checked > kSamples / 2);
}

}  // namespace

TEST_CASE("the thesis crank-rocker's centrodes: I13 at rest on the coupler, rolling without slip", "[centrodes]") {
  const Mechanism m = makeFourBar({60.0, 25.0, 70.0, 45.0}, Branch::Open).value();
  checkAgainstSolver(m, fourbar::kB, fourbar::kC, fourbar::kCoupler, 70.0);
}

TEST_CASE("a double-crank's and an offset slider-crank's centrodes follow the solver too", "[centrodes]") {
  const Mechanism dragLink = makeFourBar({20.0, 60.0, 70.0, 50.0}, Branch::Open).value();  // shortest grounded
  checkAgainstSolver(dragLink, fourbar::kB, fourbar::kC, fourbar::kCoupler, 70.0);
  const Mechanism slider = makeSliderCrank({40.0, 140.0, 15.0}).value();
  checkAgainstSolver(slider, slidercrank::kB, slidercrank::kC, slidercrank::kRod, 140.0);
}

TEST_CASE("a parallelogram's coupler translates: its centre is at infinity, no centrode", "[centrodes]") {
  // Of the two branches of equal opposite links, the parallelogram is the one whose coupler
  // keeps its angle (the other, the antiparallelogram, has elliptic centrodes).
  int parallelograms = 0;
  for (const Branch branch : {Branch::Open, Branch::Crossed}) {
    const Mechanism m = makeFourBar({60.0, 25.0, 60.0, 25.0}, branch).value();
    const SweepResult s = turn(m);
    const std::vector<double>& angle = s.linkAngle[fourbar::kCoupler.index];
    bool translates = true;
    for (std::size_t j = 0; j < s.size(); ++j)
      if (s.assembled(j) && std::abs(std::remainder(angle[j] - angle[0], 2.0 * kPi)) > 1e-9) translates = false;
    const auto curves = centrodes(m, s);
    REQUIRE(curves);
    if (!translates) continue;
    ++parallelograms;
    CHECK(curves->fixed.empty());
    CHECK(curves->moving.empty());
  }
  CHECK(parallelograms == 1);
}

TEST_CASE("a shaper's centrodes are its link's (body 5), and follow the solver", "[centrodes]") {
  const Mechanism m = designForExample("shaper")->mechanism;
  const auto curves = centrodes(m, turn(m));
  REQUIRE(curves);
  CHECK(curves->body == 5);  // 1 frame, 2 crank, 3 block, 4 rocker, 5 link, 6 ram
  checkAgainstSolver(m, shaper::kD, shaper::kRam, shaper::kLink, 400.0);
}

TEST_CASE("a linkage whose every body is jointed to the frame has no centrodes: refused with the reason",
          "[centrodes]") {
  const Mechanism m = designForExample("excavator-boom")->mechanism;
  const auto frame = couplerFrame(m, solvePose(m, {1.5, 0.0, 0.0}, SolveRequest{false, false}).value());
  REQUIRE_FALSE(frame);
  CHECK(frame.error().code == ErrorCode::InvalidStructure);
  CHECK(frame.error().message.find("every body of this linkage is jointed to it") != std::string::npos);
}
