#include "ui/canvas/feasible_range_item.h"

#include "ui/number_text.h"

#include "ui/canvas/canvas_style.h"

#include "kinematics/model/units.h"

#include <QPainter>

#include <algorithm>
#include <cmath>
#include <vector>

namespace linkwright::ui {

namespace k = kinematics;

namespace {

constexpr double kTwoPi = 2.0 * k::kPi;
constexpr double kRayFactor = 1.12;  // limit rays reach a little past the arc

QPointF onCircle(const QPointF& centre, double radius, double angle) {
  return centre + radius * QPointF(std::cos(angle), std::sin(angle));
}

// Appends an arc as a polyline (scene y is up, so plain cos/sin go counter-clockwise).
void addArc(QPainterPath& path, const QPointF& centre, double radius, double from, double to, bool connect) {
  const int steps = std::max(2, static_cast<int>(std::ceil((to - from) / k::degToRad(2.0))));
  for (int i = 0; i <= steps; ++i) {
    const QPointF p = onCircle(centre, radius, from + (to - from) * i / steps);
    if (i == 0 && !connect) path.moveTo(p);
    else path.lineTo(p);
  }
}

struct Arc {
  double from;
  double to;
};

// The assemblable arcs starting in [0, 2π), in order, and the gaps between them.
std::vector<Arc> complementOf(const std::vector<k::AngleRange>& ranges) {
  if (ranges.empty()) return {{0.0, kTwoPi}};
  std::vector<Arc> arcs;
  for (const k::AngleRange& r : ranges) {
    const double start = r.from - kTwoPi * std::floor(r.from / kTwoPi);
    arcs.push_back({start, start + (r.to - r.from)});
  }
  std::sort(arcs.begin(), arcs.end(), [](const Arc& a, const Arc& b) { return a.from < b.from; });
  std::vector<Arc> gaps;
  for (std::size_t i = 0; i < arcs.size(); ++i) {
    const double next = i + 1 < arcs.size() ? arcs[i + 1].from : arcs.front().from + kTwoPi;
    if (next - arcs[i].to > 1e-9) gaps.push_back({arcs[i].to, next});
  }
  return gaps;
}

QString degrees(double angle) { return numberText(k::radToDeg(angle), 'f', 1) + QChar(0x00B0); }

}  // namespace

FeasibleRangeItem::FeasibleRangeItem(QGraphicsItem* parent) : QGraphicsItem(parent) { setZValue(canvas::z::kRange); }

void FeasibleRangeItem::setRange(const k::InputRange& inputs, const QPointF& centre, double radius, double phase) {
  prepareGeometryChange();
  // The crank points at input angle + phase: the arcs are drawn where it points, the label
  // gives input angles.
  k::InputRange range = inputs;
  for (k::AngleRange& r : range.ranges) r = {r.from + phase, r.to + phase};
  m_feasibleArcs = {};
  m_infeasibleSectors = {};
  m_infeasibleArcs = {};
  m_limitRays = {};
  for (const k::AngleRange& r : range.ranges) {
    addArc(m_feasibleArcs, centre, radius, r.from, r.to, false);
    for (const double limit : {r.from, r.to}) {
      m_limitRays.moveTo(centre);
      m_limitRays.lineTo(onCircle(centre, kRayFactor * radius, limit));
    }
  }
  const std::vector<Arc> gaps = complementOf(range.ranges);
  const Arc* widest = nullptr;
  for (const Arc& gap : gaps) {
    m_infeasibleSectors.moveTo(centre);
    addArc(m_infeasibleSectors, centre, radius, gap.from, gap.to, true);
    m_infeasibleSectors.closeSubpath();
    addArc(m_infeasibleArcs, centre, radius, gap.from, gap.to, false);
    if (widest == nullptr || gap.to - gap.from > widest->to - widest->from) widest = &gap;
  }
  const double r = kRayFactor * radius;
  m_bounds = QRectF(centre - QPointF(r, r), centre + QPointF(r, r));

  QStringList parts;
  for (const k::AngleRange& rr : inputs.ranges) parts << tr("%1 to %2").arg(degrees(rr.from), degrees(rr.to));
  m_labelText = parts.isEmpty() ? tr("crank cannot be assembled at any angle")
                                : tr("crank can reach %1").arg(parts.join(tr(" and ")));
  // Outside the crank's circle (inside it a sentence wider than the crank sat over the
  // pivot's name and the crank's lines), centred above or below it, on the side of the widest
  // unreachable sector (below when it is level): a sentence is wide, and beside the circle it
  // reached past a narrow canvas's edge.
  const double middle = widest != nullptr ? (widest->from + widest->to) / 2.0 : 0.0;
  const double side = std::sin(middle) > 1e-9 ? 1.0 : -1.0;
  m_labelDirection = QPointF(0.0, side);
  m_labelAnchor = centre + QPointF(0.0, side * r);
}

void FeasibleRangeItem::setPresentationScale(double factor) {
  m_scale = factor;
  update();
}

QRectF FeasibleRangeItem::boundingRect() const { return m_bounds; }

void FeasibleRangeItem::paint(QPainter* painter, const QStyleOptionGraphicsItem*, QWidget*) {
  painter->setRenderHint(QPainter::Antialiasing);
  painter->setPen(Qt::NoPen);
  painter->setBrush(colors().infeasibleFill);
  painter->drawPath(m_infeasibleSectors);
  painter->setBrush(QBrush(colors().infeasible, Qt::BDiagPattern));  // cosmetic pattern
  painter->drawPath(m_infeasibleSectors);
  painter->setBrush(Qt::NoBrush);

  QPen rays(colors().infeasible, 1.0 * m_scale, Qt::DashLine);
  rays.setCosmetic(true);
  painter->setPen(rays);
  painter->drawPath(m_limitRays);
  QPen outline(colors().infeasible, 1.5 * m_scale, Qt::DotLine);
  outline.setCosmetic(true);
  painter->setPen(outline);
  painter->drawPath(m_infeasibleArcs);
  QPen arc(colors().feasible, canvas::kRangeArcWidthPx * m_scale, Qt::SolidLine, Qt::FlatCap);
  arc.setCosmetic(true);
  painter->setPen(arc);
  painter->drawPath(m_feasibleArcs);
}

}  // namespace linkwright::ui
