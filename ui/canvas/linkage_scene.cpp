#include "ui/canvas/linkage_scene.h"

#include "ui/canvas/mass_centres_item.h"
#include "ui/canvas/springs_item.h"

#include "ui/number_text.h"

#include "ui/canvas/arrow_item.h"
#include "ui/canvas/canvas_style.h"
#include "ui/canvas/drag_handles.h"
#include "ui/canvas/feasible_range_item.h"
#include "ui/canvas/instant_centres_item.h"
#include "ui/canvas/label_item.h"
#include "ui/canvas/mechanism_items.h"
#include "ui/document/mechanism_document.h"
#include "ui/geometry.h"

#include "kinematics/model/fourbar.h"

#include <algorithm>
#include <cmath>

namespace linkwright::ui {

namespace k = kinematics;

namespace {

// The longest arrow of the cycle is this fraction of the linkage's size.
constexpr double kLongestArrowFraction = 0.3;
// The range arc's rays reach this far past the crank radius (see FeasibleRangeItem).
constexpr double kRangeReach = 1.12;
constexpr double kMessageWidthPx = 340.0;
constexpr double kRangeLabelGapPx = 4.0;  // between the range's rays and its sentence

QString formatMagnitude(double value) {
  if (!(value > 0.0) || !std::isfinite(value)) return QStringLiteral("0");
  const int digits = static_cast<int>(std::floor(std::log10(value)));
  return numberText(value, 'f', std::clamp(2 - digits, 0, 6));
}

}  // namespace

LinkageScene::LinkageScene(QObject* parent)
    : QGraphicsScene(parent), m_range(new FeasibleRangeItem), m_centres(new InstantCentresItem),
      m_springs(new SpringsItem), m_massCentres(new MassCentresItem), m_message(new LabelItem),
      m_rangeLabel(new LabelItem) {
  setBackgroundBrush(colors().canvasBackground);
  // The links and labels move on every frame of a drag, and Qt rebuilds its BSP index for
  // each move; a plain search serves a few dozen items as fast (Qt's advice for moving scenes).
  setItemIndexMethod(NoIndex);
  addItem(m_range);
  addItem(m_centres);
  m_centres->setVisible(false);
  addItem(m_springs);
  addItem(m_massCentres);
  addItem(m_message);
  m_message->setBoxed(true);
  m_message->setMaximumWidth(kMessageWidthPx);
  m_message->setColor(colors().refusal);
  m_message->setPlacement(QPointF(14.0, 14.0), Qt::AlignLeft | Qt::AlignTop);
  m_message->setZValue(canvas::z::kMessage);
  m_message->setVisible(false);
  addItem(m_rangeLabel);
  m_rangeLabel->setBoxed(true);
  m_rangeLabel->setColor(colors().infeasible.darker(170));
  m_rangeLabel->setZValue(canvas::z::kLabels);
  m_rangeLabel->setVisible(false);
}

// The items go before the QGraphicsScene base deletes whatever is left.
LinkageScene::~LinkageScene() = default;

void LinkageScene::updateDesign(const MechanismDocument& document) {
  const k::Mechanism& m = document.mechanism();
  DrawingPlan plan = planDrawing(m);
  if (!m_items || m_items->plan() != plan || m_colorsChanged) {
    m_items.reset();
    m_items = std::make_unique<MechanismItems>(this, m, std::move(plan), m_linkColors);
    m_colorsChanged = false;
    m_items->setPresentationScale(m_presentationScale);
    m_handles = dragHandles(m_items->plan(), m);
    rebuildArrows(m.points.size());
  }
  const k::InputRange& range = document.analysis().inputRange;
  const k::CrankPoint* crank = crankOf(m);
  m_range->setVisible(!range.fullRotation && crank != nullptr);
  if (m_range->isVisible())
    m_range->setRange(range, toQt(document.pose().position[crank->pivot.index]), crank->length, crank->phase);
  placeRangeLabel();

  computeBounds(document);
  m_items->setDesign(m, document.sweep(), document.pose(), linkageSize(), document.design().time);
  // Slideways and slotted bars reach a little past the points; a fit shows them whole.
  if (const QRectF extra = m_items->extraExtent(); !extra.isNull()) m_bounds = m_bounds.united(extra);
  computeArrowScales(document);
  m_springs->setSprings(m, document.design().dynamics.loads.springs, 0.04 * linkageSize());
  m_massCentres->setMasses(m, document.design().dynamics.links, 0.025 * linkageSize());
  if (m_centres->isVisible()) m_centres->setCentrodes(document.centrodes());
  const double margin = 0.1 * linkageSize();
  setSceneRect(m_bounds.adjusted(-margin, -margin, margin, margin));  // what an export shows
  updatePose(document);
}

void LinkageScene::rebuildArrows(std::size_t points) {
  for (ArrowItem* arrow : m_velocityArrows) delete arrow;
  for (ArrowItem* arrow : m_accelerationArrows) delete arrow;
  m_velocityArrows.assign(points, nullptr);
  m_accelerationArrows.assign(points, nullptr);
  for (std::size_t i = 0; i < points; ++i) {
    if (m_items->plan().ground[i]) continue;
    m_velocityArrows[i] = new ArrowItem(colors().velocity);
    m_accelerationArrows[i] = new ArrowItem(colors().acceleration);
    for (ArrowItem* arrow : {m_velocityArrows[i], m_accelerationArrows[i]}) {
      addItem(arrow);
      arrow->setVisible(false);
      arrow->setPresentationScale(m_presentationScale);
    }
  }
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
    const k::CrankPoint* crank = crankOf(document.mechanism());
    const QPointF pivot = toQt(document.pose().position[crank->pivot.index]);
    const double r = kRangeReach * crank->length;
    include(pivot - QPointF(r, r));
    include(pivot + QPointF(r, r));
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
    for (std::size_t p = 0; p < m_velocityArrows.size(); ++p) {
      if (m_velocityArrows[p] == nullptr) continue;
      if (p < current.size()) most = std::max(most, current[p].norm());
      if (p >= columns.size()) continue;
      for (std::size_t j = 0; j < columns[p].size() && j < sweep.size(); ++j)
        if (sweep.ok(j)) most = std::max(most, columns[p][j].norm());
    }
    return most;
  };
  const double size = linkageSize();
  const auto scaleFor = [&](double most) {
    return most > 0.0 && std::isfinite(most) ? kLongestArrowFraction * size / most : 0.0;
  };
  m_velocityScale = scaleFor(longest(sweep.velocity, document.pose().velocity));
  m_accelerationScale = scaleFor(longest(sweep.acceleration, document.pose().acceleration));
}

