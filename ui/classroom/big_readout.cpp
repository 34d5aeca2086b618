#include "ui/classroom/big_readout.h"

#include "ui/colors.h"
#include "ui/plots/axis_range.h"
#include "ui/plots/plot_quantity.h"

#include "kinematics/analysis/centre_model.h"
#include "kinematics/model/driver.h"
#include "kinematics/model/units.h"

#include <QApplication>
#include <QFontMetricsF>

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

namespace linkwright::ui {

namespace k = kinematics;
using Kind = ReadoutQuantity::Kind;
using k::ColumnQuantity;

namespace {

// Twice the window's text: a back row reads it; presentation mode enlarges it further.
constexpr double kTextScale = 2.0;
const QString kUndefined(QChar(0x2014));  // "—"
// The type never shrinks below this, however narrow the window: better cut than unreadable.
constexpr double kSmallestPointSize = 10.0;
// Angles nearest 180°: (0°, 360°], as a textbook gives a rocker's angle.
constexpr double kAngleCentreDeg = 180.0;

bool isGround(const k::Mechanism& m, k::PointId p) {
  return std::holds_alternative<k::GroundPoint>(m.points[p.index].definition);
}

// `numbers`: each link's textbook number (centre_model.h): the frame is body 1, the crank 2, ...
QString inputSymbol(const k::Mechanism& m, const std::vector<std::size_t>& numbers) {
  if (k::inputKind(m) == k::InputKind::Angle) {
    for (std::size_t l = 0; l < m.links.size(); ++l)
      if (k::isDrivenCrankLink(m, k::LinkId{l})) return QStringLiteral("θ") + QString::number(numbers[l]);
    return QStringLiteral("θ");
  }
  const auto driver = k::driverPoint(m);
  const bool actuator = driver && std::holds_alternative<k::ActuatorPoint>(m.points[driver->index].definition);
  return actuator ? QStringLiteral("L") : QStringLiteral("s");
}

// The last link turning about a ground pivot other than the driven crank: a four-bar's rocker.
std::optional<std::size_t> outputLink(const k::Mechanism& m) {
  std::optional<std::size_t> output;
  for (std::size_t l = 0; l < m.links.size(); ++l)
    if (!k::isDrivenCrankLink(m, k::LinkId{l}) && (isGround(m, m.links[l].first) || isGround(m, m.links[l].second)))
      output = l;
  return output;
}

// Decimals of a length in `unit` (and of a speed in `unit`/s): about 0.1 mm.
int lengthDecimals(const std::string& unit) {
  if (unit == "mm") return 1;
  if (unit == "cm") return 2;
  if (unit == "m" || unit == "in") return 3;
  return 2;
}

QString angleText(double radians, AngleUnit unit) {
  return unit == AngleUnit::Degrees ? readoutNumber(k::radToDeg(radians), 1) + QChar(0x00B0)
                                    : readoutNumber(radians, 3) + QStringLiteral(" rad");
}

// The input as the plots' cursor has it: a crank angle within the design's range (a full turn
// from 0° on a time base), or a driver's length.
QString inputText(const MechanismDocument& d, AngleUnit unit) {
  const k::Mechanism& m = d.mechanism();
  const double q = d.crankAngle();
  if (k::inputKind(m) != k::InputKind::Angle)
    return readoutNumber(k::inputDisplayValue(m, q), lengthDecimals(d.lengthUnit())) + QLatin1Char(' ') +
           QString::fromStdString(d.lengthUnit());
  double deg = k::radToDeg(q);
  if (!d.onTimeBase()) deg = wrapIntoRange(deg, d.design().fromDeg, d.design().toDeg).value_or(deg);
  else if (d.analysis().inputRange.fullRotation) deg -= 360.0 * std::floor(deg / 360.0);
  return angleText(k::degToRad(deg), unit);
}

QString valueText(const MechanismDocument& d, const ReadoutQuantity& r, AngleUnit unit) {
  const k::Pose& pose = d.pose();
  const double q = d.crankAngle();
  const bool rates = d.poseStatus() == k::PoseStatus::Ok;
  const QString length = QString::fromStdString(d.lengthUnit());
  const int decimals = lengthDecimals(d.lengthUnit());
  switch (r.kind) {
  case Kind::Time: return readoutNumber(d.time(), 3) + QStringLiteral(" s");
  case Kind::Input: return inputText(d, unit);
  case Kind::Angle: return angleText(k::degToRad(r.column.valueOf(pose, q, kAngleCentreDeg)), unit);
  case Kind::AngularRate:
    if (!rates) return kUndefined;
    return readoutNumber(toAngleUnit(r.column.valueOf(pose, q), unit), unit == AngleUnit::Degrees ? 1 : 2) +
           QLatin1Char(' ') + quantityUnit(QuantityKind::Omega, unit);
  case Kind::Length: return readoutNumber(r.column.valueOf(pose, q), decimals) + QLatin1Char(' ') + length;
  case Kind::LengthRate:
    if (!rates) return kUndefined;
    return readoutNumber(r.column.valueOf(pose, q), decimals) + QLatin1Char(' ') +
           quantityUnit(QuantityKind::Velocity, unit, length);
  }
  return {};
}

}  // namespace

QString readoutNumber(double value, int decimals) {
  if (!std::isfinite(value)) return kUndefined;
  QString text = QString::number(value, 'f', decimals);
  // "-0.0" reads as a sign that is not there.
  if (text.startsWith(QLatin1Char('-')) && text.mid(1).toDouble() == 0.0) text.remove(0, 1);
  if (text.startsWith(QLatin1Char('-'))) text.replace(0, 1, QChar(0x2212));
  return text;
}

std::vector<ReadoutQuantity> readoutQuantities(const MechanismDocument& d) {
  const k::Mechanism& m = d.mechanism();
  std::vector<ReadoutQuantity> out;
  if (d.onTimeBase()) out.push_back({Kind::Time, {}, QStringLiteral("t")});
  const std::vector<std::size_t> numbers = k::linkNumbers(m);
  out.push_back({Kind::Input, {}, inputSymbol(m, numbers)});
  if (const auto l = outputLink(m)) {
    const QString number = QString::number(numbers[*l]);
    out.push_back({Kind::Angle, {{}, ColumnQuantity::LinkAngle, *l}, QStringLiteral("θ") + number});
    out.push_back({Kind::AngularRate, {{}, ColumnQuantity::LinkOmega, *l}, QStringLiteral("ω") + number});
  }
  // The plots' quantities: a ground slider's coordinate along its guide, and μ.
  const std::vector<PlotCurve> curves = plotCurves(m, d.pose());
  const auto first = [&](auto wanted) -> const PlotCurve* {
    for (const PlotCurve& c : curves)
      if (wanted(c.quantity.column)) return &c;
    return nullptr;
  };
  if (const PlotCurve* c =
          first([](ColumnQuantity q) { return q == ColumnQuantity::PointX || q == ColumnQuantity::PointY; }))
    out.push_back({Kind::Length, {{}, c->quantity.column, c->quantity.index}, c->name});
  if (const PlotCurve* c =
          first([](ColumnQuantity q) { return q == ColumnQuantity::PointVx || q == ColumnQuantity::PointVy; }))
    out.push_back({Kind::LengthRate, {{}, c->quantity.column, c->quantity.index}, c->name});
  if (const PlotCurve* c = first([](ColumnQuantity q) { return q == ColumnQuantity::TransmissionAngle; }))
    out.push_back({Kind::Angle, {{}, c->quantity.column, c->quantity.index}, QStringLiteral("μ")});
  return out;
}

std::vector<ReadoutEntry> readoutEntries(const MechanismDocument& d, const std::vector<ReadoutQuantity>& quantities,
                                         AngleUnit unit) {
  std::vector<ReadoutEntry> entries;
  entries.reserve(quantities.size());
  for (const ReadoutQuantity& r : quantities) entries.push_back({r.symbol, valueText(d, r, unit)});
  return entries;
}

BigReadout::BigReadout(MechanismDocument* document, QWidget* parent) : QLabel(parent), m_document(document) {
  setObjectName(QStringLiteral("BigReadout"));
  setTextFormat(Qt::PlainText);
  setAlignment(Qt::AlignCenter);
  // Never wider than the window: a long line is cut, not the window stretched.
  setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
  setPresentationScale(1.0);
  refreshColors();
  m_quantities = readoutQuantities(*m_document);
  refresh();
  connect(m_document, &MechanismDocument::changed, this, &BigReadout::onDocumentChanged);
}

void BigReadout::setAngleUnit(AngleUnit unit) {
  m_unit = unit;
  refresh();
  fitFont();
}

void BigReadout::setPresentationScale(double factor) {
  const double base = QApplication::font().pointSizeF();
  m_pointSize = (base > 0.0 ? base : 9.0) * kTextScale * factor;  // a pixel-sized font has no point size
  fitFont();
}

void BigReadout::showEvent(QShowEvent* event) {
  QLabel::showEvent(event);
  if (!std::exchange(m_stale, false)) return;
  m_quantities = readoutQuantities(*m_document);
  refresh();
  fitFont();
}

void BigReadout::resizeEvent(QResizeEvent* event) {
  QLabel::resizeEvent(event);
  fitFont();
}

void BigReadout::fitFont() {
  QFont big = QApplication::font();
  big.setPointSizeF(m_pointSize);
  const double width = QFontMetricsF(big).horizontalAdvance(text());
  const double room = contentsRect().width();
  // A tenth to spare: the numbers' widths change as the linkage moves.
  if (width > 0.0 && room > 0.0 && 1.1 * width > room)
    big.setPointSizeF(std::max(kSmallestPointSize, m_pointSize * room / (1.1 * width)));
  setFont(big);
}

void BigReadout::refreshColors() {
  const Palette& c = colors();
  setStyleSheet(QStringLiteral("QLabel#BigReadout { color: %1; background: %2; border-bottom: 2px solid %1; "
                               "padding: 2px 12px; }")
                    .arg(c.label.name(), c.canvasBackground.name()));
}

void BigReadout::onDocumentChanged(Changes what) {
  // Off screen (the default) it only notes that it is behind; showEvent catches up.
  if (!isVisible()) {
    m_stale = true;
    return;
  }
  if (what & Change::Design) m_quantities = readoutQuantities(*m_document);
  if (what & (Changes(Change::Design) | Change::Motion | Change::Request | Change::Analysis)) refresh();
  if (what & Change::Design) fitFont();  // other quantities, another length of text
}

// A few values off the solved pose: cheap enough for every frame of a drag or the animation.
void BigReadout::refresh() {
  m_entries = readoutEntries(*m_document, m_quantities, m_unit);
  QStringList parts;
  for (const ReadoutEntry& e : m_entries) parts << e.symbol + QStringLiteral(" = ") + e.value;
  setText(parts.join(QStringLiteral("    ")));
  // Shrinks only while moving: a font that changed size with every digit would flicker.
  if (QFontMetricsF(font()).horizontalAdvance(text()) > contentsRect().width() && contentsRect().width() > 0) fitFont();
}

}  // namespace linkwright::ui
