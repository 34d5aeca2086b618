#include "ui/classroom/polygon_scale.h"

#include "ui/number_text.h"

#include <array>
#include <cmath>

namespace linkwright::ui {

namespace {
constexpr std::array<double, 4> kMantissas{1.0, 2.0, 2.5, 5.0};
}

double roundScaleAtLeast(double unitsPerCm) {
  if (!std::isfinite(unitsPerCm) || unitsPerCm <= 0.0) return 1.0;
  const double decade = std::pow(10.0, std::floor(std::log10(unitsPerCm)));
  for (const double m : kMantissas)
    if (m * decade >= unitsPerCm * (1.0 - 1e-12)) return m * decade;
  return 10.0 * decade;
}

std::vector<double> roundScalesAround(double fit) {
  const double centre = roundScaleAtLeast(fit);
  const double decade = std::pow(10.0, std::floor(std::log10(centre)));
  std::vector<double> scales;
  for (int d = -1; d <= 1; ++d)
    for (const double m : kMantissas) scales.push_back(m * decade * std::pow(10.0, d));
  scales.push_back(10.0 * decade * 10.0);
  return scales;
}

QString scaleText(double unitsPerCm, const QString& unit) {
  return QStringLiteral("1 cm = %1 %2").arg(numberText(unitsPerCm, 'g', 6), unit);
}

}  // namespace linkwright::ui
