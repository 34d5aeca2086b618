// The Monte-Carlo tolerance study (kinematics/tune/tolerance_monte_carlo.h): every sampled
// curve, rebuilt alone from its seed and index and swept again, lies in the band, which it
// reaches; the worst deviation is the samples' own; a seed repeats and another seed differs;
// for a small tolerance each sample's deviation is the sensitivities' first-order prediction
// and the worst stays within the first-order worst case; failed samples are counted; bad
// specs are refused with the field and the range named.

#include "kinematics/tune/tolerance_monte_carlo.h"
#include "kinematics/design/examples.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/units.h"
#include "kinematics/tune/tolerance_sensitivity.h"

#include "tests/support/catch.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

using namespace linkwright::kinematics;

namespace {

SweepSpec grid(std::size_t samples) {
  SweepSpec spec;
  spec.toAngle = 2.0 * kPi;
  spec.samples = samples;
  spec.omega = 2.0;
  spec.alpha = 1.0;
  return spec;
}

Mechanism thesisWithP() {
  return makeFourBar(kThesisCrankRocker, Branch::Open, "mm", CouplerPointSpec{35.0, 20.0}).value();
}

// Sweeps each sample again from its offsets alone and checks it against the bands.
void checkBandsHoldEverySample(const Mechanism& m, const SweepSpec& spec, const MonteCarloResult& r) {
  std::vector<double> worst(r.bands.size(), 0.0);
  std::vector<std::vector<double>> low(r.bands.size()), high(r.bands.size());
  for (std::size_t b = 0; b < r.bands.size(); ++b) {
    low[b].assign(spec.samples, std::numeric_limits<double>::infinity());
    high[b].assign(spec.samples, -std::numeric_limits<double>::infinity());
  }
  std::size_t used = 0;
  for (std::size_t k = 0; k < r.spec.samples; ++k) {
    const std::vector<double> tolerances = dimensionTolerances(r.spec, r.dimensions);
    const auto offsets = toleranceSampleOffsets(r.spec, tolerances, k);
    for (std::size_t d = 0; d < offsets.size(); ++d) REQUIRE(std::abs(offsets[d]) <= tolerances[d]);
    const SweepResult s = sweep(offsetDimensions(m, r.dimensions, offsets), spec).value();
    if (!std::all_of(s.report.begin(), s.report.end(), [](const auto& p) { return p.status == PoseStatus::Ok; }))
      continue;
    ++used;
    for (std::size_t b = 0; b < r.bands.size(); ++b) {
      const ToleranceBand& band = r.bands[b];
      for (std::size_t j = 0; j < s.size(); ++j) {
        const double v = toleranceColumnValue(band.column, s, j, band.nominal[j]);
        INFO(band.column.name << " sample " << k << " at " << j);
        CHECK(v >= band.low[j]);
        CHECK(v <= band.high[j]);
        low[b][j] = std::min(low[b][j], v);
        high[b][j] = std::max(high[b][j], v);
        worst[b] = std::max(worst[b], std::abs(v - band.nominal[j]));
      }
    }
  }
  CHECK(used == r.used);
  for (std::size_t b = 0; b < r.bands.size(); ++b) {
    INFO(r.bands[b].column.name);
    CHECK(r.bands[b].low == low[b]);  // the band is the samples' own envelope, not wider
    CHECK(r.bands[b].high == high[b]);
    CHECK(r.bands[b].sampledWorstDeviation == worst[b]);  // on the grid: the samples' own worst
    CHECK(r.bands[b].worstDeviation >= worst[b]);         // refined between the grid's inputs
  }
}

std::size_t band(const MonteCarloResult& r, const std::string& name) {
  for (std::size_t b = 0; b < r.bands.size(); ++b)
    if (r.bands[b].column.name == name) return b;
  FAIL("no column " << name);
  return 0;
}

}  // namespace

