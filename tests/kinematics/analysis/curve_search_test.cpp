// Tests the fast searches the coupler-curve classifier stands on against the brute force they
// replace, on coupler curves and on random input:
// - kinematics/analysis/box_pairs.h: the pairs of boxes that meet, from buckets, are exactly
//   the pairs an all-pairs test finds (pieces of a figure-eight and of a curve that runs back
//   over itself; random boxes of mixed sizes, some wide enough to skip the buckets);
// - kinematics/analysis/point_tree.h: the nearest point is the one a scan of every point finds;
// - kinematics/analysis/window_fits.h: every window's line and circle are the direct
//   least-squares fits, within() agrees with measuring every sample, and turnsAtLeast() with
//   the step-by-step turn.

#include "kinematics/analysis/box_pairs.h"
#include "kinematics/analysis/point_tree.h"
#include "kinematics/analysis/window_fits.h"

#include "kinematics/model/fourbar.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/sweep.h"

#include "tests/support/catch.h"
#include "tests/support/coupler_curves.h"

#include <Eigen/Dense>

#include <cmath>
#include <random>

using namespace linkwright::kinematics;
namespace test = linkwright::test;

namespace {

std::vector<std::pair<std::size_t, std::size_t>> allPairs(const std::vector<Eigen::AlignedBox2d>& boxes) {
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (std::size_t i = 0; i < boxes.size(); ++i)
    for (std::size_t j = i + 1; j < boxes.size(); ++j)
      if (!boxes[i].isEmpty() && !boxes[j].isEmpty() && boxes[i].intersects(boxes[j])) pairs.push_back({i, j});
  return pairs;
}

std::vector<Eigen::AlignedBox2d> pieceBoxes(const CouplerCurve& c) {
  std::vector<Eigen::AlignedBox2d> boxes;
  for (std::size_t i = 0; i < c.pieces(); ++i) {
    Eigen::AlignedBox2d b(c.point[i]);
    b.extend(c.point[c.next(i)]);
    boxes.push_back(b);
  }
  return boxes;
}

double cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

}  // namespace

TEST_CASE("box pairs from buckets are the all-pairs test's", "[atlas][crunode]") {
  SECTION("a figure-eight's pieces") {
    const auto boxes = pieceBoxes(test::couplerCurveOf({2.5, 1.0, 1.5, 2.5}, {2.25, 1.5}, 720));
    const auto pairs = intersectingBoxPairs(boxes);
    CHECK(pairs == allPairs(boxes));
    CHECK(pairs.size() > boxes.size());  // neighbours touch, and the crossing's pieces meet
  }
  SECTION("a point on the rocker, whose curve runs back over itself") {
    const auto boxes = pieceBoxes(test::couplerCurveOf({3.0, 1.0, 3.0, 2.5}, {1.0, 0.3}, 500));
    CHECK(intersectingBoxPairs(boxes) == allPairs(boxes));
  }
  SECTION("random boxes, small and wide") {
    std::mt19937 random(56);
    std::uniform_real_distribution<double> place(-10.0, 10.0), side(0.0, 0.3), wide(0.0, 8.0);
    for (int round = 0; round < 5; ++round) {
      std::vector<Eigen::AlignedBox2d> boxes;
      for (int i = 0; i < 400; ++i) {
        const Eigen::Vector2d lo(place(random), place(random));
        const double w = i % 37 == 0 ? wide(random) : side(random), h = i % 41 == 0 ? wide(random) : side(random);
        boxes.emplace_back(lo, lo + Eigen::Vector2d(w, h));
      }
      boxes.emplace_back();  // empty: meets nothing
      CHECK(intersectingBoxPairs(boxes) == allPairs(boxes));
    }
  }
}

TEST_CASE("the point tree's nearest point is the nearest of all", "[atlas][symmetric]") {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  const CouplerCurve c = test::couplerCurveOf({2.5, 1.0, 1.5, 2.5}, {2.25, 1.5}, 997);
  const PointTree tree(c.point);
  for (int k = 0; k < 500; ++k) {
    const Eigen::Vector2d x(u(random), u(random));
    std::size_t best = 0;
    for (std::size_t i = 1; i < c.size(); ++i)
      if ((c.point[i] - x).squaredNorm() < (c.point[best] - x).squaredNorm()) best = i;
    CHECK(tree.nearest(x) == best);
  }
  CHECK(PointTree({}).nearest({1.0, 2.0}) == 0);
}

TEST_CASE("window fits are the direct least-squares fits, and within() is every sample's test", "[atlas][straight]") {
  const CouplerCurve c = test::couplerCurveOf({2.0, 1.0, 2.5, 2.5}, {2.0, 0.0}, 720);  // Hoeken's
  const std::size_t n = c.size();
  const WindowFits fits(c);
  std::mt19937 random(3);
  std::uniform_int_distribution<std::size_t> start(0, n - 1), length(2, n - 1);
  int accepted = 0, refused = 0;
  for (int k = 0; k < 400; ++k) {
    const SampleWindow w{start(random), 0};
    const SampleWindow window{w.first, w.first + length(random) % (k % 2 ? 40 : n - 1) + 2};
    CAPTURE(window.first, window.last);
    // The direct fits, about the window's first point.
    const Eigen::Vector2d o = fits.at(window.first);
    Eigen::Vector2d mean = Eigen::Vector2d::Zero();
    Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
    Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
    for (std::size_t i = window.first; i <= window.last; ++i) {
      const Eigen::Vector2d p = fits.at(i) - o;
      mean += p;
      const Eigen::Vector3d row(p.x(), p.y(), 1.0);
      normal += row * row.transpose();
      rhs -= row * p.squaredNorm();
    }
    mean /= static_cast<double>(window.count());
    Eigen::Matrix2d scatter = Eigen::Matrix2d::Zero();
    for (std::size_t i = window.first; i <= window.last; ++i)
      scatter += (fits.at(i) - o - mean) * (fits.at(i) - o - mean).transpose();
    const Eigen::Vector2d direction = Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(scatter).eigenvectors().col(1);
    const WindowLine line = fits.line(window);
    CHECK((line.mean - (o + mean)).norm() < 1e-12);
    CHECK(std::abs(cross2(line.direction, direction)) < 1e-9);
    const Eigen::Vector3d def = normal.ldlt().solve(rhs);
    const Eigen::Vector2d centre = o + Eigen::Vector2d(-0.5 * def[0], -0.5 * def[1]);
    const WindowCircle circle = fits.circle(window);
    REQUIRE(circle.ok);
    if (window.count() > 20) {  // a short window's circle is ill-conditioned in either way
      CHECK((circle.centre - centre).norm() < 1e-6 * std::max(1.0, circle.radius));
    }
    // within() against the worst sample, at tolerances about it.
    for (const double scale : {0.5, 0.999, 1.001, 2.0}) {
      const double lineWorst = fits.deviation(window, line), circleWorst = fits.deviation(window, circle);
      CHECK(fits.within(window, line, scale * lineWorst) == (scale > 1.0));
      CHECK(fits.within(window, circle, scale * circleWorst) == (scale > 1.0));
      (scale > 1.0 ? accepted : refused) += 1;
      const double turn = fits.turn(window, circle.centre);
      CHECK(fits.turnsAtLeast(window, circle, circleWorst, scale * turn) == (scale <= 1.0));
    }
  }
  CHECK(accepted > 0);
  CHECK(refused > 0);
}
