// The document's displayed sampling and the error it states (ui/document/quality_estimate.h,
// MechanismDocument::qualityEstimate): the stated error is the core's own measurement at the
// displayed N, motion never re-measures, a width that keeps the count keeps the sweep, a
// rocking crank says why there is no figure, and the worker that measures it gives the same
// figure as the GUI thread and drops a superseded measurement.

#include "ui/document/quality_estimate.h"
#include "ui/document/mechanism_document.h"
#include "ui/document/quality_estimator.h"
#include "ui/plots/quality_bar.h"

#include "kinematics/analysis/sampling_accuracy.h"
#include "kinematics/design/design.h"
#include "kinematics/design/examples.h"

#include "tests/ui/support/four_bar_design.h"

#include "tests/support/catch.h"

#include <QSignalSpy>
#include <QTest>

#include <cmath>

using namespace linkwright;
using ui::MechanismDocument;
using ui::SamplingQuality;
namespace k = kinematics;

namespace {

k::Design tripleRocker() {
  return testing::fourBar({40.0, 30.0, 20.0, 25.0});  // non-Grashof: the crank rocks through ±78.6°
}

// What the core says the displayed samples buy, computed here independently of the document.
k::PeakError coreError(const MechanismDocument& doc) {
  const std::size_t n = ui::samplesPerRevolution(doc.displaySpec().samples, 360.0);
  const double omega = std::abs(doc.displaySpec().omega);
  const k::NewtonSettings newton{ui::qualityPreset(doc.quality()).newtonTolerance};
  const auto read = k::sampledPeaks(doc.mechanism(), omega, n, k::DerivativeMethod::Exact, newton);
  const auto exact = k::exactPeaks(doc.mechanism(), omega);
  REQUIRE(read);
  REQUIRE(exact);
  return k::peakError(*read, *exact);
}

}  // namespace

TEST_CASE("the stated error is peakError(sampledPeaks(N), exactPeaks) at the displayed N", "[ui][quality]") {
  const std::string example = GENERATE(std::string("thesis-crank-rocker"), std::string("watt-ii"));
  const SamplingQuality quality = GENERATE(SamplingQuality::Draft, SamplingQuality::Normal, SamplingQuality::Precise);
  CAPTURE(example, static_cast<int>(quality));
  MechanismDocument doc;
  doc.reset(*k::designForExample(example));
  doc.setQuality(quality);
  doc.setDisplayWidth(450.0);
  REQUIRE(doc.qualityEstimatePending());
  doc.measureQualityNow();
  REQUIRE_FALSE(doc.qualityEstimatePending());
  const ui::QualityEstimate& e = doc.qualityEstimate();
  CHECK(doc.displaySpec().samples == ui::displaySampleCount(quality, 450.0, 360.0));
  CHECK(doc.sweep().size() == doc.displaySpec().samples);
  CHECK(e.samplesPerRevolution == doc.displaySpec().samples - 1);
  REQUIRE(e.error.has_value());
  CHECK(*e.error == coreError(doc));
  CHECK(std::isfinite(e.error->worstRate()));
}

TEST_CASE("finer qualities state smaller errors on the thesis crank-rocker", "[ui][quality]") {
  MechanismDocument doc;
  doc.setDisplayWidth(450.0);
  double previous = 1.0;
  for (const SamplingQuality q : {SamplingQuality::Draft, SamplingQuality::Normal, SamplingQuality::Precise}) {
    doc.setQuality(q);
    doc.measureQualityNow();
    const double worst = doc.qualityEstimate().error->worstRate();
    CAPTURE(static_cast<int>(q), worst);
    CHECK(worst < previous);
    previous = worst;
  }
  CHECK(previous < 1e-5);  // 3600 samples per revolution: about 1e-6 (docs/accuracy.md)
}

TEST_CASE("a rocking crank gets a reason instead of a number", "[ui][quality][errors]") {
  MechanismDocument doc;
  doc.reset(tripleRocker());
  ui::QualityBar bar(&doc);
  doc.measureQualityNow();
  const ui::QualityEstimate& e = doc.qualityEstimate();
  CHECK_FALSE(e.error.has_value());
  CHECK(e.unavailable.contains(QStringLiteral("does not turn fully")));
  CHECK(e.detail.contains(QStringLiteral("must turn fully")));  // the core's sentence
  CHECK(bar.errorText().contains(QStringLiteral("not measurable")));
  for (const QString& text : {bar.errorText(), bar.costText()}) {
    CHECK_FALSE(text.contains(QStringLiteral("nan"), Qt::CaseInsensitive));
    CHECK_FALSE(text.contains(QStringLiteral("inf"), Qt::CaseInsensitive));
  }
}