TEST_CASE("the Monte-Carlo band holds every sampled curve of a four-bar and of a six-bar, and is their envelope",
          "[tolerance][monte-carlo]") {
  for (const Mechanism& m : {thesisWithP(), findExample("watt-ii")->mechanism}) {
    const SweepSpec spec = grid(37);
    const MonteCarloResult r = toleranceMonteCarlo(m, spec, {0.5, 60, 7}).value();
    CHECK(r.used == 60);
    CHECK(r.bands.size() == toleranceColumns(m).size());
    checkBandsHoldEverySample(m, spec, r);
  }
}

TEST_CASE("the same seed gives the same study and another seed another", "[tolerance][monte-carlo]") {
  const Mechanism m = findExample("ls3-engine")->mechanism;
  const auto a = toleranceMonteCarlo(m, grid(25), {0.2, 40, 1}).value();
  const auto b = toleranceMonteCarlo(m, grid(25), {0.2, 40, 1}).value();
  const auto c = toleranceMonteCarlo(m, grid(25), {0.2, 40, 2}).value();
  for (std::size_t i = 0; i < a.bands.size(); ++i) {
    CHECK(a.bands[i].low == b.bands[i].low);
    CHECK(a.bands[i].worstDeviation == b.bands[i].worstDeviation);
  }
  const std::size_t piston = band(a, "C_x_mm");
  CHECK(a.bands[piston].worstDeviation != c.bands[piston].worstDeviation);
  CHECK(a.bands[piston].low != c.bands[piston].low);
}

TEST_CASE(
    "for a small tolerance each sample deviates as the sensitivities predict, and the worst stays within the "
    "first-order worst case",
    "[tolerance][monte-carlo]") {
  const Mechanism m = thesisWithP();
  const SweepSpec spec = grid(73);
  const double t = 1e-3;
  const MonteCarloResult r = toleranceMonteCarlo(m, spec, {t, 200, kDefaultToleranceSeed}).value();
  const SweepSensitivities s = sweepSensitivities(m, spec).value();
  REQUIRE(s.columns.size() == r.bands.size());
  for (std::size_t c = 0; c < s.columns.size(); ++c) {
    const double firstOrder = s.firstOrderWorst(c, std::vector<double>(s.dimensions.size(), t));
    INFO(s.columns[c].name << ": Monte Carlo " << r.bands[c].worstDeviation << ", first order " << firstOrder);
    CHECK(r.bands[c].worstDeviation <= firstOrder * (1 + 1e-3));
    // 200 corners of a 9-dimensional box reach a good part of the furthest one (the crank's
    // ω and α are the driver's: no deviation, round-off in the first order).
    CHECK(r.bands[c].worstDeviation >= 0.4 * firstOrder - 1e-12);
  }
  // Each sample's deviation is Σ ∂y/∂p·δp to second order in t.
  const std::size_t py = band(r, "P_y_mm");
  for (std::size_t k = 0; k < 20; ++k) {
    const auto offsets = toleranceSampleOffsets(r.spec, dimensionTolerances(r.spec, r.dimensions), k);
    const SweepResult sample = sweep(offsetDimensions(m, r.dimensions, offsets), spec).value();
    for (std::size_t j = 0; j < sample.size(); ++j) {
      double predicted = 0.0;
      for (std::size_t d = 0; d < offsets.size(); ++d) predicted += s.derivative[py][d][j] * offsets[d];
      const double actual = s.columns[py].value(sample, j) - r.bands[py].nominal[j];
      CHECK(actual ==
            Approx(predicted).margin(1e-3 * s.firstOrderWorst(py, std::vector<double>(s.dimensions.size(), t))));
    }
  }
}

