#pragma once
// The drawing scale of a velocity or acceleration polygon, as a student chooses it: a round
// number of polygon units (mm/s, mm/s²) per centimetre of drawing, "1 cm = 50 mm/s". Only
// view arithmetic: which round scales to offer and how a scale reads.

#include <QString>

#include <vector>

namespace linkwright::ui {

/// The smallest round scale (1, 2, 2.5 or 5 × 10^n units per cm) at least `unitsPerCm`; 1 for
/// a value that is not positive and finite (a polygon at rest).
double roundScaleAtLeast(double unitsPerCm);

/// Round scales from about a tenth of `fit` to ten times it, increasing: what the scale box
/// offers beside "fit".
std::vector<double> roundScalesAround(double fit);

/// "1 cm = 50 mm/s".
QString scaleText(double unitsPerCm, const QString& unit);

}  // namespace linkwright::ui
