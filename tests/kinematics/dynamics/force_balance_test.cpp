// Shaking-force balance (force_balance.h): the four-bar's counterweights against the closed
// form for uniform bars, its shaking force zero to round-off at every sample after the balance
// (the funsho four-bar and random four-bars with masses), the slider-crank's residual against
// its closed form, and the refusals.

#include "kinematics/dynamics/force_balance.h"
#include "kinematics/design/examples.h"
#include "kinematics/dynamics/force_sweep.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/slider_crank.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/sweep.h"

#include "tests/support/catch.h"

#include <cmath>
#include <numbers>
#include <random>

using namespace linkwright::kinematics;

namespace {

constexpr double kTurn = 2.0 * std::numbers::pi;

// The largest shaking force over a turn, and the largest after `balanced`, at every sample.
struct ShakingPair {
  double before = 0.0;
  double worstAfter = 0.0;
};

ShakingPair shaking(const Mechanism& m, const LinkageDynamics& before, const LinkageDynamics& after, double omega,
                    double alpha) {
  const auto s = sweep(m, SweepSpec{0.0, kTurn, 361, omega, alpha}).value();
  const auto f0 = sweepForces(m, before, s).value();
  const auto f1 = sweepForces(m, after, s).value();
  ShakingPair p;
  for (std::size_t j = 0; j < s.size(); ++j) {
    REQUIRE(f0.ok(j));
    REQUIRE(f1.ok(j));
    p.before = std::max(p.before, f0.shakingForce[j].norm());
    p.worstAfter = std::max(p.worstAfter, f1.shakingForce[j].norm());
  }
  return p;
}

}  // namespace

TEST_CASE("a four-bar of uniform bars gets the textbook counterweights", "[dynamics][balance]") {
  // Uniform bars (centres at the middle): M3 = m3 l3/2, so the crank needs −(m2 + m3) l2/2 more
  // and the rocker −(m3 + m4) l4/2: (m2 + m3)/2 on the crank one crank length behind O2, and
  // (m3 + m4)/2 on the rocker one rocker length behind O4.
  const Mechanism m = makeFourBar({60.0, 25.0, 70.0, 45.0}, Branch::Open).value();
  LinkageDynamics d;
  d.links = {{"crank", 0.2, std::nullopt, std::nullopt},
             {"coupler", 0.5, std::nullopt, std::nullopt},
             {"rocker", 0.3, std::nullopt, std::nullopt}};
  const auto b = balanceShakingForce(m, d);
  REQUIRE(b.ok());
  REQUIRE(b->counterweights.size() == 2);
  const Counterweight& crank = b->counterweights[0];
  const Counterweight& rocker = b->counterweights[1];
  CHECK(crank.link == "crank");
  CHECK(crank.mass == Approx(0.35).epsilon(1e-12));
  CHECK(crank.centre.along == Approx(-25.0).epsilon(1e-12));
  CHECK(crank.centre.across == Approx(0.0).margin(1e-12));
  CHECK(rocker.link == "rocker");
  CHECK(rocker.mass == Approx(0.4).epsilon(1e-12));
  CHECK(rocker.centre.along == Approx(-45.0).epsilon(1e-12));
  // Joined to the links' masses: the crank's 0.2 kg at +12.5 mm and 0.35 kg at −25 mm make
  // 0.55 kg at (0.2·12.5 − 0.35·25)/0.55 mm, with m L²/12 and the parallel-axis terms.
  REQUIRE(b->balanced.links.size() == 3);
  const LinkMass& joined = b->balanced.links[0];
  CHECK(joined.mass == Approx(0.55));
  CHECK(joined.centre->along == Approx((0.2 * 12.5 - 0.35 * 25.0) / 0.55));
  const double c = joined.centre->along;
  CHECK(*joined.inertia ==
        Approx(0.2 * 0.025 * 0.025 / 12.0 + 1e-6 * (0.2 * (12.5 - c) * (12.5 - c) + 0.35 * (25.0 + c) * (25.0 + c))));
  // Twice as far out, half the mass.
  BalanceOptions far;
  far.radius = 2.0;
  const auto b2 = balanceShakingForce(m, d, far);
  CHECK(b2->counterweights[0].mass == Approx(0.175).epsilon(1e-12));
  CHECK(b2->counterweights[0].centre.along == Approx(-50.0).epsilon(1e-12));
}

