// The soak's checks (soak_checks.h) catch what they are there to catch: a sweep of the thesis
// four-bar passes, and each kind of corruption of it is reported.

#include "tests/kinematics/soak/soak_checks.h"

#include "kinematics/model/fourbar.h"
#include "kinematics/model/units.h"
#include "tests/support/approx.h"

#include "tests/support/catch.h"

#include <limits>

using namespace linkwright;
namespace k = kinematics;

namespace {

bool mentions(const test::SweepCheck& c, const std::string& text) {
  for (const auto& f : c.findings)
    if (f.find(text) != std::string::npos) return true;
  return false;
}

}  // namespace

TEST_CASE("the soak's checks pass a good sweep and report each corruption", "[soak]") {
  const k::Mechanism m = k::makeFourBar(test::kThesis, k::Branch::Open).value();
  const k::SweepSpec spec{0.0, 2.0 * k::kPi, 73, 3.0, -2.0};
  const k::SweepResult good = k::sweep(m, spec).value();
  const test::SweepCheck clean = test::checkSweep(m, spec, good, 3);
  CHECK(clean.findings.empty());
  CHECK(clean.assembled == 73);
  CHECK(clean.ratesCompared == 3);
  CHECK(clean.worstClosure < 1e-15);
  CHECK(clean.worstRateRatio <= 1.0);

  const std::size_t c = k::fourbar::kC.index, coupler = k::fourbar::kCoupler.index;
  SECTION("a value that is not finite") {
    k::SweepResult bad = good;
    bad.velocity[c][40].y() = std::numeric_limits<double>::quiet_NaN();
    CHECK(mentions(test::checkSweep(m, spec, bad, 3), "velocity or acceleration of C not finite at sample 40"));
  }
  SECTION("a point off its links, as a jump to the other branch") {
    k::SweepResult bad = good;
    // C mirrored across the line B–O4: the crossed assembly, all lengths still right.
    const Eigen::Vector2d b = bad.position[k::fourbar::kB.index][30], o4 = bad.position[k::fourbar::kO4.index][30];
    const Eigen::Vector2d axis = (o4 - b).normalized();
    const Eigen::Vector2d along = b + axis * axis.dot(bad.position[c][30] - b);
    bad.position[c][30] = 2.0 * along - bad.position[c][30];
    const test::SweepCheck check = test::checkSweep(m, spec, bad, 3);
    CHECK(mentions(check, "C jumps"));
    CHECK_FALSE(mentions(check, "misfit"));  // the mirror keeps every length
  }
  SECTION("a link that changes length") {
    k::SweepResult bad = good;
    bad.position[c][50].x() += 1e-6;
    CHECK(mentions(test::checkSweep(m, spec, bad, 3), "link coupler misfit"));
  }
  SECTION("a wrong ω") {
    k::SweepResult bad = good;
    bad.linkOmega[coupler][24] *= 1.001;  // one of the three samples compared (0, 24, 48)
    CHECK(mentions(test::checkSweep(m, spec, bad, 3), "ω of coupler at sample 24"));
  }
}
