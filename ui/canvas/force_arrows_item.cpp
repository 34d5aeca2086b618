#include "ui/canvas/force_arrows_item.h"

#include "ui/canvas/canvas_style.h"
#include "ui/canvas/label_item.h"
#include "ui/document/force_results.h"
#include "ui/document/mechanism_document.h"
#include "ui/geometry.h"

#include "kinematics/solve/rigid_bodies.h"

#include <QCoreApplication>
#include <QGraphicsScene>
#include <QPainter>
#include <QTransform>

#include <algorithm>
#include <cmath>

namespace linkwright::ui {

namespace k = kinematics;

namespace {
constexpr double kLabelGapPx = 4.0;
// How many lines out a label may be moved to clear the labels of larger forces.
constexpr int kMaxLabelSteps = 6;

double overlapArea(const QRectF& box, const std::vector<QRectF>& taken) {
  double area = 0.0;
  for (const QRectF& t : taken)
    if (const QRectF common = t.intersected(box); common.isValid()) area += common.width() * common.height();
  return area;
}
}  // namespace

ForceArrowItem::ForceArrowItem(QGraphicsItem* parent) : QGraphicsItem(parent), m_label(new LabelItem(this)) {
  setFlag(ItemIgnoresTransformations);
  setZValue(canvas::z::kArrows);
  m_label->setColor(kForceArrowColor.darker(120));
  m_label->setBackdrop(true);
}

void ForceArrowItem::setArrow(const QPointF& scenePoint, const QPointF& direction, double lengthPx,
                              const QString& label) {
  prepareGeometryChange();
  setPos(scenePoint);
  const double norm = std::hypot(direction.x(), direction.y());
  m_direction = norm > 0.0 ? direction / norm : QPointF(1.0, 0.0);
  m_lengthPx = lengthPx;
  m_label->setText(label);
  m_label->setPos(tipPx());
  m_labelShift = {};
  m_label->placeToward(m_direction, kLabelGapPx * m_scale);
}

void ForceArrowItem::setLabelShift(double alongPx, double acrossPx) {
  if (m_labelShift == QPointF(alongPx, acrossPx)) return;
  m_labelShift = {alongPx, acrossPx};
  // In the item's pixels (y down): along the arrow, and its left (counter-clockwise) normal.
  const QPointF along(m_direction.x(), -m_direction.y()), left(-m_direction.y(), -m_direction.x());
  m_label->setPos(tipPx() + (alongPx * along + acrossPx * left) * m_scale);
}

QRectF ForceArrowItem::labelRect(const QTransform& sceneToPixels) const {
  return m_label->deviceTransform(sceneToPixels).mapRect(m_label->textRect());
}

void ForceArrowItem::setPresentationScale(double factor) {
  m_scale = factor;
  m_label->setScale(factor);
  update();
}

QString ForceArrowItem::label() const { return m_label->text(); }

QPointF ForceArrowItem::tipPx() const { return QPointF(m_direction.x(), -m_direction.y()) * m_lengthPx; }

QRectF ForceArrowItem::boundingRect() const {
  const double pad = (canvas::kArrowHeadPx + canvas::kArrowWidthPx) * m_scale;
  return QRectF(QPointF(0.0, 0.0), tipPx()).normalized().adjusted(-pad, -pad, pad, pad);
}

void ForceArrowItem::paint(QPainter* painter, const QStyleOptionGraphicsItem*, QWidget*) {
  if (!(m_lengthPx > 1.0)) return;
  painter->setRenderHint(QPainter::Antialiasing);
  const QPointF tip = tipPx();
  const QPointF unit = tip / m_lengthPx;
  const QPointF normal(-unit.y(), unit.x());
  const double head = std::min(canvas::kArrowHeadPx * m_scale, 0.6 * m_lengthPx);
  const QPointF base = tip - head * unit;
  painter->setPen(QPen(kForceArrowColor, canvas::kArrowWidthPx * m_scale, Qt::SolidLine, Qt::RoundCap));
  painter->drawLine(QPointF(0.0, 0.0), base);
  painter->setPen(Qt::NoPen);
  painter->setBrush(kForceArrowColor);
  const QPointF triangle[] = {tip, base + 0.4 * head * normal, base - 0.4 * head * normal};
  painter->drawPolygon(triangle, 3);
}

ForceArrowsItem::ForceArrowsItem(QGraphicsItem* parent) : QGraphicsItem(parent) {
  setFlag(ItemHasNoContents);
  setZValue(canvas::z::kArrows);
}

ForceArrowItem* ForceArrowsItem::arrowAt(std::size_t index) {
  while (m_arrows.size() <= index) {
    auto* arrow = new ForceArrowItem(this);
    arrow->setPresentationScale(m_scale);
    m_arrows.push_back(arrow);
  }
  return m_arrows[index];
}

void ForceArrowsItem::setForces(const MechanismDocument& document, const ForceResults& forces) {
  const k::PoseForces* f = forces.poseForces();
  const k::BodyModel* bodies = forces.bodies();
  const double peak = forces.peakJointForce();
  std::size_t used = 0;
  double longest = kForceArrowLengthPx * m_scale;
  if (!m_canvas.isEmpty())
    longest = std::min(longest, kForceArrowCanvasShare * std::min(m_canvas.width(), m_canvas.height()));
  if (f != nullptr && bodies != nullptr && peak > 0.0) {
    const k::Pose& pose = document.pose();
    const auto place = [&](const Eigen::Vector2d& at, const Eigen::Vector2d& force) {
      const double size = force.norm();
      ForceArrowItem* arrow = arrowAt(used++);
      arrow->setArrow(toQt(at), toQt(force), std::min(1.0, size / peak) * longest,
                      QCoreApplication::translate("ForceArrowsItem", "%1 N").arg(formatForce(size)));
      arrow->setVisible(true);
    };
    for (std::size_t i = 0; i < bodies->revolutes.size() && i < f->revolute.size(); ++i)
      place(pose.position[bodies->revolutes[i].point.index], f->revolute[i]);
    for (std::size_t i = 0; i < bodies->prismatics.size() && i < f->normal.size(); ++i) {
      const k::PrismaticJoint& joint = bodies->prismatics[i];
      // The core's normal force acts along n = u⊥ (inverse_dynamics.h), u the sliding direction.
      const Eigen::Vector2d u = k::prismaticDirection(document.mechanism(), joint, pose);
      place(pose.position[joint.pin.index], f->normal[i] * Eigen::Vector2d(-u.y(), u.x()));
    }
  }
  for (std::size_t i = used; i < m_arrows.size(); ++i) m_arrows[i]->setVisible(false);
  separateLabels();
}

bool ForceArrowsItem::showsArrows() const {
  return isVisible() &&
         std::any_of(m_arrows.begin(), m_arrows.end(), [](const ForceArrowItem* a) { return a->isVisible(); });
}

void ForceArrowsItem::setPresentationScale(double factor) {
  m_scale = factor;
  for (ForceArrowItem* arrow : m_arrows) arrow->setPresentationScale(factor);
  separateLabels();
}

void ForceArrowsItem::setCanvasSize(const QSizeF& pixels) { m_canvas = pixels; }

void ForceArrowsItem::setViewScale(double pixelsPerUnit) {
  if (pixelsPerUnit == m_pixelsPerUnit) return;
  m_pixelsPerUnit = pixelsPerUnit;
  separateLabels();
}

// Two joints near each other on screen with forces alike (a crank's two pins) put their arrows'
// tips, and so their labels, on top of each other, and a short arrow's label falls on its
// joint's name. In order of size, each label is moved beside its tip, either side, or out along
// its arrow, a line at a time, until its box is clear of the points' names and the labels of
// larger forces (at most kMaxLabelSteps lines; else where it overlaps least). Where the feet are
// on screen follows the canvas's scale, so this is redone when the scale changes.
void ForceArrowsItem::separateLabels() {
  std::vector<ForceArrowItem*> shown;
  for (ForceArrowItem* arrow : m_arrows)
    if (arrow->isVisible()) shown.push_back(arrow);
  std::stable_sort(shown.begin(), shown.end(),
                   [](const ForceArrowItem* a, const ForceArrowItem* b) { return a->lengthPx() > b->lengthPx(); });
  for (ForceArrowItem* arrow : shown) arrow->setLabelShift(0.0, 0.0);
  if (!(m_pixelsPerUnit > 0.0)) return;
  // The view's translation moves every box alike, so the scale alone places them.
  const QTransform toPixels = QTransform::fromScale(m_pixelsPerUnit, -m_pixelsPerUnit);
  std::vector<QRectF> taken;
  if (scene() != nullptr)
    for (const QGraphicsItem* item : scene()->items()) {
      const auto* label = dynamic_cast<const LabelItem*>(item);
      const bool ours = std::any_of(m_arrows.begin(), m_arrows.end(),
                                    [&](const ForceArrowItem* a) { return a->labelItem() == label; });
      if (label != nullptr && !ours && label->isVisible() && !label->text().isEmpty())
        taken.push_back(label->deviceTransform(toPixels).mapRect(label->textRect()));
    }
  for (ForceArrowItem* arrow : shown) {
    const double line = arrow->labelRect(toPixels).height() / m_scale;
    QPointF best;
    double least = overlapArea(arrow->labelRect(toPixels), taken);
    // Beside the tip first, either side (parallel arrows' labels stack), then farther out.
    for (int step = 1; step <= kMaxLabelSteps && least > 0.0; ++step)
      for (const QPointF shift : {QPointF(0.0, step), QPointF(0.0, -step), QPointF(step, 0.0)}) {
        arrow->setLabelShift(shift.x() * line, shift.y() * line);
        if (const double o = overlapArea(arrow->labelRect(toPixels), taken); o < least) {
          least = o;
          best = shift;
          if (o == 0.0) break;
        }
      }
    arrow->setLabelShift(best.x() * line, best.y() * line);
    taken.push_back(arrow->labelRect(toPixels));
  }
}

}  // namespace linkwright::ui
