// The exact sensitivities (kinematics/tune/tolerance_sensitivity.h) against a second method:
// central differences of the real solver, each dimension moved ±h and ±h/2, extrapolated by
// Richardson (R = (4·D(h/2) − D(h))/3, whose error the difference |R − D(h/2)| bounds), for a
// four-bar with a coupler point, a slider-crank, a dyadic six-bar and a six-bar Newton solves.

#include "kinematics/tune/tolerance_sensitivity.h"
#include "kinematics/design/examples.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/units.h"

#include "tests/support/catch.h"

#include <algorithm>
#include <cmath>
#include <functional>

using namespace linkwright::kinematics;

namespace {

// Every 20° of a turn, with a crank acceleration so that α's sensitivities see it.
SweepSpec grid(double stepDeg = 20.0) {
  SweepSpec spec;
  spec.fromAngle = degToRad(5.0);
  spec.toAngle = degToRad(365.0);
  spec.samples = static_cast<std::size_t>(std::lround(360.0 / stepDeg)) + 1;
  spec.omega = 2.0;
  spec.alpha = 3.0;
  return spec;
}

// The column at every sample of the linkage with dimension d moved by `offset`.
std::vector<double> moved(const Mechanism& m, const SweepSensitivities& s, std::size_t d, std::size_t c,
                          const SweepSpec& spec, double offset) {
  std::vector<double> offsets(s.dimensions.size(), 0.0);
  offsets[d] = offset;
  const SweepResult r = sweep(offsetDimensions(m, s.dimensions, offsets), spec).value();
  std::vector<double> out(r.size());
  for (std::size_t j = 0; j < r.size(); ++j)
    out[j] = toleranceColumnValue(s.columns[c], r, j, s.columns[c].value(s.sweep, j));
  return out;
}

// Checks every column's derivative with respect to every dimension at every sample against
// Richardson's extrapolation of central differences; returns how many were compared.
std::size_t checkAgainstRichardson(const Mechanism& m, const SweepSpec& spec, double h) {
  const SweepSensitivities s = sweepSensitivities(m, spec).value();
  REQUIRE(!s.dimensions.empty());
  REQUIRE(!s.columns.empty());
  std::size_t compared = 0;
  for (std::size_t d = 0; d < s.dimensions.size(); ++d) {
    for (std::size_t c = 0; c < s.columns.size(); ++c) {
      const auto plus = moved(m, s, d, c, spec, h), minus = moved(m, s, d, c, spec, -h);
      const auto plusHalf = moved(m, s, d, c, spec, h / 2), minusHalf = moved(m, s, d, c, spec, -h / 2);
      double scale = 0.0;  // the column's size, for the round-off floor
      for (std::size_t j = 0; j < s.sweep.size(); ++j) scale = std::max(scale, std::abs(plus[j]));
      for (std::size_t j = 0; j < s.sweep.size(); ++j) {
        const double exact = s.derivative[c][d][j];
        REQUIRE(std::isfinite(exact));
        const double coarse = (plus[j] - minus[j]) / (2 * h);
        const double fine = (plusHalf[j] - minusHalf[j]) / h;
        const double richardson = (4 * fine - coarse) / 3;
        const double estimate = std::abs(richardson - fine);
        const double roundOff = 1e-9 * scale / h;
        INFO(s.columns[c].name << " by " << s.dimensions[d].name << " at sample " << j << ": exact " << exact
                               << ", Richardson " << richardson << " ± " << estimate);
        CHECK(std::abs(exact - richardson) <= estimate + roundOff);
        ++compared;
      }
    }
  }
  return compared;
}

Mechanism example(const std::string& name) { return findExample(name).value().mechanism; }

}  // namespace

TEST_CASE("a four-bar's sensitivities, coupler point and rates included, are Richardson's limit of central differences",
          "[tolerance][sensitivity]") {
  const Mechanism m = makeFourBar(kThesisCrankRocker, Branch::Open, "mm", CouplerPointSpec{35.0, 20.0}).value();
  const SweepSensitivities s = sweepSensitivities(m, grid()).value();
  // Frame, crank, coupler, rocker lengths, O2's x and y, O4 across the frame line, P's two offsets.
  std::vector<std::string> names;
  for (const auto& d : s.dimensions) names.push_back(d.name);
  CHECK(names == std::vector<std::string>{"frame length", "crank length", "coupler length", "rocker length", "O2 x",
                                          "O2 y", "O4 across the frame line", "P along its link", "P across its link"});
  CHECK(checkAgainstRichardson(m, grid(), 0.01) > 1000);
}

TEST_CASE("a slider-crank's sensitivities are Richardson's limit of central differences", "[tolerance][sensitivity]") {
  const Mechanism m = example("ls3-engine");
  CHECK(checkAgainstRichardson(m, grid(), 0.01) > 100);
}

