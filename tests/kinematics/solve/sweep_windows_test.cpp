// Tests sweepInWindows (solve/sweep.h): a sweep delivered in windows, whose memory does not
// grow with the sample count, is the whole sweep cut into pieces, bit for bit: every column,
// report and instant, across a gap, a lock, a toggle, free points and a time base, for windows
// of one sample, an odd size and more than the sweep; its summary is the whole sweep's runs.

#include "kinematics/solve/sweep.h"

#include "kinematics/design/design.h"
#include "kinematics/design/examples.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/sixbar.h"
#include "kinematics/model/units.h"

#include "tests/support/locking_six_bar.h"

#include "tests/support/catch.h"

#include <string>
#include <vector>

using namespace linkwright::kinematics;

namespace {

// Appends window `part`'s samples to `whole`, column by column.
template <typename T>
void append(std::vector<std::vector<T>>& whole, const std::vector<std::vector<T>>& part) {
  whole.resize(part.size());
  for (std::size_t i = 0; i < part.size(); ++i) whole[i].insert(whole[i].end(), part[i].begin(), part[i].end());
}

struct Joined {
  SweepResult whole;
  std::vector<std::size_t> firsts;
  SweepSummary summary;
};

Joined joinedWindows(const Mechanism& m, const SweepSpec& spec, std::size_t window) {
  Joined j;
  auto summary = sweepInWindows(m, spec, {}, window, [&](const SweepResult& part, std::size_t first) {
    j.firsts.push_back(first);
    CHECK(first == j.whole.size());
    CHECK(part.size() <= window);
    j.whole.request = part.request;
    j.whole.time.insert(j.whole.time.end(), part.time.begin(), part.time.end());
    j.whole.inputAngle.insert(j.whole.inputAngle.end(), part.inputAngle.begin(), part.inputAngle.end());
    j.whole.report.insert(j.whole.report.end(), part.report.begin(), part.report.end());
    append(j.whole.position, part.position);
    append(j.whole.velocity, part.velocity);
    append(j.whole.acceleration, part.acceleration);
    append(j.whole.linkAngle, part.linkAngle);
    append(j.whole.linkOmega, part.linkOmega);
    append(j.whole.linkAlpha, part.linkAlpha);
    append(j.whole.transmissionAngle, part.transmissionAngle);
    return true;
  });
  REQUIRE(summary);
  j.summary = *summary;
  return j;
}

void checkSameAsWhole(const Mechanism& m, const SweepSpec& spec) {
  const auto full = sweep(m, spec);
  REQUIRE(full);
  for (const std::size_t window : {std::size_t{1}, std::size_t{7}, std::size_t{100}, spec.samples + 5}) {
    CAPTURE(window);
    const Joined j = joinedWindows(m, spec, window);
    CHECK(j.firsts.size() == (spec.samples + window - 1) / window);
    CHECK(j.whole.inputAngle == full->inputAngle);
    CHECK(j.whole.time == full->time);
    CHECK(j.whole.report == full->report);
    CHECK(j.whole.position == full->position);
    CHECK(j.whole.velocity == full->velocity);
    CHECK(j.whole.acceleration == full->acceleration);
    CHECK(j.whole.linkAngle == full->linkAngle);  // unwrapped across the windows' seams
    CHECK(j.whole.linkOmega == full->linkOmega);
    CHECK(j.whole.linkAlpha == full->linkAlpha);
    CHECK(j.whole.transmissionAngle == full->transmissionAngle);
    CHECK(j.summary.samples == full->size());
    CHECK(j.summary.notAssembled == full->notAssembled);
    CHECK(j.summary.singularAngles == full->singularAngles);
    CHECK(j.summary.lockedBetween == full->lockedBetween);
    CHECK(j.summary.firstFailure == full->firstFailure);
    std::size_t assembled = 0;
    for (std::size_t s = 0; s < full->size(); ++s) assembled += full->assembled(s) ? 1 : 0;
    CHECK(j.summary.assembledSamples == assembled);
  }
}

}  // namespace

