#include "ui/plots/plot_quantity.h"

#include "ui/colors.h"

#include "kinematics/analysis/centre_model.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/solve/guide_line.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>

namespace linkwright::ui {

namespace k = kinematics;
using k::ColumnQuantity;

namespace {

// Gives the free functions below a translation context lupdate understands.
class Text {
  Q_DECLARE_TR_FUNCTIONS(PlotQuantityText)
};

QuantityKind kindOf(ColumnQuantity c) {
  switch (c) {
  case ColumnQuantity::Time:  // an x axis, never a curve
  case ColumnQuantity::InputAngle:
  case ColumnQuantity::LinkAngle:
  case ColumnQuantity::TransmissionAngle: return QuantityKind::Angle;
  case ColumnQuantity::LinkOmega: return QuantityKind::Omega;
  case ColumnQuantity::LinkAlpha: return QuantityKind::Alpha;
  case ColumnQuantity::InputLength:
  case ColumnQuantity::PointX:
  case ColumnQuantity::PointY: return QuantityKind::Position;
  case ColumnQuantity::PointVx:
  case ColumnQuantity::PointVy: return QuantityKind::Velocity;
  case ColumnQuantity::PointAx:
  case ColumnQuantity::PointAy: return QuantityKind::Acceleration;
  }
  return QuantityKind::Angle;
}

// `numbers`: each link's textbook number, as the instant centres number bodies.
void addLinkCurves(std::vector<PlotCurve>& out, const k::Mechanism& m, const std::vector<std::size_t>& numbers,
                   ColumnQuantity column, const QString& symbol, const QString& suffix) {
  for (std::size_t l = 0; l < m.links.size(); ++l) {
    if (k::isDrivenCrankLink(m, k::LinkId{l})) continue;  // the driver's own, constant or the input
    const QString name = QString::fromStdString(m.links[l].name);
    out.push_back({{column, l},
                   name + suffix,
                   QStringLiteral("%1 %2%3").arg(name, symbol).arg(numbers[l]),
                   linkColor(l),
                   symbol + QString::number(numbers[l])});
  }
}

// A crank-driven linkage's ratios (centre_model.h: its input and output bodies), in the
// output's colour (the rocker's, the slider's).
void addRatioCurves(std::vector<PlotCurve>& out, const k::Mechanism& m, const k::Result<k::CentreModel>& model) {
  if (!model || !model->ratio.exists()) return;  // no such ratios
  const k::RatioBodies bodies = model->ratio;
  QColor color = linkColor(model->outputLink ? model->outputLink->index : 0);
  if (model->outputGuide) {
    const std::size_t slider = model->outputGuide->slider.point.index;
    color = sliderColor(static_cast<std::size_t>(
        std::count_if(m.points.begin(), m.points.begin() + static_cast<std::ptrdiff_t>(slider),
                      [](const k::Point& p) { return std::holds_alternative<k::RrpPoint>(p.definition); })));
  }
  const PlotQuantity ratio = PlotQuantity::ofRatio(RatioQuantity::VelocityRatio, bodies);
  const PlotQuantity advantage = PlotQuantity::ofRatio(RatioQuantity::Advantage, bodies);
  out.push_back({ratio, QStringLiteral("velocity_ratio"), Text::tr("ratio %1").arg(ratioSymbol(ratio)), color,
                 ratioSymbol(ratio)});
  out.push_back({advantage, QStringLiteral("mechanical_advantage"),
                 Text::tr("advantage %1").arg(ratioSymbol(advantage)), color, ratioSymbol(advantage)});
}

}  // namespace

const PlotQuantity PlotQuantity::CouplerAngle{ColumnQuantity::LinkAngle, k::fourbar::kCoupler.index};
const PlotQuantity PlotQuantity::RockerAngle{ColumnQuantity::LinkAngle, k::fourbar::kRocker.index};
const PlotQuantity PlotQuantity::TransmissionAngle{ColumnQuantity::TransmissionAngle, k::fourbar::kC.index};
const PlotQuantity PlotQuantity::CouplerOmega{ColumnQuantity::LinkOmega, k::fourbar::kCoupler.index};
const PlotQuantity PlotQuantity::RockerOmega{ColumnQuantity::LinkOmega, k::fourbar::kRocker.index};
const PlotQuantity PlotQuantity::CouplerAlpha{ColumnQuantity::LinkAlpha, k::fourbar::kCoupler.index};
const PlotQuantity PlotQuantity::RockerAlpha{ColumnQuantity::LinkAlpha, k::fourbar::kRocker.index};

QuantityKind quantityKind(PlotQuantity q) {
  switch (q.ratio) {
  case RatioQuantity::None: break;
  case RatioQuantity::VelocityRatio: return QuantityKind::VelocityRatio;
  case RatioQuantity::Advantage: return QuantityKind::Advantage;
  }
  return kindOf(q.column);
}

std::vector<PlotCurve> plotCurves(const k::Mechanism& m, const k::Pose& pose) {
  std::vector<PlotCurve> out;
  const auto model = k::centreModel(m);  // bodies found once: link numbers and ratios
  const std::vector<std::size_t> numbers = model ? model->linkNumbers : k::linkNumbers(m);
  addLinkCurves(out, m, numbers, ColumnQuantity::LinkAngle, QStringLiteral("θ"), QStringLiteral("_angle"));
  const std::vector<std::size_t> dyads = k::transmissionJoints(m);
  for (std::size_t d = 0; d < dyads.size(); ++d) {
    const QString point = QString::fromStdString(m.points[dyads[d]].name);
    const bool one = dyads.size() == 1;
    out.push_back({{ColumnQuantity::TransmissionAngle, dyads[d]},
                   one ? QStringLiteral("transmission_angle") : QStringLiteral("transmission_angle_") + point,
                   one ? Text::tr("transmission μ") : Text::tr("μ at %1").arg(point),
                   transmissionColor(d),
                   one ? QStringLiteral("μ") : QStringLiteral("μ ") + point});
  }
  addLinkCurves(out, m, numbers, ColumnQuantity::LinkOmega, QStringLiteral("ω"), QStringLiteral("_omega"));
  addLinkCurves(out, m, numbers, ColumnQuantity::LinkAlpha, QStringLiteral("α"), QStringLiteral("_alpha"));
  // A slider on a ground guide: the coordinate its guide mostly runs along (a piston's x).
  std::size_t sliders = 0;
  for (std::size_t i = 0; i < m.points.size(); ++i) {
    const auto* s = std::get_if<k::RrpPoint>(&m.points[i].definition);
    if (s == nullptr) continue;
    const std::size_t ordinal = sliders++;
    if (s->guide.link || i >= pose.position.size()) continue;
    const Eigen::Vector2d u = k::guideLineAt(m, s->guide, pose).direction;
    const bool alongX = std::abs(u.x()) >= std::abs(u.y());
    const QString point = QString::fromStdString(m.points[i].name);
    const QString axis = alongX ? QStringLiteral("x") : QStringLiteral("y");
    const QColor color = sliderColor(ordinal);
    out.push_back(
        {{alongX ? ColumnQuantity::PointX : ColumnQuantity::PointY, i}, point + "_" + axis, point + " " + axis, color});
    out.push_back({{alongX ? ColumnQuantity::PointVx : ColumnQuantity::PointVy, i},
                   point + "_v" + axis,
                   point + " v" + axis,
                   color});
    out.push_back({{alongX ? ColumnQuantity::PointAx : ColumnQuantity::PointAy, i},
                   point + "_a" + axis,
                   point + " a" + axis,
                   color});
  }
  addRatioCurves(out, m, model);
  // Checkbox and legend order: by chart.
  std::stable_sort(out.begin(), out.end(), [](const PlotCurve& a, const PlotCurve& b) {
    return quantityKind(a.quantity) < quantityKind(b.quantity);
  });
  return out;
}

const PlotCurve* findCurve(const std::vector<PlotCurve>& curves, PlotQuantity quantity) {
  for (const PlotCurve& c : curves)
    if (c.quantity == quantity) return &c;
  return nullptr;
}

// The core's unit rule (kinematics/solve/sweep_columns.h: columnUnit), for a column of the kind,
// angles and their rates both in the plots' angle unit.
QString quantityUnit(QuantityKind kind, AngleUnit unit, const QString& lengthUnit) {
  ColumnQuantity column = ColumnQuantity::LinkAngle;
  switch (kind) {
  case QuantityKind::Angle: break;
  case QuantityKind::Omega: column = ColumnQuantity::LinkOmega; break;
  case QuantityKind::Alpha: column = ColumnQuantity::LinkAlpha; break;
  case QuantityKind::Position: column = ColumnQuantity::PointX; break;
  case QuantityKind::Velocity: column = ColumnQuantity::PointVx; break;
  case QuantityKind::Acceleration: column = ColumnQuantity::PointAx; break;
  case QuantityKind::VelocityRatio:
  case QuantityKind::Advantage: return {};
  }
  const std::string angle = angleUnitSymbol(unit).toStdString();
  return QString::fromStdString(k::columnUnit(column, lengthUnit.toStdString(), angle, angle));
}

QString ratioSymbol(PlotQuantity q) {
  const std::size_t a = q.bodies.input, b = q.bodies.output;
  if (q.ratio == RatioQuantity::VelocityRatio)
    return q.bodies.outputSlides ? QStringLiteral("v/ω%1").arg(a) : QStringLiteral("ω%1/ω%2").arg(b).arg(a);
  if (q.ratio == RatioQuantity::Advantage)
    return q.bodies.outputSlides ? QStringLiteral("F/T%1").arg(a) : QStringLiteral("T%1/T%2").arg(b).arg(a);
  return {};
}

QString quantityUnit(PlotQuantity q, AngleUnit unit, const QString& lengthUnit) {
  if (q.ratio == RatioQuantity::None || !q.bodies.outputSlides) return quantityUnit(quantityKind(q), unit, lengthUnit);
  return q.ratio == RatioQuantity::VelocityRatio ? lengthUnit + QStringLiteral("/rad")
                                                 : QStringLiteral("1/") + lengthUnit;
}

QString valueAxisTitle(QuantityKind kind, AngleUnit unit, const QString& lengthUnit) {
  const QString u = quantityUnit(kind, unit, lengthUnit);
  switch (kind) {
  case QuantityKind::Angle: return Text::tr("angle [%1]").arg(u);
  case QuantityKind::Omega: return Text::tr("ω [%1]").arg(u);
  case QuantityKind::Alpha: return Text::tr("α [%1]").arg(u);
  case QuantityKind::Position: return Text::tr("position [%1]").arg(u);
  case QuantityKind::Velocity: return Text::tr("v [%1]").arg(u);
  case QuantityKind::Acceleration: return Text::tr("a [%1]").arg(u);
  case QuantityKind::VelocityRatio: return QStringLiteral("ω4/ω2");
  case QuantityKind::Advantage: return QStringLiteral("T4/T2");
  }
  return u;
}

QString valueAxisTitle(PlotQuantity q, AngleUnit unit, const QString& lengthUnit) {
  if (q.ratio == RatioQuantity::None) return valueAxisTitle(quantityKind(q), unit, lengthUnit);
  if (!q.bodies.outputSlides) return ratioSymbol(q);
  return QStringLiteral("%1 [%2]").arg(ratioSymbol(q), quantityUnit(q, unit, lengthUnit));
}

bool QuantitySelection::contains(PlotQuantity q) const {
  return std::find(m_hidden.begin(), m_hidden.end(), q) == m_hidden.end();
}

void QuantitySelection::set(PlotQuantity q, bool on) {
  const auto at = std::find(m_hidden.begin(), m_hidden.end(), q);
  if (on && at != m_hidden.end()) m_hidden.erase(at);
  if (!on && at == m_hidden.end()) m_hidden.push_back(q);
}

bool QuantitySelection::operator==(const QuantitySelection& other) const {
  return m_hidden.size() == other.m_hidden.size() &&
         std::all_of(m_hidden.begin(), m_hidden.end(), [&](PlotQuantity q) { return !other.contains(q); });
}

bool QuantitySelection::any(QuantityKind kind, const std::vector<PlotCurve>& curves) const {
  return std::any_of(curves.begin(), curves.end(),
                     [&](const PlotCurve& c) { return quantityKind(c.quantity) == kind && contains(c.quantity); });
}

QuantitySelection defaultSelection(const std::vector<PlotCurve>& curves) {
  QuantitySelection s;
  for (const PlotCurve& c : curves)
    if (c.quantity.ratio != RatioQuantity::None) s.set(c.quantity, false);
  const bool sliders = std::any_of(curves.begin(), curves.end(), [](const PlotCurve& c) {
    return quantityKind(c.quantity) == QuantityKind::Position;
  });
  if (!sliders) return s;
  for (const PlotCurve& c : curves) {
    const QuantityKind kind = quantityKind(c.quantity);
    if (kind == QuantityKind::Omega || kind == QuantityKind::Alpha) s.set(c.quantity, false);
  }
  return s;
}

QuantitySelection selectionAfter(const std::vector<PlotCurve>& before, const QuantitySelection& current,
                                 const std::vector<PlotCurve>& after) {
  const bool sameQuantities =
      std::equal(before.begin(), before.end(), after.begin(), after.end(),
                 [](const PlotCurve& x, const PlotCurve& y) { return x.quantity == y.quantity; });
  return sameQuantities ? current : defaultSelection(after);
}

std::optional<QuantitySelection> selectionOfKeys(const std::vector<PlotCurve>& curves, const QStringList& keys,
                                                 QString& unknown) {
  for (const QString& key : keys)
    if (std::none_of(curves.begin(), curves.end(), [&](const PlotCurve& c) { return c.key == key; })) {
      unknown = key;
      return std::nullopt;
    }
  QuantitySelection s;
  for (const PlotCurve& c : curves) s.set(c.quantity, keys.contains(c.key));
  return s;
}

k::SolveRequest requestFor(const QuantitySelection& s, const std::vector<PlotCurve>& curves) {
  const bool accelerations = s.any(QuantityKind::Alpha, curves) || s.any(QuantityKind::Acceleration, curves);
  const bool velocities = s.any(QuantityKind::Omega, curves) || s.any(QuantityKind::Velocity, curves);
  return {velocities || accelerations, accelerations};
}

}  // namespace linkwright::ui