TEST_CASE("a six-bar's sensitivities are Richardson's limit of central differences", "[tolerance][sensitivity]") {
  CHECK(checkAgainstRichardson(example("watt-ii"), grid(30.0), 0.01) > 1000);
}

TEST_CASE("a six-bar that Newton solves has sensitivities that are Richardson's limit of central differences",
          "[tolerance][sensitivity]") {
  CHECK(checkAgainstRichardson(example("stephenson-ii"), grid(45.0), 0.01) > 100);
}

TEST_CASE("a dimension the outputs do not depend on has zero sensitivity, and the first-order worst case sums them",
          "[tolerance][sensitivity]") {
  const Mechanism m = makeFourBar(kThesisCrankRocker, Branch::Open, "mm", CouplerPointSpec{35.0, 20.0}).value();
  const SweepSensitivities s = sweepSensitivities(m, grid()).value();
  const auto column = [&](const std::string& name) {
    return static_cast<std::size_t>(
        std::find_if(s.columns.begin(), s.columns.end(), [&](const SweepColumn& c) { return c.name == name; }) -
        s.columns.begin());
  };
  const auto dimension = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find_if(s.dimensions.begin(), s.dimensions.end(),
                                                 [&](const ToleranceDimension& d) { return d.name == name; }) -
                                    s.dimensions.begin());
  };
  // The rocker's angle does not depend on where P sits on the coupler. O2's x and the frame's
  // length (O4 along the frame line, here +x) together move the whole linkage along x: P's x
  // one for one, its y and every angle not at all.
  CHECK(s.largest(column("rocker_angle_deg"), dimension("P along its link")) == 0.0);
  const auto alongX = [&](const std::string& name, std::size_t j) {
    return s.derivative[column(name)][dimension("O2 x")][j] + s.derivative[column(name)][dimension("frame length")][j];
  };
  for (std::size_t j = 0; j < s.sweep.size(); ++j) {
    CHECK(alongX("P_x_mm", j) == Approx(1.0).margin(1e-12));
    CHECK(alongX("P_y_mm", j) == Approx(0.0).margin(1e-12));
    CHECK(alongX("coupler_angle_deg", j) == Approx(0.0).margin(1e-12));
    CHECK(alongX("rocker_alpha_rad_s2", j) == Approx(0.0).margin(1e-12));
    CHECK(s.derivative[column("P_x_mm")][dimension("O2 x")][j] != Approx(1.0).margin(1e-3));  // O2 alone is not
  }
  std::size_t at = 0;
  const double worst = s.firstOrderWorst(column("P_y_mm"), std::vector<double>(s.dimensions.size(), 0.1), &at);
  double sum = 0.0;
  for (std::size_t d = 0; d < s.dimensions.size(); ++d) sum += std::abs(s.derivative[column("P_y_mm")][d][at]) * 0.1;
  CHECK(worst == Approx(sum).epsilon(1e-14));
  CHECK(worst > 0.1);  // at least O2's own y
}

TEST_CASE("the sensitivities' summary, folded window by window, is the whole grid's largest and first-order worst",
          "[tolerance][sensitivity][windows]") {
  for (const Mechanism& m : {makeFourBar(kThesisCrankRocker, Branch::Open, "mm", CouplerPointSpec{35.0, 20.0}).value(),
                             example("watt-ii")}) {
    SweepSpec spec;
    spec.toAngle = 2.0 * kPi;
    spec.samples = 361;
    spec.omega = 2.0;
    spec.alpha = 1.0;
    const SweepSensitivities whole = sweepSensitivities(m, spec).value();
    std::vector<double> tolerances;
    for (std::size_t d = 0; d < whole.dimensions.size(); ++d)
      tolerances.push_back(0.01 * static_cast<double>(1 + d % 3));
    for (const std::size_t window : {std::size_t{1}, std::size_t{7}, std::size_t{1000}}) {
      CAPTURE(window);
      std::size_t reported = 0;
      RunControl control;
      control.progress = [&](std::size_t done, std::size_t total) {
        CHECK(total == 361);
        CHECK(done > reported);
        reported = done;
      };
      const SensitivitySummary s = sensitivitySummary(m, spec, tolerances, control, window).value();
      CHECK(reported == 361);
      CHECK(s.inputs == 361);
      REQUIRE(s.columns.size() == whole.columns.size());
      for (std::size_t c = 0; c < s.columns.size(); ++c) {
        std::size_t at = 0;
        CHECK(s.sampledFirstOrderWorst[c] == whole.firstOrderWorst(c, tolerances, &at));
        CHECK(s.firstOrderWorstAt[c] == at);
        CHECK(s.firstOrderWorst[c] >= s.sampledFirstOrderWorst[c]);
        for (std::size_t d = 0; d < s.dimensions.size(); ++d) {
          CHECK(s.sampledLargest[c][d] == whole.largest(c, d));
          CHECK(s.largest[c][d] >= s.sampledLargest[c][d]);
        }
      }
    }
  }
}

