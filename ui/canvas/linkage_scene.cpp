#include "ui/canvas/linkage_scene.h"

#include "ui/canvas/arrow_item.h"
#include "ui/canvas/canvas_style.h"
#include "ui/canvas/coupler_path_item.h"
#include "ui/canvas/drag_handles.h"
#include "ui/canvas/feasible_range_item.h"
#include "ui/canvas/ground_pivot_item.h"
#include "ui/canvas/joint_handle_item.h"
#include "ui/canvas/label_item.h"
#include "ui/canvas/link_item.h"
#include "ui/document/mechanism_document.h"
#include "ui/geometry.h"

#include <QGraphicsLineItem>
#include <QGraphicsPolygonItem>
#include <QPen>

#include <algorithm>
#include <cmath>
#include <vector>

namespace linkwright::ui {

namespace k = kinematics;
namespace fourbar = kinematics::fourbar;
using kinematics::FourBarHandle;

namespace {

// The longest arrow of the cycle is this fraction of the linkage's size.
constexpr double kLongestArrowFraction = 0.3;
// The range arc's rays reach this far past the crank radius (see FeasibleRangeItem).
constexpr double kRangeReach = 1.12;
constexpr double kLabelDistancePx = 9.0;
constexpr double kMessageWidthPx = 340.0;

// The order of LinkageScene::m_pointLabels.
constexpr std::array<FourBarHandle, 5> kLabelledHandles{FourBarHandle::O2, FourBarHandle::O4, FourBarHandle::B, FourBarHandle::C,
                                                        FourBarHandle::CouplerPoint};
constexpr std::array<k::PointId, 3> kArrowPointIds{fourbar::kB, fourbar::kC, fourbar::kCouplerPoint};

QString formatMagnitude(double value) {
  if (!(value > 0.0) || !std::isfinite(value)) return QStringLiteral("0");
  const int digits = static_cast<int>(std::floor(std::log10(value)));
  return QString::number(value, 'f', std::clamp(2 - digits, 0, 6));
}

// Puts a point's name on the side away from the links that meet there (screen layout only);
// a ground pivot's name goes beside it, on the side away from the frame line.
void placeLabel(LabelItem* label, const QPointF& at, const std::vector<QPointF>& neighbours, bool ground) {
  QPointF away(0.0, 0.0);
  for (const QPointF& n : neighbours) {
    const QPointF d = n - at;
    const double length = std::hypot(d.x(), d.y());
    if (length > 0.0) away -= d / length;
  }
  // Beside a pivot, a little above the frame line: its support is below and its link above.
  if (ground) away = QPointF(away.x() < 0.0 ? -1.0 : 1.0, 0.25);
  if (std::hypot(away.x(), away.y()) < 1e-6) away = QPointF(1.0, 1.0);
  label->setPos(at);
  label->placeToward(away, kLabelDistancePx);
}

QPen cosmeticPen(const QColor& color, double width, Qt::PenStyle style = Qt::SolidLine) {
  QPen pen(color, width, style, Qt::RoundCap, Qt::RoundJoin);
  pen.setCosmetic(true);
  return pen;
}

} // namespace

LinkageScene::LinkageScene(QObject* parent)
    : QGraphicsScene(parent), m_frame(new QGraphicsLineItem), m_range(new FeasibleRangeItem), m_path(new CouplerPathItem),
      m_couplerTriangle(new QGraphicsPolygonItem), m_crank(new LinkItem(canvas::kCrankColor)),
      m_coupler(new LinkItem(canvas::kCouplerColor)), m_rocker(new LinkItem(canvas::kRockerColor)),
      m_groundO2(new GroundPivotItem), m_groundO4(new GroundPivotItem), m_pinB(new JointHandleItem(JointHandleItem::Style::Pin)),
      m_pinC(new JointHandleItem(JointHandleItem::Style::Pin)),
      m_dotP(new JointHandleItem(JointHandleItem::Style::Dot, canvas::kCouplerPointColor)), m_message(new LabelItem) {
  setBackgroundBrush(Qt::white);
  m_frame->setPen(cosmeticPen(canvas::kFrameColor, canvas::kFrameWidthPx, Qt::DashLine));
  m_frame->setZValue(canvas::z::kFrame);
  m_couplerTriangle->setPen(cosmeticPen(canvas::kCouplerColor.lighter(130), 1.0));
  m_couplerTriangle->setBrush(canvas::kCouplerFillColor);
  m_couplerTriangle->setZValue(canvas::z::kCouplerTriangle);
  for (QGraphicsItem* item : std::initializer_list<QGraphicsItem*>{
           m_frame, m_range, m_path, m_couplerTriangle, m_crank, m_coupler, m_rocker, m_groundO2, m_groundO4, m_pinB, m_pinC,
           m_dotP, m_message})
    addItem(item);
  for (std::size_t i = 0; i < m_pointLabels.size(); ++i) {
    m_pointLabels[i] = new LabelItem;
    m_pointLabels[i]->setText(handleName(kLabelledHandles[i]));
    addItem(m_pointLabels[i]);
  }
  for (std::size_t i = 0; i < kArrowPoints; ++i) {
    m_velocityArrows[i] = new ArrowItem(canvas::kVelocityColor);
    m_accelerationArrows[i] = new ArrowItem(canvas::kAccelerationColor);
    addItem(m_velocityArrows[i]);
    addItem(m_accelerationArrows[i]);
    m_velocityArrows[i]->setVisible(false);
    m_accelerationArrows[i]->setVisible(false);
  }
  m_message->setBoxed(true);
  m_message->setMaximumWidth(kMessageWidthPx);
  m_message->setColor(canvas::kRefusalColor);
  m_message->setPlacement(QPointF(14.0, 14.0), Qt::AlignLeft | Qt::AlignTop);
  m_message->setZValue(canvas::z::kMessage);
  m_message->setVisible(false);
}

void LinkageScene::updateDesign(const MechanismDocument& document) {
  const k::FourBarDesign& design = document.design();
  m_hasCouplerPoint = design.couplerPoint.has_value() && document.pose().position.size() > fourbar::kCouplerPoint.index;
  m_path->setFromSweep(document.sweep(), fourbar::kCouplerPoint);
  m_path->setVisible(m_hasCouplerPoint);
  m_couplerTriangle->setVisible(m_hasCouplerPoint);
  m_dotP->setVisible(m_hasCouplerPoint);
  m_pointLabels[4]->setVisible(m_hasCouplerPoint);

  const k::InputRange& range = document.analysis().inputRange;
  m_range->setVisible(!range.fullRotation);
  if (!range.fullRotation)
    m_range->setRange(range, toQt(document.pose().position[fourbar::kO2.index]), design.lengths.crank);

  computeBounds(document);
  computeArrowScales(document);
  const double margin = 0.1 * linkageSize();
  setSceneRect(m_bounds.adjusted(-margin, -margin, margin, margin));  // what an export shows
  updatePose(document);
}

void LinkageScene::computeBounds(const MechanismDocument& document) {
  const k::SweepResult& sweep = document.sweep();
  double left = 0.0, right = 0.0, bottom = 0.0, top = 0.0;
  bool any = false;
  const auto include = [&](const QPointF& p) {
    left = any ? std::min(left, p.x()) : p.x();
    right = any ? std::max(right, p.x()) : p.x();
    bottom = any ? std::min(bottom, p.y()) : p.y();
    top = any ? std::max(top, p.y()) : p.y();
    any = true;
  };
  for (const auto& column : sweep.position)
    for (std::size_t j = 0; j < column.size() && j < sweep.size(); ++j)
      if (sweep.assembled(j)) include(toQt(column[j]));
  for (const Eigen::Vector2d& p : document.pose().position) include(toQt(p));
  if (m_range->isVisible()) {
    const QPointF o2 = toQt(document.pose().position[fourbar::kO2.index]);
    const double r = kRangeReach * document.design().lengths.crank;
    include(o2 - QPointF(r, r));
    include(o2 + QPointF(r, r));
  }
  m_bounds = QRectF(QPointF(left, bottom), QPointF(right, top));
}

double LinkageScene::linkageSize() const {
  const double size = std::max(m_bounds.width(), m_bounds.height());
  return size > 0.0 && std::isfinite(size) ? size : 1.0;
}

void LinkageScene::computeArrowScales(const MechanismDocument& document) {
  // Fixed per design from the whole cycle, so arrows grow and shrink as the linkage moves.
  const k::SweepResult& sweep = document.sweep();
  const auto longest = [&](const std::vector<std::vector<Eigen::Vector2d>>& columns,
                           const std::vector<Eigen::Vector2d>& current) {
    double most = 0.0;
    for (const k::PointId p : kArrowPointIds) {
      if (p == fourbar::kCouplerPoint && !m_hasCouplerPoint) continue;
      if (p.index < current.size()) most = std::max(most, current[p.index].norm());
      if (p.index >= columns.size()) continue;
      for (std::size_t j = 0; j < columns[p.index].size() && j < sweep.size(); ++j)
        if (sweep.ok(j)) most = std::max(most, columns[p.index][j].norm());
    }
    return most;
  };
  const double size = linkageSize();
  const auto scaleFor = [&](double most) { return most > 0.0 && std::isfinite(most) ? kLongestArrowFraction * size / most : 0.0; };
  m_velocityScale = scaleFor(longest(sweep.velocity, document.pose().velocity));
  m_accelerationScale = scaleFor(longest(sweep.acceleration, document.pose().acceleration));
}

void LinkageScene::updatePose(const MechanismDocument& document) {
  const auto& position = document.pose().position;
  const auto at = [&](k::PointId id) { return id.index < position.size() ? toQt(position[id.index]) : QPointF(); };
  const QPointF o2 = at(fourbar::kO2), o4 = at(fourbar::kO4), b = at(fourbar::kB), c = at(fourbar::kC);
  m_frame->setLine(QLineF(o2, o4));
  m_crank->setEnds(o2, b);
  m_coupler->setEnds(b, c);
  m_rocker->setEnds(o4, c);
  m_groundO2->setPos(o2);
  m_groundO4->setPos(o4);
  m_pinB->setPos(b);
  m_pinC->setPos(c);
  if (m_hasCouplerPoint) {
    const QPointF p = at(fourbar::kCouplerPoint);
    m_dotP->setPos(p);
    m_couplerTriangle->setPolygon(QPolygonF({b, c, p}));
  }
  const QPointF p = m_hasCouplerPoint ? at(fourbar::kCouplerPoint) : QPointF();
  placeLabel(m_pointLabels[0], o2, {b, o4}, true);
  placeLabel(m_pointLabels[1], o4, {c, o2}, true);
  placeLabel(m_pointLabels[2], b, m_hasCouplerPoint ? std::vector<QPointF>{o2, c, p} : std::vector<QPointF>{o2, c}, false);
  placeLabel(m_pointLabels[3], c, m_hasCouplerPoint ? std::vector<QPointF>{b, o4, p} : std::vector<QPointF>{b, o4}, false);
  if (m_hasCouplerPoint) placeLabel(m_pointLabels[4], p, {b, c}, false);
  updateArrows(document);
}

void LinkageScene::updateArrows(const MechanismDocument& document) {
  const k::Pose& pose = document.pose();
  const bool rates = document.poseStatus() == k::PoseStatus::Ok;
  const QString unit = QString::fromStdString(document.design().lengthUnit);
  const auto place = [&](ArrowItem* arrow, k::PointId p, bool show, double scale, const std::vector<Eigen::Vector2d>& column,
                         const QString& perTime) {
    const bool exists = p != fourbar::kCouplerPoint || m_hasCouplerPoint;
    const bool visible = show && rates && exists && scale > 0.0 && p.index < column.size() && p.index < pose.position.size();
    arrow->setVisible(visible);
    if (!visible) return;
    const Eigen::Vector2d& value = column[p.index];
    arrow->setArrow(toQt(pose.position[p.index]), scale * toQt(value), tr("%1 %2%3").arg(formatMagnitude(value.norm()), unit, perTime));
  };
  for (std::size_t i = 0; i < kArrowPoints; ++i) {
    place(m_velocityArrows[i], kArrowPointIds[i], m_showVelocity, m_velocityScale, pose.velocity, tr("/s"));
    place(m_accelerationArrows[i], kArrowPointIds[i], m_showAcceleration, m_accelerationScale, pose.acceleration,
          tr("/s\u00B2"));
  }
}

void LinkageScene::setPresentationScale(double factor) {
  m_presentationScale = factor;
  for (LinkItem* link : {m_crank, m_coupler, m_rocker}) link->setPresentationScale(factor);
  m_path->setPresentationScale(factor);
  m_range->setPresentationScale(factor);
  for (QGraphicsItem* item : std::initializer_list<QGraphicsItem*>{m_groundO2, m_groundO4, m_pinB, m_pinC, m_dotP, m_message})
    item->setScale(factor);
  for (LabelItem* label : m_pointLabels) label->setScale(factor);
  for (std::size_t i = 0; i < kArrowPoints; ++i) {
    m_velocityArrows[i]->setPresentationScale(factor);
    m_accelerationArrows[i]->setPresentationScale(factor);
  }
  m_frame->setPen(cosmeticPen(canvas::kFrameColor, canvas::kFrameWidthPx * factor, Qt::DashLine));
  m_couplerTriangle->setPen(cosmeticPen(canvas::kCouplerColor.lighter(130), factor));
}

void LinkageScene::setShowVelocityArrows(bool show) {
  m_showVelocity = show;
  for (ArrowItem* arrow : m_velocityArrows) arrow->setVisible(false);
}

void LinkageScene::setShowAccelerationArrows(bool show) {
  m_showAcceleration = show;
  for (ArrowItem* arrow : m_accelerationArrows) arrow->setVisible(false);
}

std::optional<QPointF> LinkageScene::handlePosition(FourBarHandle handle) const {
  if (handle == FourBarHandle::CouplerPoint && !m_hasCouplerPoint) return std::nullopt;
  return handleItem(handle)->pos();
}

const QGraphicsItem* LinkageScene::handleItem(FourBarHandle handle) const {
  switch (handle) {
  case FourBarHandle::O2: return m_groundO2;
  case FourBarHandle::O4: return m_groundO4;
  case FourBarHandle::B: return m_pinB;
  case FourBarHandle::C: return m_pinC;
  case FourBarHandle::CouplerPoint: return m_dotP;
  }
  return m_pinB;
}

void LinkageScene::setHotHandle(std::optional<FourBarHandle> handle) {
  const auto is = [&](FourBarHandle h) { return handle.has_value() && *handle == h; };
  m_groundO2->setHot(is(FourBarHandle::O2));
  m_groundO4->setHot(is(FourBarHandle::O4));
  m_pinB->setHot(is(FourBarHandle::B));
  m_pinC->setHot(is(FourBarHandle::C));
  m_dotP->setHot(is(FourBarHandle::CouplerPoint));
}

const LinkItem* LinkageScene::linkItem(k::LinkId link) const {
  if (link == fourbar::kCrank) return m_crank;
  if (link == fourbar::kCoupler) return m_coupler;
  if (link == fourbar::kRocker) return m_rocker;
  return nullptr;
}

int LinkageScene::arrowSlot(k::PointId point) {
  for (std::size_t i = 0; i < kArrowPointIds.size(); ++i)
    if (kArrowPointIds[i] == point) return static_cast<int>(i);
  return -1;
}

const ArrowItem* LinkageScene::velocityArrow(k::PointId point) const {
  const int slot = arrowSlot(point);
  return slot < 0 ? nullptr : m_velocityArrows[static_cast<std::size_t>(slot)];
}

const ArrowItem* LinkageScene::accelerationArrow(k::PointId point) const {
  const int slot = arrowSlot(point);
  return slot < 0 ? nullptr : m_accelerationArrows[static_cast<std::size_t>(slot)];
}

void LinkageScene::showMessage(const QPointF& scenePos, const QString& text) {
  m_message->setText(text);
  m_message->setPos(scenePos);
  m_message->setVisible(true);
}

void LinkageScene::hideMessage() { m_message->setVisible(false); }

} // namespace linkwright::ui
