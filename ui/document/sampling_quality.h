#pragma once
// The displayed cycle's sampling quality: how many samples the plots (and the canvas's paths)
// get per pixel of plot width, with a floor per revolution of the crank, and the Newton
// tolerance for points no dyad places. Draft, Normal and Precise trade sweep time for the peak
// error stated beside the choice, which is measured on the design (quality_estimate.h), not
// taken from this table. Plain arithmetic: no kinematics here.

#include <QString>

#include <cstddef>

namespace linkwright::ui {

enum class SamplingQuality { Draft, Normal, Precise };

/// What one quality means.
struct QualityPreset {
  double samplesPerPixel = 1.0;      ///< samples per pixel of plot-area width
  std::size_t minPerRevolution = 0;  ///< floor, samples per 360° of crank angle
  double newtonTolerance = 1e-12;    ///< kinematics::NewtonSettings::tolerance (relative misfit)
  bool operator==(const QualityPreset&) const = default;
};

/// Draft: 1 sample per 4 px, ≥ 36/rev, 1e-6; Normal: 1 per px, ≥ 360/rev, 1e-10; Precise:
/// 4 per px, ≥ 3600/rev, 1e-12.
QualityPreset qualityPreset(SamplingQuality quality);

/// The width (px) the displayed sweep is spread over until a plot reports its own: 720, so
/// Normal gives the seeds' half-degree grid over a full turn.
inline constexpr double kDefaultDisplayWidth = 720.0;

/// Samples (≥ 2, ends included) of a grid spanning `spanDeg` (> 0) degrees of crank angle drawn
/// across `widthPx` pixels: intervals = max(⌈widthPx × samplesPerPixel⌉, ⌈minPerRevolution ×
/// spanDeg / 360⌉), samples = intervals + 1.
std::size_t displaySampleCount(SamplingQuality quality, double widthPx, double spanDeg);

/// Samples per revolution of a grid of `samples` samples over `spanDeg` degrees: its intervals
/// scaled to 360°, rounded (exactly samples − 1 for a full turn).
std::size_t samplesPerRevolution(std::size_t samples, double spanDeg);

/// The settings key of a quality ("draft", "normal", "precise"), and back (Normal for any other).
QString qualityKey(SamplingQuality quality);
SamplingQuality qualityFromKey(const QString& key);

}  // namespace linkwright::ui
