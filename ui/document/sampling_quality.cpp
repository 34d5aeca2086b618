#include "ui/document/sampling_quality.h"

#include <algorithm>
#include <cmath>

namespace linkwright::ui {

QualityPreset qualityPreset(SamplingQuality quality) {
  switch (quality) {
  case SamplingQuality::Draft: return {0.25, 36, 1e-6};
  case SamplingQuality::Normal: return {1.0, 360, 1e-10};
  case SamplingQuality::Precise: return {4.0, 3600, 1e-12};
  }
  return {};
}

std::size_t displaySampleCount(SamplingQuality quality, double widthPx, double spanDeg) {
  const QualityPreset p = qualityPreset(quality);
  // Plots are a few thousand pixels wide at most; the clamp only guards a bogus width.
  const double width = std::isfinite(widthPx) ? std::clamp(widthPx, 0.0, 1e5) : kDefaultDisplayWidth;
  const double span = std::isfinite(spanDeg) && spanDeg > 0.0 ? spanDeg : 360.0;
  const auto byWidth = static_cast<std::size_t>(std::ceil(width * p.samplesPerPixel - 1e-9));
  const auto floor = static_cast<std::size_t>(std::ceil(static_cast<double>(p.minPerRevolution) * span / 360.0 - 1e-9));
  return std::max<std::size_t>({byWidth, floor, 1}) + 1;
}

std::size_t samplesPerRevolution(std::size_t samples, double spanDeg) {
  if (samples < 2 || !(spanDeg > 0.0)) return 0;
  return static_cast<std::size_t>(std::lround(static_cast<double>(samples - 1) * 360.0 / spanDeg));
}

QString qualityKey(SamplingQuality quality) {
  switch (quality) {
  case SamplingQuality::Draft: return QStringLiteral("draft");
  case SamplingQuality::Normal: return QStringLiteral("normal");
  case SamplingQuality::Precise: return QStringLiteral("precise");
  }
  return QStringLiteral("normal");
}

SamplingQuality qualityFromKey(const QString& key) {
  if (key == QLatin1String("draft")) return SamplingQuality::Draft;
  if (key == QLatin1String("precise")) return SamplingQuality::Precise;
  return SamplingQuality::Normal;
}

}  // namespace linkwright::ui
