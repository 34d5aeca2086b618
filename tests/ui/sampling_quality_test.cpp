// ui/document/sampling_quality.h: how many samples a plot of a given width gets at each quality.

#include "ui/document/sampling_quality.h"

#include "tests/support/catch.h"

using namespace linkwright::ui;

TEST_CASE("the displayed sample count follows the plot's width and the quality, above a floor per revolution",
          "[ui][sampling]") {
  const auto [quality, widthPx, spanDeg, samples] = GENERATE(table<SamplingQuality, double, double, std::size_t>({
      {SamplingQuality::Draft, 400.0, 360.0, 101},      // 1 per 4 px
      {SamplingQuality::Draft, 401.0, 360.0, 102},      // a part-sample rounds up
      {SamplingQuality::Draft, 100.0, 360.0, 37},       // floor: 36 per revolution
      {SamplingQuality::Normal, 500.0, 360.0, 501},     // 1 per px
      {SamplingQuality::Normal, 200.0, 360.0, 361},     // floor: 360 per revolution
      {SamplingQuality::Normal, 200.0, 180.0, 201},     // the floor scales with the span...
      {SamplingQuality::Normal, 100.0, 720.0, 721},     // ...both ways
      {SamplingQuality::Precise, 500.0, 360.0, 3601},   // floor: 3600 per revolution
      {SamplingQuality::Precise, 1000.0, 360.0, 4001},  // 4 per px
  }));
  CAPTURE(static_cast<int>(quality), widthPx, spanDeg);
  CHECK(displaySampleCount(quality, widthPx, spanDeg) == samples);
}

TEST_CASE("samples per revolution scale a grid's intervals to 360°", "[ui][sampling]") {
  CHECK(samplesPerRevolution(361, 360.0) == 360);
  CHECK(samplesPerRevolution(181, 180.0) == 360);
  CHECK(samplesPerRevolution(721, 720.0) == 360);
  CHECK(samplesPerRevolution(1, 360.0) == 0);
}

TEST_CASE("the default width gives Normal the seeds' half-degree grid", "[ui][sampling]") {
  CHECK(displaySampleCount(SamplingQuality::Normal, kDefaultDisplayWidth, 360.0) == 721);
}

TEST_CASE("qualities round-trip through their settings keys, anything else reads as Normal", "[ui][sampling]") {
  for (const SamplingQuality q : {SamplingQuality::Draft, SamplingQuality::Normal, SamplingQuality::Precise})
    CHECK(qualityFromKey(qualityKey(q)) == q);
  CHECK(qualityFromKey(QStringLiteral("ultra")) == SamplingQuality::Normal);
  CHECK(qualityPreset(SamplingQuality::Draft).newtonTolerance == 1e-6);
  CHECK(qualityPreset(SamplingQuality::Normal).newtonTolerance == 1e-10);
  CHECK(qualityPreset(SamplingQuality::Precise).newtonTolerance == 1e-12);
}
