#include "ui/canvas/driven_path_item.h"

#include "ui/canvas/canvas_style.h"
#include "ui/geometry.h"

#include "kinematics/model/path_shape.h"
#include "kinematics/model/units.h"

#include <QFont>
#include <QGraphicsSimpleTextItem>
#include <QPainterPath>
#include <QPen>

#include <algorithm>
#include <cmath>

namespace linkwright::ui {

namespace k = kinematics;

namespace {

constexpr QColor kUnreachableColor{214, 39, 40};
constexpr double kGuideWidthPx = 1.5;
constexpr double kUnreachableWidthPx = 4.0;
constexpr int kArcSteps = 96;  // segments for a full turn

QPen cosmetic(const QColor& color, double width, Qt::PenStyle style) {
  QPen pen(color, width, style, Qt::RoundCap, Qt::RoundJoin);
  pen.setCosmetic(true);
  return pen;
}

}  // namespace

QPainterPath pathCurve(const k::PathShape& shape, double from, double to) {
  QPainterPath curve;
  curve.moveTo(toQt(k::pathAt(shape, from).point));
  if (const auto* line = std::get_if<k::PolylinePath>(&shape)) {
    double start = 0.0;
    for (std::size_t v = 0; v + 1 < line->vertices.size(); ++v) {
      start += (line->vertices[v + 1] - line->vertices[v]).norm();
      if (start > from && start < to) curve.lineTo(toQt(line->vertices[v + 1]));
    }
  } else {
    const auto& arc = std::get<k::ArcPath>(shape);
    const double turn = (to - from) / arc.radius;
    const int steps = std::max(2, static_cast<int>(std::ceil(kArcSteps * turn / (2.0 * k::kPi))));
    for (int i = 1; i < steps; ++i) curve.lineTo(toQt(k::pathAt(shape, from + (to - from) * i / steps).point));
  }
  curve.lineTo(toQt(k::pathAt(shape, to).point));
  return curve;
}

DrivenPathItem::DrivenPathItem(QGraphicsItem* parent)
    : QGraphicsPathItem(parent), m_unreachable(new QGraphicsPathItem(this)) {
  setZValue(canvas::z::kSlideway);
  applyPens();
}

void DrivenPathItem::setShape(const k::PathShape& shape, const std::vector<Stretch>& unreachable) {
  setPath(pathCurve(shape, 0.0, k::pathLength(shape)));
  QPainterPath out;
  for (QGraphicsSimpleTextItem* label : m_labels) delete label;
  m_labels.clear();
  for (const Stretch& s : unreachable) {
    out.addPath(pathCurve(shape, s.from, s.to));
    auto* label = new QGraphicsSimpleTextItem(s.label, this);
    label->setBrush(kUnreachableColor);
    label->setFlag(ItemIgnoresTransformations);  // text stays upright and pixel-sized
    label->setPos(toQt(k::pathAt(shape, 0.5 * (s.from + s.to)).point));
    m_labels.push_back(label);
  }
  m_unreachable->setPath(out);
  applyPens();
}

std::vector<QString> DrivenPathItem::stretchLabels() const {
  std::vector<QString> out;
  for (const QGraphicsSimpleTextItem* label : m_labels) out.push_back(label->text());
  return out;
}

void DrivenPathItem::setPresentationScale(double factor) {
  m_scale = factor;
  applyPens();
}

void DrivenPathItem::applyPens() {
  setPen(cosmetic(colors().frame, kGuideWidthPx * m_scale, Qt::DashDotLine));
  m_unreachable->setPen(cosmetic(kUnreachableColor, kUnreachableWidthPx * m_scale, Qt::SolidLine));
  QFont font;
  font.setPointSizeF(canvas::kLabelPointSize * m_scale);
  for (QGraphicsSimpleTextItem* label : m_labels) label->setFont(font);
}

}  // namespace linkwright::ui