TEST_CASE("a study run in shards of samples has the one run's bands to the last bit", "[tolerance][monte-carlo]") {
  // ± 4 mm: some samples fail, so the counts are checked too.
  const Mechanism m = thesisWithP();
  const auto whole = toleranceMonteCarlo(m, grid(37), {4.0, 90, 5}).value();
  const auto first = toleranceMonteCarlo(m, grid(37), {4.0, 50, 5, 0}).value();
  const auto second = toleranceMonteCarlo(m, grid(37), {4.0, 40, 5, 50}).value();
  CHECK(first.used + second.used == whole.used);
  CHECK(first.notAssembled + second.notAssembled == whole.notAssembled);
  CHECK(whole.notAssembled > 0);
  for (std::size_t b = 0; b < whole.bands.size(); ++b) {
    const ToleranceBand &w = whole.bands[b], &x = first.bands[b], &y = second.bands[b];
    CAPTURE(w.column.name);
    for (std::size_t j = 0; j < w.low.size(); ++j) {
      CHECK(w.low[j] == std::min(x.low[j], y.low[j]));
      CHECK(w.high[j] == std::max(x.high[j], y.high[j]));
    }
    // The worst is that of the linkage whose worst on the grid is the larger, refined alike.
    const ToleranceBand& larger = y.sampledWorstDeviation > x.sampledWorstDeviation ? y : x;
    CHECK(w.sampledWorstDeviation == larger.sampledWorstDeviation);
    CHECK(w.worstLinkage == larger.worstLinkage);
    CHECK(w.worstDeviation == larger.worstDeviation);
    CHECK(w.worstInput == larger.worstInput);
  }
  // The second shard differs from the first 40 samples: its indices are its own.
  const auto early = toleranceMonteCarlo(m, grid(37), {4.0, 40, 5, 0}).value();
  CHECK(early.bands[band(early, "P_x_mm")].low != second.bands[band(second, "P_x_mm")].low);
}

TEST_CASE("a dimension with a tolerance of its own moves within it, the others within the common one",
          "[tolerance][monte-carlo]") {
  const Mechanism m = thesisWithP();
  MonteCarloSpec spec{0.5, 40, 9};
  spec.perDimension = {{"coupler length", 2.0}, {"O2 x", 0.0}};
  const MonteCarloResult r = toleranceMonteCarlo(m, grid(37), spec).value();
  const std::vector<double> t = dimensionTolerances(spec, r.dimensions);
  const MonteCarloSpec common{0.5, 40, 9};
  const std::vector<double> t0 = dimensionTolerances(common, r.dimensions);
  for (std::size_t d = 0; d < r.dimensions.size(); ++d) {
    const std::string& name = r.dimensions[d].name;
    CHECK(t[d] == (name == "coupler length" ? 2.0 : name == "O2 x" ? 0.0 : 0.5));
    CHECK(t0[d] == 0.5);
  }
  for (std::size_t k = 0; k < spec.samples; ++k) {
    // The same uniform draws, each scaled by its dimension's ±.
    const auto own = toleranceSampleOffsets(spec, t, k), plain = toleranceSampleOffsets(common, t0, k);
    for (std::size_t d = 0; d < t.size(); ++d) {
      CHECK(std::abs(own[d]) <= t[d]);
      CHECK(own[d] == plain[d] / 0.5 * t[d]);
    }
  }
  checkBandsHoldEverySample(m, grid(37), r);
  // The first-order bound weighs each derivative by its own ±.
  const SweepSensitivities s = sweepSensitivities(m, grid(37)).value();
  const std::size_t py = band(r, "P_y_mm");
  double sum = 0.0;
  for (std::size_t d = 0; d < t.size(); ++d) sum += std::abs(s.derivative[py][d][5]) * t[d];
  CHECK(s.firstOrderDeviation(py, 5, t) == sum);
  CHECK(s.firstOrderDeviation(py, 5, t) != s.firstOrderDeviation(py, 5, t0));
}

TEST_CASE("a tolerance of its own is refused for a dimension the linkage lacks, twice, or beyond its length",
          "[tolerance][monte-carlo]") {
  const Mechanism m = thesisWithP();
  const auto message = [&](std::vector<DimensionTolerance> own) {
    MonteCarloSpec spec{0.1, 10, 1};
    spec.perDimension = std::move(own);
    const auto r = toleranceMonteCarlo(m, grid(13), spec);
    REQUIRE_FALSE(r.ok());
    return r.error().field + ": " + r.error().message;
  };
  CHECK(message({{"crank", 0.1}}) ==
        "perDimension[0]: no dimension is named 'crank' (this linkage's: frame length, crank length, coupler length, "
        "rocker length, O2 x, O2 y, O4 across the frame line, P along its link, P across its link)");
  CHECK(message({{"crank length", 0.1}, {"crank length", 0.2}}) ==
        "perDimension[1]: crank length is given a tolerance twice");
  CHECK(message({{"crank length", 25.0}}) ==
        "perDimension[0]: the tolerance of crank length must be finite, at least 0 and less than the length "
        "(25 mm) (got 25 mm)");
  CHECK(message({{"O2 x", -1.0}}) == "perDimension[0]: the tolerance of O2 x must be finite, at least 0 (got -1 mm)");
}