TEST_CASE("after a full balance a four-bar's shaking force is zero to round-off at every sample",
          "[dynamics][balance]") {
  const auto e = findExample("funsho-fourbar").value();
  const auto b = balanceShakingForce(e.mechanism, e.dynamics);
  REQUIRE(b.ok());
  const ShakingPair funsho = shaking(e.mechanism, e.dynamics, b->balanced, e.omega, 0.0);
  CHECK(funsho.before > 1.0);
  CHECK(funsho.worstAfter <= 1e-9 * funsho.before);
  // Random crank-rockers with masses off the link lines, at any speed and acceleration.
  std::mt19937 random(44);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int tried = 0;
  while (tried < 20) {
    const FourBarLengths l{50.0 + 50.0 * unit(random), 5.0 + 15.0 * unit(random), 40.0 + 60.0 * unit(random),
                           30.0 + 60.0 * unit(random)};
    const auto m = makeFourBar(l, unit(random) < 0.5 ? Branch::Open : Branch::Crossed);
    if (!m) continue;
    const auto full = sweep(*m, SweepSpec{0.0, kTurn, 361, 1.0, 0.0});
    bool turns = full.ok();
    for (std::size_t j = 0; turns && j < full->size(); ++j) turns = full->ok(j);
    if (!turns) continue;  // not a crank-rocker, or a toggle on the way
    ++tried;
    LinkageDynamics d;
    for (const char* link : {"crank", "coupler", "rocker"})
      d.links.push_back({link, 0.1 + unit(random),
                         LinkFramePoint{100.0 * unit(random) - 20.0, 30.0 * unit(random) - 15.0}, 1e-4 * unit(random)});
    CAPTURE(l.frame, l.crank, l.coupler, l.rocker);
    const auto random4 = balanceShakingForce(*m, d);
    REQUIRE(random4.ok());
    const ShakingPair p = shaking(*m, d, random4->balanced, 10.0 * unit(random) + 1.0, 5.0 * unit(random));
    CHECK(p.worstAfter <= 1e-9 * p.before);
  }
}

TEST_CASE("a slider-crank's counterweight leaves −m_r (a_C + k r ω² e^{iθ2}) of the shaking force",
          "[dynamics][balance]") {
  const Mechanism m = makeSliderCrank({46.0, 155.0, 0.0}).value();
  LinkageDynamics d;
  d.links = {{"crank", 0.8, LinkFramePoint{10.0, 0.0}, 1e-3}, {"rod", 0.6, LinkFramePoint{50.0, 0.0}, 2e-3}};
  d.sliders = {{"C", 0, 0.5, 0.0}};
  const double omega = 300.0;
  const double reciprocating = 0.5 + 0.6 * 50.0 / 155.0;  // kg: the slider and the rod's share at C
  const auto s = sweep(m, SweepSpec{0.0, kTurn, 361, omega, 0.0}).value();
  for (const double k : {0.0, 0.5, 1.0}) {
    CAPTURE(k);
    BalanceOptions o;
    o.reciprocatingFraction = k;
    const auto b = balanceShakingForce(m, d, o);
    REQUIRE(b.ok());
    REQUIRE(b->counterweights.size() == 1);
    CHECK(b->counterweights[0].link == "crank");
    const auto f = sweepForces(m, b->balanced, s).value();
    double worst = 0.0, size = 0.0;
    for (std::size_t j = 0; j < s.size(); ++j) {
      const Eigen::Vector2d r = s.position[slidercrank::kB.index][j] * 1e-3;  // m, from O2 at the origin
      const Eigen::Vector2d aC = s.acceleration[slidercrank::kC.index][j] * 1e-3;
      const Eigen::Vector2d expected = -reciprocating * (aC + k * omega * omega * r);
      worst = std::max(worst, (f.shakingForce[j] - expected).norm());
      size = std::max(size, expected.norm());
    }
    CHECK(worst <= 1e-9 * size);
  }
}

TEST_CASE("shaking-force balance refuses what it cannot balance, naming the field", "[dynamics][balance]") {
  const auto watt = findExample("watt-ii").value();
  LinkageDynamics some;
  some.links = {{"crank", 1.0, std::nullopt, std::nullopt}};
  const auto sixBar = balanceShakingForce(watt.mechanism, some);
  REQUIRE_FALSE(sixBar.ok());
  CHECK(sixBar.error().field == "linkage");
  CHECK(sixBar.error().message == "shaking-force balance by counterweights is for a four-bar or a slider-crank");
  const Mechanism m = makeFourBar({60.0, 25.0, 70.0, 45.0}, Branch::Open).value();
  CHECK(balanceShakingForce(m, {}).error().field == "dynamics");
  BalanceOptions o;
  o.reciprocatingFraction = 1.5;
  CHECK(balanceShakingForce(m, some, o).error().message ==
        "the fraction of the reciprocating mass to balance must be between 0 and 1 (got 1.5)");
  o = {};
  o.radius = 0.0;
  CHECK(balanceShakingForce(m, some, o).error().field == "radius");
}
