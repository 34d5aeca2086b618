// Tests kinematics/solve/sample_writer.h: a pose lands in the selected columns only, angles are
// unwrapped across ±180° (also across a gap and inside a block), a block lands as its poses
// would one by one, rates are 0 at a singular sample, a failed sample is 0 everywhere, and the
// ground pivots' columns are filled by finish().

#include "kinematics/solve/sample_writer.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"
#include "kinematics/solve/sweep.h"

#include "tests/support/approx.h"

#include "tests/support/catch.h"

#include <span>
#include <vector>

using namespace linkwright::kinematics;
using linkwright::test::kThesis;
using linkwright::test::within;

namespace {
constexpr auto kO4 = fourbar::kO4.index;
constexpr auto kB = fourbar::kB.index;
constexpr auto kC = fourbar::kC.index;
constexpr auto kCrank = fourbar::kCrank.index;
constexpr auto kRocker = fourbar::kRocker.index;

// A four-bar's result of n samples, every column allocated by a real sweep.
SweepResult columnsFor(const Mechanism& m, std::size_t n, const SolveRequest& request = {}) {
  auto r = sweep(m, {0.0, 1.0, n, 1.0, 0.0}, request);
  REQUIRE(r.ok());
  return *r;
}

Pose solved(const Mechanism& m, double angleDeg) {
  auto p = solvePose(m, {degToRad(angleDeg), 2.0, 0.5});
  REQUIRE(p.ok());
  return *p;
}
}  // namespace

TEST_CASE("SampleWriter copies a pose into every selected column", "[sweep]") {
  const Mechanism m = makeFourBar(kThesis, Branch::Open).value();
  SweepResult out = columnsFor(m, 3);
  SampleWriter writer(m, out);
  const Pose p = solved(m, 30.0);
  writer.write(1, p);
  CHECK(out.position[kC][1] == p.position[kC]);
  CHECK(out.velocity[kB][1] == p.velocity[kB]);
  CHECK(out.acceleration[kC][1] == p.acceleration[kC]);
  CHECK(out.transmissionAngle[kC][1] == p.transmissionAngle[kC]);
  CHECK(out.linkAngle[kRocker][1] == p.linkAngle[kRocker]);
  CHECK(out.linkOmega[kRocker][1] == p.linkOmega[kRocker]);
  CHECK(out.linkAlpha[kRocker][1] == p.linkAlpha[kRocker]);

  // A singular sample keeps its positions and angles; its rates, cleared, read 0.
  Pose singular = p;
  clearRates(singular);
  writer.write(2, singular);
  CHECK(out.position[kC][2] == p.position[kC]);
  CHECK(out.velocity[kC][2] == Eigen::Vector2d::Zero());
  CHECK(out.acceleration[kB][2] == Eigen::Vector2d::Zero());
  CHECK(out.linkOmega[kRocker][2] == 0.0);
  CHECK(out.linkAlpha[kRocker][2] == 0.0);
  CHECK(out.linkAngle[kRocker][2] == p.linkAngle[kRocker]);
}

TEST_CASE("SampleWriter leaves out what the request did not select", "[sweep]") {
  const Mechanism m = makeFourBar(kThesis, Branch::Open).value();
  SolveRequest request{true, false};
  request.only = Selection{std::vector<PointId>{}, std::vector<LinkId>{fourbar::kRocker}};
  SweepResult out = columnsFor(m, 2, request);
  SampleWriter writer(m, out);
  writer.write(0, solved(m, 10.0));
  CHECK(out.position[kC].empty());
  CHECK(out.linkAngle[kCrank].empty());
  CHECK(out.acceleration.empty());
  CHECK(out.linkOmega[kRocker][0] == solved(m, 10.0).linkOmega[kRocker]);
}