TEST_CASE("the estimate is measured once changes settle, never for crank motion", "[ui][quality]") {
  MechanismDocument doc;
  doc.measureQualityNow();
  QSignalSpy spy(&doc, &MechanismDocument::changed);
  doc.setCrankAngle(1.0);
  CHECK_FALSE(doc.qualityEstimatePending());
  const k::Design d = testing::withLengths(doc.design(), {60.0, 25.0, 72.0, 45.0});
  REQUIRE_FALSE(doc.edit(d, "coupler").has_value());
  CHECK(doc.qualityEstimatePending());
  const std::size_t before = doc.qualityEstimate().samplesPerRevolution;
  // It arrives on its own after the settle time, announced as an Estimate change.
  REQUIRE(spy.wait(10 * MechanismDocument::kEstimateSettleMs));
  CHECK((spy.last().first().value<ui::Changes>() & ui::Change::Estimate));
  CHECK_FALSE(doc.qualityEstimatePending());
  CHECK(doc.qualityEstimate().samplesPerRevolution == before);
}

TEST_CASE("a width that keeps the sample count keeps the sweep", "[ui][quality]") {
  MechanismDocument doc;
  doc.setQuality(SamplingQuality::Draft);
  doc.setDisplayWidth(400.0);  // 101 samples
  REQUIRE(doc.sweep().size() == 101);
  QSignalSpy spy(&doc, &MechanismDocument::changed);
  doc.setDisplayWidth(399.0);  // ⌈99.75⌉ = 100 intervals still
  CHECK(spy.isEmpty());
  CHECK(doc.sweep().size() == 101);
  doc.setDisplayWidth(420.0);
  REQUIRE(spy.count() == 1);
  CHECK((spy.first().first().value<ui::Changes>() & ui::Change::Request));
  CHECK(doc.sweep().size() == 106);
}

TEST_CASE("the analysis keeps the design's grid whatever the displayed resolution", "[ui][quality]") {
  MechanismDocument doc;
  doc.reset(tripleRocker());
  doc.setQuality(SamplingQuality::Draft);
  doc.setDisplayWidth(100.0);  // 37 samples
  REQUIRE(doc.sweep().size() == 37);
  const k::SweepResult grid = k::sweep(doc.mechanism(), k::designSweepSpec(doc.design()), {false, false}).value();
  CHECK(doc.analysis().notAssembled == grid.notAssembled);
  // A four-bar's limits are closed form: the same at any resolution.
  const auto limits = doc.analysis().limits;
  doc.setQuality(SamplingQuality::Precise);
  CHECK(doc.analysis().limits == limits);
}

TEST_CASE("the quality's Newton tolerance reaches the sweep and the estimate", "[ui][quality]") {
  MechanismDocument doc;
  doc.reset(*k::designForExample("stephenson-ii"));  // free points, solved by Newton
  doc.setQuality(SamplingQuality::Draft);
  CHECK(doc.request().newton.tolerance == 1e-6);
  doc.setRequest({true, false});  // a plot's request carries no tolerance of its own
  CHECK(doc.request().newton.tolerance == 1e-6);
  doc.setDisplayWidth(144.0);  // 36 intervals: keeps this Debug-built test quick
  doc.measureQualityNow();
  REQUIRE(doc.qualityEstimate().error.has_value());
  CHECK(*doc.qualityEstimate().error == coreError(doc));
}

TEST_CASE("the estimate measured in a worker equals the one measured in the GUI thread", "[ui][quality][worker]") {
  MechanismDocument doc;
  doc.reset(*k::designForExample("watt-ii"));
  doc.setDisplayWidth(300.0);
  QSignalSpy spy(&doc, &MechanismDocument::changed);
  REQUIRE(doc.qualityEstimatePending());
  // The settle timer starts the worker; the document stays pending until its result lands.
  REQUIRE(spy.wait(20 * MechanismDocument::kEstimateSettleMs));
  while (doc.qualityEstimatePending()) REQUIRE(spy.wait(20 * MechanismDocument::kEstimateSettleMs));
  CHECK((spy.last().first().value<ui::Changes>() & ui::Change::Estimate));
  REQUIRE(doc.qualityEstimate().error.has_value());
  CHECK(*doc.qualityEstimate().error == coreError(doc));
}

TEST_CASE("a newer edit drops the estimate measured for the older design", "[ui][quality][worker]") {
  ui::QualityEstimator estimator;
  QSignalSpy measured(&estimator, &ui::QualityEstimator::measured);
  const k::Mechanism older = k::designForExample("watt-ii")->mechanism;
  const k::Mechanism newer = testing::fourBar({60.0, 25.0, 72.0, 45.0}).mechanism;
  estimator.start({older, 1.0, 720, {}});
  estimator.start({newer, 1.0, 360, {}});  // supersedes the first while it runs
  REQUIRE(estimator.busy());
  REQUIRE(measured.wait(20000));
  // Exactly one result lands, the newer design's, and nothing is left running.
  REQUIRE(measured.count() == 1);
  CHECK_FALSE(estimator.busy());
  const auto landed = measured.first().first().value<ui::QualityEstimate>();
  CHECK(landed.samplesPerRevolution == 360);
  const ui::QualityEstimate direct = ui::estimatePeakError(newer, 1.0, 360, {});
  REQUIRE(landed.error.has_value());
  REQUIRE(direct.error.has_value());
  CHECK(*landed.error == *direct.error);

  // Cancelled, a running measurement's result never lands.
  estimator.start({older, 1.0, 720, {}});
  estimator.cancel();
  REQUIRE(QTest::qWaitFor([&] { return !estimator.busy(); }, 20000));
  CHECK(measured.count() == 1);
}