void LinkageScene::updatePose(const MechanismDocument& document) {
  m_items->setPose(document.mechanism(), document.pose());
  m_springs->setPose(document.pose());
  m_massCentres->setPose(document.pose());
  if (m_centres->isVisible()) m_centres->setCentres(document.centresAtPose());
  updateArrows(document);
}

void LinkageScene::updateArrows(const MechanismDocument& document) {
  const k::Pose& pose = document.pose();
  const bool rates = document.poseStatus() == k::PoseStatus::Ok;
  const QString unit = QString::fromStdString(document.lengthUnit());
  const auto place = [&](ArrowItem* arrow, std::size_t p, bool show, double scale,
                         const std::vector<Eigen::Vector2d>& column, const QString& perTime) {
    const bool visible = show && rates && scale > 0.0 && p < column.size() && p < pose.position.size();
    arrow->setVisible(visible);
    if (!visible) return;
    const Eigen::Vector2d& value = column[p];
    arrow->setArrow(toQt(pose.position[p]), scale * toQt(value),
                    tr("%1 %2%3").arg(formatMagnitude(value.norm()), unit, perTime));
  };
  for (std::size_t p = 0; p < m_velocityArrows.size(); ++p) {
    if (m_velocityArrows[p] == nullptr) continue;
    place(m_velocityArrows[p], p, m_showVelocity, m_velocityScale, pose.velocity, tr("/s"));
    place(m_accelerationArrows[p], p, m_showAcceleration, m_accelerationScale, pose.acceleration, tr("/s\u00B2"));
  }
}

void LinkageScene::setRangeLabelShown(bool shown) {
  m_rangeLabelShown = shown;
  placeRangeLabel();
}

void LinkageScene::placeRangeLabel() {
  m_rangeLabel->setVisible(m_rangeLabelShown && m_range->isVisible());
  if (!m_rangeLabel->isVisible()) return;
  m_rangeLabel->setText(m_range->labelText());
  m_rangeLabel->setPos(m_range->labelAnchor());
  m_rangeLabel->placeToward(m_range->labelDirection(), kRangeLabelGapPx);
}