TEST_CASE("SampleWriter unwraps link angles, also across a failed sample", "[sweep]") {
  const Mechanism m = makeFourBar(kThesis, Branch::Open).value();
  SweepResult out = columnsFor(m, 4);
  SampleWriter writer(m, out);
  Pose p = solved(m, 170.0);
  writer.write(0, p);
  CHECK(out.linkAngle[kCrank][0] == within(degToRad(170.0), 1e-15));
  p.linkAngle[kCrank] = degToRad(-175.0);  // the pose's angle wraps; the column must not
  writer.write(1, p);
  CHECK(out.linkAngle[kCrank][1] == within(degToRad(185.0), 1e-14));
  writer.writeNothing(2);
  CHECK(out.linkAngle[kCrank][2] == 0.0);
  CHECK(out.position[kC][2] == Eigen::Vector2d::Zero());
  CHECK(out.velocity[kC][2] == Eigen::Vector2d::Zero());
  CHECK(out.transmissionAngle[kC][2] == 0.0);
  p.linkAngle[kCrank] = degToRad(-160.0);  // continues from sample 1, not from the failed one
  writer.write(3, p);
  CHECK(out.linkAngle[kCrank][3] == within(degToRad(200.0), 1e-14));
}

TEST_CASE("SampleWriter writes a block as it writes its poses one by one", "[sweep]") {
  const Mechanism m = makeFourBar(kThesis, Branch::Open).value();
  std::vector<Pose> block{solved(m, 150.0), solved(m, 170.0), solved(m, 190.0), solved(m, 210.0)};
  SweepResult oneByOne = columnsFor(m, 6);
  SweepResult together = columnsFor(m, 6);
  SampleWriter single(m, oneByOne);
  SampleWriter blockwise(m, together);
  single.write(0, block[0]);
  blockwise.write(0, block[0]);
  for (std::size_t b = 1; b < block.size(); ++b) single.write(b, block[b]);
  blockwise.write(1, std::span<const Pose>(block).subspan(1));  // the crank wraps past 180° inside the block
  for (std::size_t j = 0; j < block.size(); ++j) {
    CHECK(together.position[kC][j] == oneByOne.position[kC][j]);
    CHECK(together.velocity[kB][j] == oneByOne.velocity[kB][j]);
    CHECK(together.acceleration[kC][j] == oneByOne.acceleration[kC][j]);
    CHECK(together.transmissionAngle[kC][j] == oneByOne.transmissionAngle[kC][j]);
    CHECK(together.linkAngle[kCrank][j] == oneByOne.linkAngle[kCrank][j]);
    CHECK(together.linkOmega[kRocker][j] == oneByOne.linkOmega[kRocker][j]);
    CHECK(together.linkAlpha[kRocker][j] == oneByOne.linkAlpha[kRocker][j]);
  }
  CHECK(together.linkAngle[kCrank][3] == within(degToRad(210.0), 1e-14));
  CHECK(together.position[kC][3] == block[3].position[kC]);
}

TEST_CASE("SampleWriter fills a ground pivot's columns only where the linkage assembles", "[sweep]") {
  const Mechanism m = makeFourBar(kThesis, Branch::Open).value();
  SweepResult out = columnsFor(m, 3);
  out.position[kO4].assign(3, Eigen::Vector2d(-1.0, -1.0));  // stale values from an earlier sweep
  out.velocity[kO4].assign(3, Eigen::Vector2d(-1.0, -1.0));
  out.report[1].status = PoseStatus::NotAssemblable;
  SampleWriter writer(m, out);
  writer.writeNothing(1);
  writer.finish(m, out);
  CHECK(out.position[kO4][0] == Eigen::Vector2d(kThesis.frame, 0.0));
  CHECK(out.position[kO4][1] == Eigen::Vector2d::Zero());
  CHECK(out.position[kO4][2] == Eigen::Vector2d(kThesis.frame, 0.0));
  CHECK(out.velocity[kO4][0] == Eigen::Vector2d::Zero());
  CHECK(out.velocity[kO4][2] == Eigen::Vector2d::Zero());
}
