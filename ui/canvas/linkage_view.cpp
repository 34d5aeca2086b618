#include "ui/canvas/linkage_view.h"

#include "ui/canvas/canvas_style.h"
#include "ui/canvas/design_drag.h"
#include "ui/canvas/drag_handles.h"
#include "ui/canvas/grid_painter.h"
#include "ui/canvas/label_item.h"
#include "ui/canvas/linkage_scene.h"
#include "ui/geometry.h"

#include <QMouseEvent>
#include <QPaintEngine>
#include <QPainter>
#include <QScrollBar>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>
#include <limits>

namespace linkwright::ui {

namespace k = kinematics;

namespace {

// Zoom stays between the linkage being 20 px and 200 000 px across: the view's scene rect
// (1000 linkage sizes) then stays inside the scroll bars' int range.
constexpr double kMinLinkagePixels = 20.0;
constexpr double kMaxLinkagePixels = 2.0e5;
constexpr double kSceneRectSizes = 1000.0;
constexpr double kMaxSceneRectPixels = 1.0e9;
constexpr double kFitMarginPx = 40.0;  // room for pins, ground supports and labels
constexpr double kWheelStep = 1.2;     // zoom per wheel notch
constexpr double kPickDragPx = 4.0;    // a shorter pose drag is a click: direction 0

}  // namespace

LinkageView::LinkageView(MechanismDocument* document, QWidget* parent)
    : QGraphicsView(parent), m_document(document), m_scene(new LinkageScene(this)) {
  setScene(m_scene);
  setRenderHints(QPainter::Antialiasing | QPainter::TextAntialiasing | QPainter::SmoothPixmapTransform);
  // Cosmetic strokes reach past item bounds by a few pixels; repainting the whole viewport
  // leaves no trails and costs nothing for a dozen items.
  setViewportUpdateMode(FullViewportUpdate);
  // drawBackground covers every pixel with the cached grid: Qt need not fill it first.
  viewport()->setAttribute(Qt::WA_OpaquePaintEvent);
  setTransformationAnchor(NoAnchor);
  setResizeAnchor(AnchorViewCenter);
  setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  setFrameShape(QFrame::NoFrame);
  setMouseTracking(true);
  setTransform(QTransform::fromScale(1.0, -1.0));
  m_scene->updateDesign(*m_document);
  ensureSceneRect(true);
  connect(m_document, &MechanismDocument::changed, this, &LinkageView::onDocumentChanged);
}

QGraphicsScene* LinkageView::linkageScene() const { return m_scene; }

void LinkageView::setShowVelocityArrows(bool show) {
  m_scene->setShowVelocityArrows(show);
  m_scene->updatePose(*m_document);
}

void LinkageView::setShowAccelerationArrows(bool show) {
  m_scene->setShowAccelerationArrows(show);
  m_scene->updatePose(*m_document);
}

void LinkageView::setShowInstantCentres(bool show) {
  m_scene->setShowInstantCentres(show, *m_document);
  viewport()->update();
}

void LinkageView::setReadOnly(bool readOnly) {
  m_readOnly = readOnly;
  if (readOnly && m_hover) {
    m_hover.reset();
    m_scene->setHotHandle(std::nullopt);
  }
}

void LinkageView::setLinkColors(std::vector<QColor> colors) {
  m_scene->setLinkColors(std::move(colors));
  m_scene->updateDesign(*m_document);
  viewport()->update();
}

void LinkageView::setPresentationScale(double factor) {
  if (!(factor > 0.0) || !std::isfinite(factor)) return;
  m_presentationScale = std::clamp(factor, 0.5, 4.0);
  m_scene->setPresentationScale(m_presentationScale);
  if (m_autoFit) fitToView();  // the margin for pins and labels grew
  viewport()->update();
}

void LinkageView::refreshColors() {
  m_grid = {};  // painted in the old colours
  m_scene->refreshColors(*m_document);
  viewport()->update();
}

double LinkageView::pixelsPerUnit() const { return std::abs(transform().m11()); }

void LinkageView::refitIfFollowing() {
  if (m_autoFit && m_gesture == Gesture::None) fitToView();
}

double LinkageView::gridSpacing() const { return ui::gridSpacing(pixelsPerUnit()); }

void LinkageView::renderLinkage(QPainter* painter, const QRectF& target) const {
  const QRectF source = m_scene->sceneRect();
  if (source.isEmpty() || target.isEmpty()) return;
  const double s = std::min(target.width() / source.width(), target.height() / source.height());
  painter->save();
  painter->translate(target.center());
  painter->scale(s, -s);
  painter->translate(-source.center());
  m_scene->render(painter, source, source, Qt::IgnoreAspectRatio);
  painter->restore();
}

void LinkageView::setPickMode(PickMode mode) {
  m_pickMode = mode;
  if (m_gesture == Gesture::Pick) m_gesture = Gesture::None;
  if (mode == PickMode::None) viewport()->unsetCursor();
  else viewport()->setCursor(Qt::CrossCursor);
  viewport()->update();
}

void LinkageView::fitToView() {
  const QRectF bounds = fitBounds();
  const double size = fitSize();
  const double w = std::max(bounds.width(), 1e-3 * size);
  const double h = std::max(bounds.height(), 1e-3 * size);
  const QSizeF area = viewport()->size();
  // Presentation mode's larger pins want a larger margin, but not most of a narrow canvas.
  const double margin = std::min(kFitMarginPx * m_presentationScale, 0.15 * std::min(area.width(), area.height()));
  const double availableW = std::max(area.width() - 2.0 * margin, 0.3 * area.width());
  const double availableH = std::max(area.height() - 2.0 * margin, 0.3 * area.height());
  double k = std::min(availableW / w, availableH / h);
  if (!(k > 0.0) || !std::isfinite(k)) k = 1.0;
  const auto apply = [&](double scale) {
    scale = std::clamp(scale * size, kMinLinkagePixels, kMaxLinkagePixels) / size;
    setTransform(QTransform::fromScale(scale, -scale));
    ensureSceneRect(true);
    centerOn(bounds.center());
    emit pixelsPerUnitChanged(pixelsPerUnit());
  };
  k = std::min(k, labelsFitScale(bounds.center(), area));
  apply(k);
  // Labels the new scale moved (force magnitudes kept apart) may reach past the edge: once more.
  if (const double again = labelsFitScale(bounds.center(), area); again < k) apply(again);
  m_scrollResidue = {};
  m_autoFit = true;
}

// Labels keep their pixel size at any zoom, so a fit of the drawing alone can leave one cut at
// the viewport's edge ("crank can reach…", an arm's "outside s…"). The largest scale at which
// every visible label, anchored where it is, lies inside the viewport when `centre` is at its
// middle: each side of each label bounds the scale, where it can be met at all.
double LinkageView::labelsFitScale(const QPointF& centre, const QSizeF& area) const {
  constexpr double kEdgePx = 4.0;
  const double halfW = area.width() / 2.0 - kEdgePx, halfH = area.height() / 2.0 - kEdgePx;
  double most = std::numeric_limits<double>::infinity();
  // a·k + b ≤ half: for a > 0 a bound on k; otherwise shrinking cannot help.
  const auto bound = [&](double a, double b, double half) {
    if (a > 0.0 && half - b > 0.0) most = std::min(most, (half - b) / a);
  };
  for (const QGraphicsItem* item : m_scene->items()) {
    const auto* label = dynamic_cast<const LabelItem*>(item);
    if (label == nullptr || !label->isVisible() || label->text().isEmpty()) continue;
    // A label on an item that keeps its pixel size too (a force arrow's) is anchored where
    // that item is, its place on it in pixels.
    const QGraphicsItem* anchor = label;
    for (const QGraphicsItem* p = label->parentItem(); p != nullptr; p = p->parentItem())
      if (p->flags() & QGraphicsItem::ItemIgnoresTransformations) anchor = p;
    const QPointF d = anchor->scenePos() - centre;
    const double scale = anchor == label ? label->scale() : 1.0;
    const QRectF r = anchor == label ? label->boundingRect() : label->mapRectToItem(anchor, label->boundingRect());
    bound(d.x(), r.right() * scale, halfW);
    bound(-d.x(), -r.left() * scale, halfW);
    bound(-d.y(), r.bottom() * scale, halfH);  // the viewport's y runs down
    bound(d.y(), -r.top() * scale, halfH);
  }
  return most;
}

void LinkageView::setExtraRegion(const QRectF& region) {
  const bool usable = region.isValid() && std::isfinite(region.width()) && std::isfinite(region.height());
  m_extraRegion = usable ? region : QRectF();
  if (m_extraRegion.isNull()) return;
  if (!visibleRegion().contains(m_extraRegion)) fitToView();
  else ensureSceneRect(false);
}

QRectF LinkageView::visibleRegion() const { return mapToScene(viewport()->rect()).boundingRect(); }

QRectF LinkageView::fitBounds() const {
  const QRectF drawing = m_scene->contentBounds();
  return m_extraRegion.isNull() ? drawing : drawing.united(m_extraRegion);
}

double LinkageView::fitSize() const {
  const double linkage = m_scene->linkageSize();
  if (m_extraRegion.isNull()) return linkage;
  const QRectF bounds = fitBounds();
  return std::max({linkage, bounds.width(), bounds.height()});
}

void LinkageView::zoomBy(double factor) { zoomAbout(QRectF(viewport()->rect()).center(), factor); }

void LinkageView::onDocumentChanged(Changes what) {
  // The crank's feasible range is drawn from the analysis, which a drag's grid may bring later.
  if (what & (Changes(Change::Design) | Change::Request | Change::Analysis)) {
    m_scene->updateDesign(*m_document);
    // reset() announces Design and File together, and a replace() Linkage; ordinary edits
    // neither, so a drag or a typed length keeps the user's zoom.
    if (((what & Change::Design) && (what & Change::File)) || (what & Change::Linkage)) fitToView();
    else ensureSceneRect(false);
    viewport()->update();  // the grid's unit may have changed
  } else if (what & Change::Motion) {
    m_scene->updatePose(*m_document);
  }
}

void LinkageView::ensureSceneRect(bool force) {
  // A scene rect far larger than the linkage lets the user pan anywhere; it is reset only
  // when the drawing nears its edge, as re-setting it re-centres the view.
  const QRectF bounds = fitBounds();
  const double size = fitSize();
  const double reach = 0.1 * kSceneRectSizes * size;
  const QRectF current = sceneRect();
  if (!force && current.contains(bounds.adjusted(-reach, -reach, reach, reach)) &&
      current.width() <= 10.0 * kSceneRectSizes * size)
    return;
  const double side = std::min(kSceneRectSizes * size, kMaxSceneRectPixels / std::max(pixelsPerUnit(), 1e-300));
  const QPointF centre = sceneAt(QRectF(viewport()->rect()).center());
  setSceneRect(QRectF(bounds.center() - QPointF(side, side) / 2.0, QSizeF(side, side)));
  if (!force) centerOn(centre);
}

QPointF LinkageView::sceneAt(const QPointF& viewportPos) const {
  return viewportTransform().inverted().map(viewportPos);
}

std::optional<DragHandle> LinkageView::handleAt(const QPointF& viewportPos) const {
  if (m_readOnly) return std::nullopt;
  std::optional<DragHandle> best;
  double bestDistance = canvas::kPickRadiusPx * m_presentationScale;
  for (const DragHandle& handle : m_scene->handles()) {
    const std::optional<QPointF> at = m_scene->handlePosition(handle);
    if (!at) continue;
    const double distance = QLineF(viewportTransform().map(*at), viewportPos).length();
    if (distance < bestDistance || (!best && distance <= bestDistance)) {
      best = handle;
      bestDistance = distance;
    }
  }
  return best;
}

void LinkageView::zoomAbout(const QPointF& viewportPos, double factor) {
  if (!(factor > 0.0) || !std::isfinite(factor)) return;
  const double size = fitSize();
  const double now = pixelsPerUnit();
  const double wanted = std::clamp(now * factor * size, kMinLinkagePixels, kMaxLinkagePixels) / size;
  m_autoFit = false;
  if (wanted == now) return;
  const QPointF anchor = sceneAt(viewportPos);
  scale(wanted / now, wanted / now);
  ensureSceneRect(false);
  scrollByPixels(viewportTransform().map(anchor) - viewportPos);
  emit pixelsPerUnitChanged(pixelsPerUnit());
}

void LinkageView::scrollByPixels(const QPointF& delta) {
  // Scroll bars take whole pixels; the remainder is kept so repeated shifts do not drift.
  m_scrollResidue += delta;
  const int dx = static_cast<int>(std::lround(m_scrollResidue.x()));
  const int dy = static_cast<int>(std::lround(m_scrollResidue.y()));
  horizontalScrollBar()->setValue(horizontalScrollBar()->value() + dx);
  verticalScrollBar()->setValue(verticalScrollBar()->value() + dy);
  m_scrollResidue -= QPointF(dx, dy);
}

void LinkageView::drawBackground(QPainter* painter, const QRectF& exposed) {
  const QString unit = QString::fromStdString(m_document->lengthUnit());
  const QPaintEngine* engine = painter->paintEngine();
  if (engine != nullptr && (engine->type() == QPaintEngine::Pdf || engine->type() == QPaintEngine::SVG)) {
    // A PDF or SVG export gets the grid as lines and text, not the screen's cached pixmap.
    painter->fillRect(exposed, colors().canvasBackground);
    paintGrid(painter, exposed, exposed, unit, m_presentationScale);
    return;
  }
  const qreal ratio = viewport()->devicePixelRatioF();
  const QSize pixels = viewport()->size() * ratio;
  if (m_grid.pixmap.size() != pixels || m_grid.pixmap.devicePixelRatio() != ratio ||
      m_grid.transform != viewportTransform() || m_grid.unit != unit || m_grid.textScale != m_presentationScale) {
    m_grid = {QPixmap(pixels), viewportTransform(), unit, m_presentationScale};
    m_grid.pixmap.setDevicePixelRatio(ratio);
    QPainter grid(&m_grid.pixmap);
    grid.setRenderHints(renderHints());
    grid.setTransform(viewportTransform());
    const QRectF visible = viewportTransform().inverted().mapRect(QRectF(viewport()->rect()));
    grid.fillRect(visible, colors().canvasBackground);
    paintGrid(&grid, visible, visible, unit, m_presentationScale);
  }
  painter->save();
  // The cache is in viewport pixels: on screen the painter's transform is the viewport's, so
  // this is the identity; a render() into a scaled or moved target (an animation's frame) puts
  // it where the viewport lands there.
  painter->setTransform(viewportTransform().inverted() * painter->transform());
  painter->drawPixmap(0, 0, m_grid.pixmap);
  painter->restore();
}

void LinkageView::drawForeground(QPainter* painter, const QRectF& rect) {
  QGraphicsView::drawForeground(painter, rect);
  if (m_gesture != Gesture::Pick || m_pickMode != PickMode::Pose) return;
  // The direction being dragged, as a rubber band from the pressed point.
  QPen pen(colors().label, 1.5 * m_presentationScale, Qt::DashLine);
  pen.setCosmetic(true);
  painter->setPen(pen);
  painter->drawLine(sceneAt(m_pickStart), sceneAt(m_lastPointer));
}

void LinkageView::finishPick(const QPointF& viewportPos) {
  const QPointF at = sceneAt(m_pickStart);
  viewport()->update();
  if (m_pickMode == PickMode::Point) {
    emit pointPicked(at);
    return;
  }
  const QPointF drag = sceneAt(viewportPos) - at;
  const bool dragged = QLineF(m_pickStart, viewportPos).length() >= kPickDragPx;
  emit posePicked(at, dragged ? std::atan2(drag.y(), drag.x()) : 0.0);
}

void LinkageView::wheelEvent(QWheelEvent* event) {
  const int notches = event->angleDelta().y();
  if (notches == 0) {
    event->ignore();
    return;
  }
  zoomAbout(event->position(), std::pow(kWheelStep, notches / 120.0));
  event->accept();
}

void LinkageView::mousePressEvent(QMouseEvent* event) {
  if (m_gesture != Gesture::None) {
    event->accept();
    return;
  }
  const QPointF pos = event->position();
  if (event->button() == Qt::LeftButton && m_pickMode != PickMode::None) {
    m_gesture = Gesture::Pick;
    m_gestureButton = Qt::LeftButton;
    m_pickStart = pos;
    m_lastPointer = pos;
    event->accept();
    return;
  }
  if (event->button() == Qt::LeftButton) {
    if (const auto handle = handleAt(pos)) {
      startDrag(*handle, pos);
      m_gestureButton = Qt::LeftButton;
      event->accept();
      return;
    }
  }
  if (event->button() == Qt::LeftButton || event->button() == Qt::MiddleButton) {
    m_gesture = Gesture::Pan;
    m_gestureButton = event->button();
    m_lastPointer = pos;
    viewport()->setCursor(Qt::ClosedHandCursor);
    event->accept();
    return;
  }
  QGraphicsView::mousePressEvent(event);
}

void LinkageView::mouseMoveEvent(QMouseEvent* event) {
  const QPointF pos = event->position();
  switch (m_gesture) {
  case Gesture::Drag: dragTo(pos); break;
  case Gesture::Pan:
    scrollByPixels(m_lastPointer - pos);
    m_lastPointer = pos;
    m_autoFit = false;
    break;
  case Gesture::Pick:
    m_lastPointer = pos;
    viewport()->update();
    break;
  case Gesture::None:
    if (m_pickMode == PickMode::None) updateHover(pos);
    break;
  }
  event->accept();
}

void LinkageView::mouseReleaseEvent(QMouseEvent* event) {
  if (m_gesture == Gesture::None || event->button() != m_gestureButton) {
    QGraphicsView::mouseReleaseEvent(event);
    return;
  }
  const QPointF pos = event->position();
  if (m_gesture == Gesture::Pick) {
    m_gesture = Gesture::None;
    m_gestureButton = Qt::NoButton;
    finishPick(pos);
    event->accept();
    return;
  }
  if (m_gesture == Gesture::Drag && pos != m_lastPointer) dragTo(pos);
  m_gesture = Gesture::None;
  m_gestureButton = Qt::NoButton;
  m_scene->hideMessage();
  m_lastRefusal.clear();
  m_hover.reset();
  updateHover(pos);
  event->accept();
}

void LinkageView::leaveEvent(QEvent* event) {
  if (m_gesture == Gesture::None && m_hover) {
    m_hover.reset();
    m_scene->setHotHandle(std::nullopt);
    viewport()->unsetCursor();
    emit statusMessage(QString());
  }
  QGraphicsView::leaveEvent(event);
}

void LinkageView::showEvent(QShowEvent* event) {
  QGraphicsView::showEvent(event);
  if (m_autoFit) fitToView();
}

void LinkageView::resizeEvent(QResizeEvent* event) {
  QGraphicsView::resizeEvent(event);
  if (m_autoFit) fitToView();
}

void LinkageView::updateHover(const QPointF& viewportPos) {
  const std::optional<DragHandle> handle = handleAt(viewportPos);
  m_scene->setHotHandle(handle);
  if (handle) viewport()->setCursor(Qt::OpenHandCursor);
  else viewport()->unsetCursor();
  if (handle != m_hover)
    emit statusMessage(handle ? dragHint(m_document->fourBar(), m_document->mechanism(), *handle) : QString());
  m_hover = handle;
}

void LinkageView::startDrag(const DragHandle& handle, const QPointF& viewportPos) {
  m_gesture = Gesture::Drag;
  m_dragHandle = handle;
  m_grabOffset = *m_scene->handlePosition(handle) - sceneAt(viewportPos);
  m_lastPointer = viewportPos;
  m_lastRefusal.clear();
  ++m_dragCount;
  m_scene->setHotHandle(handle);
  viewport()->setCursor(Qt::ClosedHandCursor);
  emit statusMessage(dragHint(m_document->fourBar(), m_document->mechanism(), handle));
}

void LinkageView::dragTo(const QPointF& viewportPos) {
  m_lastPointer = viewportPos;
  const Eigen::Vector2d target = toEigen(sceneAt(viewportPos) + m_grabOffset);
  const k::Result<DesignDrag> outcome = dragDesign(*m_document, m_dragHandle, target);
  if (!outcome) {
    refuse(QString::fromStdString(outcome.error().message), viewportPos);
    return;
  }
  const MergeKey mergeKey{ContinuousEdit::DragPoint, m_dragHandle.point.index, m_dragCount};
  const QString name = dragHandleName(m_document->mechanism(), m_dragHandle);
  if (const auto why = m_document->edit(outcome->design, tr("Move %1").arg(name), mergeKey, outcome->crankAngle)) {
    refuse(*why, viewportPos);
    return;
  }
  m_scene->hideMessage();
  m_lastRefusal.clear();
}

void LinkageView::refuse(const QString& reason, const QPointF& viewportPos) {
  // Next to the pointer, but kept inside the viewport when the pointer has left it.
  m_scene->showMessage(sceneAt(viewportPos), reason);
  const QRectF item = m_scene->messageItem()->boundingRect();
  const QRectF box(item.topLeft() * m_presentationScale, item.size() * m_presentationScale);
  const QRectF area = QRectF(viewport()->rect()).adjusted(4.0, 4.0, -4.0, -4.0);
  const auto keepIn = [](double at, double low, double high) { return std::clamp(at, low, std::max(low, high)); };
  const QPointF inside(keepIn(viewportPos.x(), area.left() - box.left(), area.right() - box.right()),
                       keepIn(viewportPos.y(), area.top() - box.top(), area.bottom() - box.bottom()));
  if (inside != viewportPos) m_scene->showMessage(sceneAt(inside), reason);
  if (reason == m_lastRefusal) return;
  m_lastRefusal = reason;
  emit editRefused(reason);
}

}  // namespace linkwright::ui