TEST_CASE("samples that do not assemble are counted and left out of the band", "[tolerance][monte-carlo]") {
  // 60/25/70/45 turns fully by 10 mm of Grashof margin: ± 4 mm on four lengths can take it away.
  const MonteCarloResult r = toleranceMonteCarlo(thesisWithP(), grid(73), {4.0, 200, 3}).value();
  CHECK(r.notAssembled > 0);
  CHECK(r.used > 0);
  CHECK(r.used + r.notAssembled + r.singular == 200);
}

TEST_CASE("a bad tolerance or sample count is refused with its field and range", "[tolerance][monte-carlo]") {
  const Mechanism m = thesisWithP();
  const auto message = [&](MonteCarloSpec spec) {
    const auto r = toleranceMonteCarlo(m, grid(13), spec);
    REQUIRE_FALSE(r.ok());
    return r.error().field + ": " + r.error().message;
  };
  CHECK(message({-0.1, 10, 1}) ==
        "tolerance: tolerance must be finite, at least 0 and less than the shortest length (crank length, 25 mm) "
        "(got -0.1 mm)");
  CHECK(message({std::numeric_limits<double>::quiet_NaN(), 10, 1}) ==
        "tolerance: tolerance must be finite, at least 0 and less than the shortest length (crank length, 25 mm) "
        "(got undefined)");
  CHECK(message({25.0, 10, 1}).find("(got 25 mm)") != std::string::npos);
  CHECK(message({0.1, 0, 1}) == "samples: samples must be between 1 and 100000 (got 0)");
  CHECK(message({0.1, kMaxToleranceSamples + 1, 1}) == "samples: samples must be between 1 and 100000 (got 100001)");
  CHECK(message({0.1, 10, 1, kMaxToleranceFirstSample + 1}) ==
        "firstSample: firstSample must be between 0 and 9007199254740992 (got 9007199254740993)");
  CHECK(toleranceMonteCarlo(m, grid(13), {0.0, 3, 1}).value().bands[0].worstDeviation == 0.0);
}

// The worst deviation is the worst linkage's own, not its grid's: refined between the 37 grid
// inputs it equals the largest deviation of that linkage, rebuilt from its seed and index, on a
// grid 10,000 times as fine (whose own sampling error there is below 1e-9), where the grid's
// inputs alone fall short by up to a few per cent.
TEST_CASE("the Monte Carlo's worst deviation is refined between the grid's inputs", "[tolerance][monte-carlo]") {
  for (const Mechanism& m : {thesisWithP(), findExample("watt-ii")->mechanism}) {
    const SweepSpec spec = grid(37);
    const MonteCarloResult r = toleranceMonteCarlo(m, spec, {0.5, 20, 7}).value();
    SweepSpec fine = spec;
    fine.samples = 10'000 * (spec.samples - 1) + 1;
    const SweepResult nominal = sweep(m, fine).value();
    bool gained = false;
    for (const ToleranceBand& band : r.bands) {
      CAPTURE(band.column.name);
      if (band.sampledWorstDeviation == 0.0) continue;  // the driver's own ω and α
      const auto offsets = toleranceSampleOffsets(r.spec, dimensionTolerances(r.spec, r.dimensions),
                                                  static_cast<std::size_t>(band.worstLinkage));
      const SweepResult s = sweep(offsetDimensions(m, r.dimensions, offsets), fine).value();
      double dense = 0.0;
      double denseAt = 0.0;
      for (std::size_t j = 0; j < s.size(); ++j) {
        const double v0 = band.column.value(nominal, j);
        const double d = std::abs(toleranceColumnValue(band.column, s, j, v0) - v0);
        if (d > dense) {
          dense = d;
          denseAt = radToDeg(sweepAngle(fine, j));
        }
      }
      CHECK(std::abs(band.worstDeviation - dense) <= 1e-9 * dense);
      // Degrees, the same place a turn apart when both are at the ends of the turn.
      CHECK(std::abs(std::remainder(band.worstInput - denseAt, 360.0)) <= 1e-3);
      CHECK(band.worstInput >= 0.0);
      CHECK(band.worstInput <= 360.0);
      CHECK(band.worstDeviation >= band.sampledWorstDeviation);
      gained = gained || band.worstDeviation > band.sampledWorstDeviation * (1.0 + 1e-3);
    }
    CHECK(gained);  // the grid's inputs alone would have failed the check above
  }
}

