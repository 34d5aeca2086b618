// Tests ui/plots/series_data.h: which samples become points, and how gaps split the runs.
#include "ui/plots/series_data.h"

#include "kinematics/design/design.h"
#include "kinematics/model/units.h"

#include "tests/ui/support/four_bar_design.h"

#include "tests/support/catch.h"

#include <limits>

using namespace linkwright::ui;
namespace k = linkwright::kinematics;

namespace {

// A six-sample sweep by hand: statuses Ok, Ok, Singular, Ok, NotAssemblable, Ok; values
// that tell the samples apart (angle j·0.1 rad, ω 10 + j, α 100 + j) and a placeholder 0 for
// rates where the sample is not ok, as the sweep writes them.
k::SweepResult handMadeSweep() {
  using S = k::PoseStatus;
  const S status[] = {S::Ok, S::Ok, S::Singular, S::Ok, S::NotAssemblable, S::Ok};
  k::SweepResult r;
  r.request = {true, true};
  const std::size_t n = 6;
  r.linkAngle.assign(3, std::vector<double>(n, 0.0));
  r.linkOmega.assign(3, std::vector<double>(n, 0.0));
  r.linkAlpha.assign(3, std::vector<double>(n, 0.0));
  r.transmissionAngle.assign(4, {});
  r.transmissionAngle[k::fourbar::kC.index].assign(n, 0.0);
  for (std::size_t j = 0; j < n; ++j) {
    r.inputAngle.push_back(0.1 * static_cast<double>(j));
    k::PoseReport report;
    report.status = status[j];
    r.report.push_back(report);
    const bool ok = status[j] == S::Ok;
    for (std::size_t link = 0; link < 3; ++link) {
      r.linkAngle[link][j] = 0.1 * static_cast<double>(j) + static_cast<double>(link);
      r.linkOmega[link][j] = ok ? 10.0 + static_cast<double>(j) : 0.0;
      r.linkAlpha[link][j] = ok ? 100.0 + static_cast<double>(j) : 0.0;
    }
    r.transmissionAngle[k::fourbar::kC.index][j] = 1.0 + 0.01 * static_cast<double>(j);
  }
  return r;
}

QList<qsizetype> runLengths(const SeriesRuns& runs) {
  QList<qsizetype> lengths;
  for (const auto& run : runs.runs) lengths.append(run.size());
  return lengths;
}

}  // namespace

TEST_CASE("Angles are plotted wherever assembled, rates only where ok", "[series_data]") {
  const k::SweepResult sweep = handMadeSweep();
  SeriesRuns runs;
  buildSeriesRuns(sweep, PlotQuantity::RockerAngle, AngleUnit::Radians, runs);
  CHECK(runLengths(runs) == QList<qsizetype>{4, 1});  // samples 0–3, then 5
  CHECK(runs.runs[0][2] == QPointF(0.2, 2.2));        // the singular sample keeps its angle
  CHECK(runs.runs[1][0] == QPointF(0.5, 2.5));

  buildSeriesRuns(sweep, PlotQuantity::RockerOmega, AngleUnit::Radians, runs);
  CHECK(runLengths(runs) == QList<qsizetype>{2, 1, 1});  // 0–1, 3, 5: no placeholder zero
  CHECK(runs.runs[1][0] == QPointF(0.3, 13.0));
  CHECK(runs.minY == 10.0);
  CHECK(runs.maxY == 15.0);

  buildSeriesRuns(sweep, PlotQuantity::CouplerAlpha, AngleUnit::Radians, runs);
  CHECK(runs.pointCount() == 4);
  for (const auto& run : runs.runs)
    for (const QPointF& p : run) CHECK(p.y() >= 100.0);

  buildSeriesRuns(sweep, PlotQuantity::TransmissionAngle, AngleUnit::Radians, runs);
  CHECK(runs.pointCount() == 5);
}

TEST_CASE("A value that is still not finite is left out of the plot like a missing one", "[series_data]") {
  // The last guard: whatever let it through, nan or inf never becomes a point.
  k::SweepResult sweep = handMadeSweep();
  sweep.linkOmega[k::fourbar::kRocker.index][1] = std::numeric_limits<double>::quiet_NaN();
  sweep.linkAngle[k::fourbar::kRocker.index][2] = std::numeric_limits<double>::infinity();
  SeriesRuns runs;
  buildSeriesRuns(sweep, PlotQuantity::RockerOmega, AngleUnit::Radians, runs);
  CHECK(runLengths(runs) == QList<qsizetype>{1, 1, 1});  // 0, 3, 5
  CHECK(runs.maxY == 15.0);
  buildSeriesRuns(sweep, PlotQuantity::RockerAngle, AngleUnit::Radians, runs);
  CHECK(runLengths(runs) == QList<qsizetype>{2, 1, 1});  // 0–1, 3, 5
}

TEST_CASE("Degrees convert x and y, rates per second too", "[series_data]") {
  const k::SweepResult sweep = handMadeSweep();
  SeriesRuns runs;
  buildSeriesRuns(sweep, PlotQuantity::CouplerOmega, AngleUnit::Degrees, runs);
  CHECK(runs.runs[0][1].x() == Approx(k::radToDeg(0.1)));
  CHECK(runs.runs[0][1].y() == Approx(k::radToDeg(11.0)));
}

TEST_CASE("A column the sweep did not compute gives no points", "[series_data]") {
  k::SweepResult sweep = handMadeSweep();
  sweep.linkOmega.clear();
  sweep.linkAlpha.clear();
  SeriesRuns runs;
  buildSeriesRuns(sweep, PlotQuantity::RockerAngle, AngleUnit::Degrees, runs);
  REQUIRE_FALSE(runs.empty());
  buildSeriesRuns(sweep, PlotQuantity::RockerOmega, AngleUnit::Degrees, runs);
  CHECK(runs.empty());
  CHECK_FALSE(hasValue(sweep, PlotQuantity::RockerAlpha, 0));
  CHECK(hasValue(sweep, PlotQuantity::RockerAngle, 0));
}

TEST_CASE("A real sweep: every assembled sample of the default design, one run", "[series_data]") {
  const k::Design design = linkwright::testing::fourBar();
  const k::SweepResult sweep = k::sweep(design.mechanism, k::designSweepSpec(design)).value();
  SeriesRuns runs;
  buildSeriesRuns(sweep, PlotQuantity::CouplerAngle, AngleUnit::Degrees, runs);
  REQUIRE(runs.runs.size() == 1);
  REQUIRE(runs.runs[0].size() == static_cast<qsizetype>(sweep.size()));
  for (std::size_t j : {std::size_t{0}, std::size_t{180}, std::size_t{457}}) {
    CAPTURE(j);
    CHECK(runs.runs[0][static_cast<qsizetype>(j)].y() == k::radToDeg(sweep.linkAngle[k::fourbar::kCoupler.index][j]));
  }
}