void LinkageScene::setLinkColors(std::vector<QColor> colors) {
  m_colorsChanged = colors != m_linkColors;
  m_linkColors = std::move(colors);
}

void LinkageScene::setPresentationScale(double factor) {
  m_presentationScale = factor;
  if (m_items) m_items->setPresentationScale(factor);
  m_range->setPresentationScale(factor);
  m_centres->setPresentationScale(factor);
  m_springs->setPresentationScale(factor);
  m_massCentres->setPresentationScale(factor);
  m_message->setScale(factor);
  m_rangeLabel->setScale(factor);
  for (auto* arrows : {&m_velocityArrows, &m_accelerationArrows})
    for (ArrowItem* arrow : *arrows)
      if (arrow != nullptr) arrow->setPresentationScale(factor);
}

void LinkageScene::refreshColors(const MechanismDocument& document) {
  setBackgroundBrush(colors().canvasBackground);
  m_message->setColor(colors().refusal);
  m_rangeLabel->setColor(colors().infeasible.darker(170));
  m_items.reset();  // bars, plates, blocks, slideways and arrows were given their colours when made
  updateDesign(document);
  update();
}

void LinkageScene::setShowVelocityArrows(bool show) {
  m_showVelocity = show;
  for (ArrowItem* arrow : m_velocityArrows)
    if (arrow != nullptr) arrow->setVisible(false);
}

void LinkageScene::setShowAccelerationArrows(bool show) {
  m_showAcceleration = show;
  for (ArrowItem* arrow : m_accelerationArrows)
    if (arrow != nullptr) arrow->setVisible(false);
}

void LinkageScene::setShowInstantCentres(bool show, const MechanismDocument& document) {
  m_centres->setVisible(show);
  if (!show) return;
  m_centres->setCentrodes(document.centrodes());
  m_centres->setCentres(document.centresAtPose());
}

std::optional<QPointF> LinkageScene::handlePosition(const DragHandle& handle) const {
  const QGraphicsItem* item = handleItem(handle);
  if (item == nullptr) return std::nullopt;
  return item->pos();
}

void LinkageScene::setHotHandle(const std::optional<DragHandle>& handle) { m_items->setHot(handle); }

const DrawingPlan& LinkageScene::plan() const { return m_items->plan(); }
const QGraphicsItem* LinkageScene::handleItem(const DragHandle& handle) const { return m_items->handle(handle); }
const LinkItem* LinkageScene::linkItem(k::LinkId link) const { return m_items->link(link); }
const SlottedLinkItem* LinkageScene::slottedLinkItem(k::LinkId link) const { return m_items->slottedLink(link); }
const QGraphicsPolygonItem* LinkageScene::bodyItem(k::LinkId link) const { return m_items->body(link); }
const QGraphicsPolygonItem* LinkageScene::couplerTriangleItem() const { return bodyItem(k::fourbar::kCoupler); }
const CouplerPathItem* LinkageScene::pathItem(k::PointId point) const { return m_items->path(point); }
const LabelItem* LinkageScene::pointLabel(k::PointId point) const { return m_items->label(point); }

std::optional<std::size_t> LinkageScene::sliderIndex(k::PointId joint) const {
  const auto& sliders = m_items->plan().sliders;
  for (std::size_t i = 0; i < sliders.size(); ++i)
    if (sliders[i].joint == joint) return i;
  return std::nullopt;
}

const SliderBlockItem* LinkageScene::sliderBlock(k::PointId joint) const {
  const auto i = sliderIndex(joint);
  return i ? m_items->block(*i) : nullptr;
}

const SlidewayItem* LinkageScene::slideway(k::PointId joint) const {
  const auto i = sliderIndex(joint);
  return i ? m_items->slideway(*i) : nullptr;
}

const ArrowItem* LinkageScene::velocityArrow(k::PointId point) const {
  return point.index < m_velocityArrows.size() ? m_velocityArrows[point.index] : nullptr;
}

const ArrowItem* LinkageScene::accelerationArrow(k::PointId point) const {
  return point.index < m_accelerationArrows.size() ? m_accelerationArrows[point.index] : nullptr;
}

void LinkageScene::showMessage(const QPointF& scenePos, const QString& text) {
  m_message->setText(text);
  m_message->setPos(scenePos);
  m_message->setVisible(true);
}

void LinkageScene::hideMessage() { m_message->setVisible(false); }

}  // namespace linkwright::ui