TEST_CASE("a study without the band reads the grid in windows and has the whole study's figures to the last bit",
          "[tolerance][monte-carlo][windows]") {
  // ± 4 mm on the four-bar: some samples fail part-way round, after windows already read.
  struct Case {
    Mechanism m;
    double t;
    std::size_t inputs, window;
  };
  const std::vector<Case> cases{{thesisWithP(), 4.0, 1001, 7},
                                {findExample("watt-ii")->mechanism, 0.5, 361, 100},
                                // Above kNominalCacheValues: the nominal swept again beside each sample.
                                {thesisWithP(), 0.5, 100'000, 4096}};
  for (const Case& c : cases) {
    CAPTURE(c.inputs, c.window);
    const std::size_t samples = c.inputs > 10'000 ? 3 : 90;
    const MonteCarloResult whole = toleranceMonteCarlo(c.m, grid(c.inputs), {c.t, samples, 5}).value();
    MonteCarloSpec streamed{c.t, samples, 5};
    streamed.band = false;
    const MonteCarloResult windows = toleranceMonteCarlo(c.m, grid(c.inputs), streamed, {}, c.window).value();
    CHECK(windows.inputs == c.inputs);
    CHECK(windows.nominal.size() == 0);
    CHECK(windows.used == whole.used);
    CHECK(windows.notAssembled == whole.notAssembled);
    CHECK(windows.singular == whole.singular);
    REQUIRE(windows.bands.size() == whole.bands.size());
    for (std::size_t b = 0; b < whole.bands.size(); ++b) {
      CAPTURE(whole.bands[b].column.name);
      CHECK(windows.bands[b].low.empty());
      CHECK(windows.bands[b].worstDeviation == whole.bands[b].worstDeviation);
      CHECK(windows.bands[b].worstGridSample == whole.bands[b].worstGridSample);
    }
  }
  const MonteCarloResult failing = toleranceMonteCarlo(thesisWithP(), grid(1001), {4.0, 90, 5}).value();
  CHECK(failing.notAssembled > 0);
}

TEST_CASE("a band kept whole is bounded, and refused beyond it naming the inputs and the bound",
          "[tolerance][monte-carlo][windows]") {
  const Mechanism m = thesisWithP();
  const std::size_t columns = toleranceColumns(m).size();
  CHECK(maxToleranceBandInputs(m) == kMaxToleranceBandValues / columns);
  const auto r = toleranceMonteCarlo(m, grid(10'000'000), {0.05, 10, 1});
  REQUIRE_FALSE(r);
  CHECK(r.error().field == "band");
  CHECK(r.error().message == "a band kept at every input holds " + std::to_string(columns) +
                                 " columns' nominal, lowest and highest values there: at most " +
                                 std::to_string(kMaxToleranceBandValues / columns) +
                                 " inputs for this linkage (got 10000000)");
}

TEST_CASE("a study reports its progress in samples and stops when cancelled", "[tolerance][monte-carlo]") {
  const Mechanism m = thesisWithP();
  std::vector<std::size_t> done;
  RunControl control;
  control.progress = [&](std::size_t k, std::size_t total) {
    CHECK(total == 25);
    done.push_back(k);
  };
  REQUIRE(toleranceMonteCarlo(m, grid(37), {0.1, 25, 1}, control));
  CHECK(done.size() == 25);
  CHECK(done.back() == 25);
  std::atomic<bool> cancel{false};
  control.cancel = &cancel;
  control.progress = [&](std::size_t k, std::size_t) {
    if (k == 3) cancel = true;
  };
  const auto stopped = toleranceMonteCarlo(m, grid(37), {0.1, 25, 1}, control);
  REQUIRE_FALSE(stopped);
  CHECK(stopped.error().code == ErrorCode::Cancelled);
}

TEST_CASE("the band's Monte-Carlo error is the order statistics': 2/(n+1) outside it, checked on a closed form",
          "[tolerance][monte-carlo][error]") {
  // Only O2 x toleranced (± t): the crank tip B's x is the nominal's plus O2's offset, uniform in
  // ±t, exactly. So at every input the band of n samples is [min, max] of n uniform offsets and
  // the fraction of all linkages outside it is 1 − (max − min)/(2t), with mean 2/(n + 1).
  const Mechanism m = thesisWithP();
  const double t = 0.5;
  const std::size_t n = 19, studies = 400;
  MonteCarloSpec spec{0.0, n, 0};
  spec.perDimension = {{"O2 x", t}};
  double outside = 0.0;
  std::size_t beyondBound = 0;
  std::size_t tip = 0;
  for (std::size_t s = 0; s < studies; ++s) {
    spec.seed = 1000 + s;
    const MonteCarloResult r = toleranceMonteCarlo(m, grid(5), spec).value();
    REQUIRE(r.used == n);
    if (s == 0) tip = band(r, "B_x_mm");
    const ToleranceBand& b = r.bands[tip];
    const double fraction = 1.0 - (b.high[2] - b.low[2]) / (2.0 * t);
    CHECK(fraction == Approx(1.0 - (b.high[0] - b.low[0]) / (2.0 * t)).margin(1e-9));  // the same at every input
    outside += fraction / studies;
    beyondBound += fraction > r.error.outsideBandBound ? 1 : 0;
    CHECK(r.error.samples == n);
    CHECK(r.error.outsideBand == Approx(2.0 / (n + 1)));
  }
  // The fraction outside the range of n draws is Beta(2, n − 1): mean 2/(n+1), variance
  // 2(n−1)/((n+1)²(n+2)); the mean of 400 within 4 standard errors.
  const double sd = std::sqrt(2.0 * (n - 1) / ((n + 1.0) * (n + 1.0) * (n + 2.0)) / studies);
  CHECK(std::abs(outside - 2.0 / (n + 1)) < 4 * sd);
  // The 95 % bound is exceeded by about 5 % of the studies (binomial: 20 ± 4.4).
  CHECK(beyondBound >= 8);
  CHECK(beyondBound <= 33);
  // The bounds' closed forms: for n = 19, 1 − 0.05^(1/19) beyond the worst, and the range's
  // coverage CDF n·yⁿ⁻¹ − (n − 1)·yⁿ at 1 − bound is 0.05.
  const MonteCarloError e = monteCarloError(19);
  CHECK(e.beyondWorst == Approx(1.0 / 20));
  CHECK(e.beyondWorstBound == Approx(1.0 - std::pow(0.05, 1.0 / 19)));
  const double y = 1.0 - e.outsideBandBound;
  CHECK(19 * std::pow(y, 18) - 18 * std::pow(y, 19) == Approx(0.05).margin(1e-12));
  // Samples for a chosen accuracy: the least n whose bound is within it.
  for (const double fraction : {0.1, 0.01, 0.001}) {
    const std::size_t needed = toleranceSamplesFor(fraction);
    CAPTURE(fraction, needed);
    CHECK(monteCarloError(needed).outsideBandBound <= fraction);
    CHECK(monteCarloError(needed - 1).outsideBandBound > fraction);
  }
  CHECK(toleranceSamplesFor(0.01) == 473);  // ≈ 4.74/fraction for small fractions
  CHECK(monteCarloError(1).outsideBand == 1.0);
  CHECK(monteCarloError(0).beyondWorst == 1.0);
}