TEST_CASE("a sweep in windows is the whole sweep, bit for bit, for every example", "[sweep][windows]") {
  for (const Example& e : examples()) {
    CAPTURE(e.name);
    const Design d = designFromExample(e);
    SweepSpec spec = designSweepSpec(d);
    // A few hundred samples keep every seam case and the test quick.
    spec.samples = std::min<std::size_t>(spec.samples, 361);
    checkSameAsWhole(d.mechanism, spec);
  }
}

TEST_CASE("windows across a gap, a lock and a toggle keep the whole sweep's runs", "[sweep][windows]") {
  // 60/25/30/45 cannot turn its crank fully: two runs of failed samples, one through 360°.
  const Mechanism rocking = *makeFourBar({60.0, 25.0, 30.0, 45.0}, Branch::Open);
  const SweepSpec turn{0.0, 2.0 * kPi, 721, 1.0, 0.0};
  checkSameAsWhole(rocking, turn);
  const auto full = sweep(rocking, turn);
  REQUIRE(full);
  REQUIRE(full->notAssembled.size() >= 1);
  // The locking six-bar in 5° steps: a lock between 290° and 295°, a toggle at 180°.
  const Mechanism locking = *makeSixBar(linkwright::test::lockingSixBar());
  const SweepSpec coarse{0.0, 2.0 * kPi, 73, 1.0, 0.0};
  const auto lockingFull = sweep(locking, coarse);
  REQUIRE(lockingFull);
  REQUIRE_FALSE(lockingFull->lockedBetween.empty());
  checkSameAsWhole(locking, coarse);
}

TEST_CASE("a reader that stops a sweep in windows stops it", "[sweep][windows]") {
  const Mechanism m = *makeFourBar({60.0, 25.0, 70.0, 45.0}, Branch::Open);
  int windows = 0;
  const auto stopped = sweepInWindows(m, {0.0, 2.0 * kPi, 1000, 1.0, 0.0}, {}, 100,
                                      [&](const SweepResult&, std::size_t) { return ++windows < 3; });
  REQUIRE_FALSE(stopped);
  CHECK(stopped.error().code == ErrorCode::Cancelled);
  CHECK(windows == 3);
  // Bad input is refused before any window.
  const auto refused = sweepInWindows(m, {0.0, 2.0 * kPi, 0, 1.0, 0.0}, {}, 100, [&](const SweepResult&, std::size_t) {
    FAIL("no window for a refused sweep");
    return true;
  });
  REQUIRE_FALSE(refused);
  CHECK(refused.error().field == "samples");
}

TEST_CASE("two sweeps read a window at a time side by side are each the whole sweep", "[sweep][windows]") {
  const Mechanism a = *makeFourBar({60.0, 25.0, 70.0, 45.0}, Branch::Open);
  const Mechanism b = *makeFourBar({60.0, 25.0, 30.0, 45.0}, Branch::Open);  // with gaps
  const SweepSpec turn{0.0, 2.0 * kPi, 721, 1.0, 0.0};
  auto ra = SweepWindows::start(a, turn, {}, 50);
  auto rb = SweepWindows::start(b, turn, {}, 50);
  REQUIRE(ra);
  REQUIRE(rb);
  SweepWindows wa = std::move(ra).value(), wb = std::move(rb).value();
  const SweepResult fa = sweep(a, turn).value(), fb = sweep(b, turn).value();
  std::size_t windows = 0;
  while (const SweepResult* pa = wa.next()) {
    const SweepResult* pb = wb.next();
    REQUIRE(pb != nullptr);
    CHECK(wa.first() == 50 * windows);
    CHECK(wb.first() == wa.first());
    for (std::size_t j = 0; j < pa->size(); ++j) {
      CHECK(pa->report[j] == fa.report[wa.first() + j]);
      CHECK(pb->report[j] == fb.report[wb.first() + j]);
      CHECK(pa->linkAngle[2][j] == fa.linkAngle[2][wa.first() + j]);
      CHECK(pb->position[3][j] == fb.position[3][wb.first() + j]);
    }
    ++windows;
  }
  CHECK(wb.next() == nullptr);
  CHECK(windows == 15);
  CHECK(wb.summary().notAssembled == fb.notAssembled);
  // A refused spec is refused before any window.
  CHECK_FALSE(SweepWindows::start(a, {0.0, 2.0 * kPi, 0, 1.0, 0.0}, {}, 50));
}
