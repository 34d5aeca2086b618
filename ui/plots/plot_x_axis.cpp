#include "ui/plots/plot_x_axis.h"

#include "ui/number_text.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>

namespace linkwright::ui {
namespace {

namespace k = kinematics;

// Ticks: about this many intervals, as on the crank axis (axis_range.cpp says why).
constexpr int kIntervals = 4;

QString tr(const char* text) { return QCoreApplication::translate("PlotXAxis", text); }

bool angular(const XSource& x) { return x.input == k::InputKind::Angle; }

}  // namespace

QString inputDisplayName(const k::Mechanism& mechanism) { return QString::fromStdString(k::inputName(mechanism)); }

QString inputAxisTitle(const k::Mechanism& mechanism, AngleUnit unit) {
  const QString symbol = k::inputKind(mechanism) == k::InputKind::Angle ? angleUnitSymbol(unit)
                                                                        : QString::fromStdString(mechanism.lengthUnit);
  return tr("%1 [%2]").arg(inputDisplayName(mechanism), symbol);
}

QString timeAxisTitle() { return tr("time [s]"); }

QString xReadoutText(double x, const PlotXAxis& axis, AngleUnit unit) {
  if (axis.source.axis == PlotAxis::Time) return tr("t = %1 s").arg(numberText(x, 'f', 3));
  if (!angular(axis.source)) return tr("%1 %2 %3").arg(axis.inputName, numberText(x, 'g', 4), axis.inputUnit);
  // Degrees read best with the degree sign right after the number, as in "at crank 90.0°".
  if (unit == AngleUnit::Degrees) return tr("crank %1°").arg(numberText(x, 'f', 1));
  return tr("crank %1 %2").arg(numberText(x, 'f', 3), angleUnitSymbol(unit));
}

double sampleX(const k::SweepResult& sweep, std::size_t j, const XSource& x, AngleUnit unit) {
  if (x.axis == PlotAxis::Time && j < sweep.time.size()) return sweep.time[j];
  return angular(x) ? toAngleUnit(sweep.inputAngle[j], unit) : sweep.inputAngle[j];
}

double extremumX(const k::Extremum& e, const XSource& x, AngleUnit unit) {
  if (x.axis == PlotAxis::Time) return e.time;
  return angular(x) ? toAngleUnit(e.inputAngle, unit) : e.inputAngle;
}

AxisRange exactAxisRange(double lo, double hi) {
  if (lo > hi) std::swap(lo, hi);
  if (!(hi > lo)) {
    lo -= 0.5;
    hi += 0.5;
  }
  AxisRange r;
  r.min = lo;
  r.max = hi;
  r.step = niceStep((hi - lo) / kIntervals);
  r.tickCount = static_cast<int>(std::floor((hi - lo) / r.step + 1e-9)) + 1;
  r.decimals = decimalsFor(r.step);
  return r;
}

PlotXAxis plotXAxis(const k::Design& design, const k::SweepResult& sweep, PlotAxis axis, AngleUnit unit) {
  const k::Mechanism& m = design.mechanism;
  PlotXAxis x;
  x.source.input = k::inputKind(m);
  x.inputName = inputDisplayName(m);
  if (!angular(x.source)) x.inputUnit = QString::fromStdString(m.lengthUnit);
  if (design.time && axis == PlotAxis::Time) {
    x.source.axis = PlotAxis::Time;
    x.range = exactAxisRange(design.time->fromTime, design.time->toTime);
    x.title = timeAxisTitle();
    return x;
  }
  x.title = inputAxisTitle(m, unit);
  if (!design.time) {
    // The grid's ends are in the input's display unit: degrees for a crank.
    x.range = angular(x.source) ? crankAxisRange(design.fromDeg, design.toDeg, unit)
                                : exactAxisRange(design.fromDeg, design.toDeg);
    return x;
  }
  // The inputs the law sweeps through, as plotted (unwrapped): the sweep's, or the law's ends.
  double lo = k::motionAt(design.time->law, design.time->fromTime).position;
  double hi = k::motionAt(design.time->law, design.time->toTime).position;
  if (!sweep.inputAngle.empty()) {
    const auto [min, max] = std::minmax_element(sweep.inputAngle.begin(), sweep.inputAngle.end());
    lo = *min;
    hi = *max;
  }
  if (!angular(x.source)) {
    x.range = exactAxisRange(lo, hi);
    return x;
  }
  // A law that holds the crank still still gets an axis around it.
  if (!(hi - lo > 1e-9)) {
    lo -= k::degToRad(1.0);
    hi += k::degToRad(1.0);
  }
  x.range = crankAxisRange(k::radToDeg(lo), k::radToDeg(hi), unit);
  return x;
}

std::optional<double> cursorX(const MechanismDocument& document, const PlotXAxis& axis, AngleUnit unit) {
  const double q = document.crankAngle();
  if (document.onTimeBase()) {
    if (axis.source.axis == PlotAxis::Time) return document.time();
    return angular(axis.source) ? toAngleUnit(q, unit) : q;
  }
  const k::Design& design = document.design();
  if (!angular(axis.source)) {
    if (q < std::min(design.fromDeg, design.toDeg) || q > std::max(design.fromDeg, design.toDeg)) return std::nullopt;
    return q;
  }
  const std::optional<double> deg = wrapIntoRange(k::radToDeg(q), design.fromDeg, design.toDeg);
  if (!deg) return std::nullopt;
  return toAngleUnit(k::degToRad(*deg), unit);
}

}  // namespace linkwright::ui
