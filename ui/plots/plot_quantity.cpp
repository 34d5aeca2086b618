#include "ui/plots/plot_quantity.h"

#include <QCoreApplication>

namespace linkwright::ui {
namespace {

// Gives the free functions below a translation context lupdate understands.
class Text {
  Q_DECLARE_TR_FUNCTIONS(PlotQuantityText)
};

} // namespace

QuantityKind quantityKind(PlotQuantity q) {
  switch (q) {
  case PlotQuantity::CouplerAngle:
  case PlotQuantity::RockerAngle:
  case PlotQuantity::TransmissionAngle: return QuantityKind::Angle;
  case PlotQuantity::CouplerOmega:
  case PlotQuantity::RockerOmega: return QuantityKind::Omega;
  case PlotQuantity::CouplerAlpha:
  case PlotQuantity::RockerAlpha: return QuantityKind::Alpha;
  }
  return QuantityKind::Angle;
}

QString quantityKey(PlotQuantity q) {
  switch (q) {
  case PlotQuantity::CouplerAngle: return QStringLiteral("coupler_angle");
  case PlotQuantity::RockerAngle: return QStringLiteral("rocker_angle");
  case PlotQuantity::TransmissionAngle: return QStringLiteral("transmission_angle");
  case PlotQuantity::CouplerOmega: return QStringLiteral("coupler_omega");
  case PlotQuantity::RockerOmega: return QStringLiteral("rocker_omega");
  case PlotQuantity::CouplerAlpha: return QStringLiteral("coupler_alpha");
  case PlotQuantity::RockerAlpha: return QStringLiteral("rocker_alpha");
  }
  return {};
}

QString quantityName(PlotQuantity q) {
  // Subscripts follow the thesis seed: 3 = coupler, 4 = rocker.
  switch (q) {
  case PlotQuantity::CouplerAngle: return Text::tr("coupler θ3");
  case PlotQuantity::RockerAngle: return Text::tr("rocker θ4");
  case PlotQuantity::TransmissionAngle: return Text::tr("transmission μ");
  case PlotQuantity::CouplerOmega: return Text::tr("coupler ω3");
  case PlotQuantity::RockerOmega: return Text::tr("rocker ω4");
  case PlotQuantity::CouplerAlpha: return Text::tr("coupler α3");
  case PlotQuantity::RockerAlpha: return Text::tr("rocker α4");
  }
  return {};
}

QColor quantityColor(PlotQuantity q) {
  // One colour per link on every chart, the canvas's own (ui/canvas/canvas_style.h:
  // kCouplerColor, kRockerColor; copied, as plots do not depend on the canvas). The
  // transmission angle is no link: brown, a colour the canvas does not use (its orange is
  // the crank's).
  switch (q) {
  case PlotQuantity::CouplerAngle:
  case PlotQuantity::CouplerOmega:
  case PlotQuantity::CouplerAlpha: return QColor(49, 130, 189);
  case PlotQuantity::RockerAngle:
  case PlotQuantity::RockerOmega:
  case PlotQuantity::RockerAlpha: return QColor(49, 163, 84);
  case PlotQuantity::TransmissionAngle: return QColor(140, 86, 75);
  }
  return Qt::black;
}

QString quantityUnit(QuantityKind kind, AngleUnit unit) {
  const QString angle = angleUnitSymbol(unit);
  switch (kind) {
  case QuantityKind::Angle: return angle;
  case QuantityKind::Omega: return angle + QStringLiteral("/s");
  case QuantityKind::Alpha: return angle + QStringLiteral("/s²");
  }
  return angle;
}

QString valueAxisTitle(QuantityKind kind, AngleUnit unit) {
  const QString u = quantityUnit(kind, unit);
  switch (kind) {
  case QuantityKind::Angle: return Text::tr("angle [%1]").arg(u);
  case QuantityKind::Omega: return Text::tr("ω [%1]").arg(u);
  case QuantityKind::Alpha: return Text::tr("α [%1]").arg(u);
  }
  return u;
}

QString crankAxisTitle(AngleUnit unit) { return Text::tr("crank angle [%1]").arg(angleUnitSymbol(unit)); }

QuantitySelection QuantitySelection::all() {
  QuantitySelection s;
  s.m_on.fill(true);
  return s;
}

bool QuantitySelection::any(QuantityKind kind) const {
  for (const PlotQuantity q : allPlotQuantities())
    if (quantityKind(q) == kind && contains(q)) return true;
  return false;
}

kinematics::SolveRequest requestFor(const QuantitySelection& s) {
  const bool alpha = s.any(QuantityKind::Alpha);
  return {s.any(QuantityKind::Omega) || alpha, alpha};
}

} // namespace linkwright::ui