// A peak on a fine grid made exact to O(h⁴): the vertex of the parabola through the grid's
// value `at` (sample j of `fine`) and its neighbours, `value` of a sweep of those three inputs.
double vertexAt(const Mechanism& m, const SweepSpec& fine, std::size_t j,
                const std::function<double(const SweepSensitivities&, std::size_t)>& value) {
  const double h = sweepAngle(fine, 1) - sweepAngle(fine, 0);
  SweepSpec three = fine;
  three.fromAngle = sweepAngle(fine, j) - h;
  three.toAngle = sweepAngle(fine, j) + h;
  three.samples = 3;
  const SweepSensitivities s = sweepSensitivities(m, three).value();
  const double a = value(s, 0), b = value(s, 1), c = value(s, 2), curvature = a - 2.0 * b + c;
  return curvature < 0.0 ? b - (c - a) * (c - a) / (8.0 * curvature) : b;
}

// The first-order worst case and each largest |∂y/∂p| are the curve's, not its grid's: refined
// between 37 grid inputs they equal the peak on a grid 10,000 times as fine, made exact by a
// parabola through its three samples there, to 1e-9; the worst is that at the place it names;
// the grid's inputs alone fall short by up to a few per cent. The grid runs 5° to 365°, so a
// worst near the turn's ends is placed back inside it.
TEST_CASE("the first-order worst case and the largest sensitivities are refined between the grid's inputs",
          "[tolerance][sensitivity]") {
  for (const Mechanism& m : {makeFourBar(kThesisCrankRocker, Branch::Open, "mm", CouplerPointSpec{35.0, 20.0}).value(),
                             example("watt-ii")}) {
    const SweepSpec spec = grid(10.0);
    SweepSpec fine = spec;
    fine.samples = 10'000 * (spec.samples - 1) + 1;
    const std::vector<double> tolerances(toleranceDimensions(m).size(), 0.05);
    const SensitivitySummary s = sensitivitySummary(m, spec, tolerances).value();
    const SensitivitySummary dense = sensitivitySummary(m, fine, tolerances).value();
    bool gained = false, largestGained = false;
    for (std::size_t c = 0; c < s.columns.size(); ++c) {
      CAPTURE(s.columns[c].name);
      if (s.sampledFirstOrderWorst[c] == 0.0) continue;  // the driver's own ω and α
      const double worst =
          vertexAt(m, fine, dense.firstOrderWorstAt[c],
                   [&](const SweepSensitivities& x, std::size_t j) { return x.firstOrderDeviation(c, j, tolerances); });
      CHECK(std::abs(s.firstOrderWorst[c] - worst) <= 1e-9 * worst);
      // The place: the deviation there, a sweep of that one input, is the worst (a place is not
      // compared with the dense grid's, since a column may peak twice alike: B's x at 0° and 180°).
      SweepSpec there = spec;
      there.fromAngle = there.toAngle = degToRad(s.firstOrderWorstInput[c]);
      there.samples = 1;
      const double atPlace = sweepSensitivities(m, there).value().firstOrderDeviation(c, 0, tolerances);
      CHECK(std::abs(atPlace - worst) <= 1e-9 * worst);
      CHECK(s.firstOrderWorstInput[c] >= 5.0);
      CHECK(s.firstOrderWorstInput[c] <= 365.0);
      CHECK(s.firstOrderWorst[c] >= s.sampledFirstOrderWorst[c]);
      gained = gained || s.firstOrderWorst[c] > s.sampledFirstOrderWorst[c] * (1.0 + 1e-3);
      // Each dimension's largest |∂y/∂p| likewise.
      for (std::size_t d = 0; d < s.dimensions.size(); ++d) {
        CAPTURE(s.dimensions[d].name);
        const double largest =
            vertexAt(m, fine, dense.largestAt[c][d],
                     [&](const SweepSensitivities& x, std::size_t j) { return std::abs(x.derivative[c][d][j]); });
        CHECK(std::abs(s.largest[c][d] - largest) <= 1e-9 * largest);
        CHECK(s.largest[c][d] >= s.sampledLargest[c][d]);
        largestGained = largestGained || s.largest[c][d] > s.sampledLargest[c][d] * (1.0 + 1e-3);
      }
    }
    CHECK(largestGained);
    CHECK(gained);  // the grid's inputs alone would have failed the check above
  }
}
