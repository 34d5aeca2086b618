#include "ui/canvas/instant_centres_item.h"

#include "ui/colors.h"

#include "ui/canvas/canvas_style.h"
#include "ui/canvas/label_item.h"
#include "ui/geometry.h"

#include <QFont>
#include <QFontMetricsF>
#include <QGraphicsScene>
#include <QPainter>
#include <QPainterPath>
#include <QStringList>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

namespace linkwright::ui {

namespace k = kinematics;

namespace {

constexpr double kCentreDotPx = 3.5;
constexpr double kFarArrowPx = 48.0;

// "₁₂", or "₁,₁₀" once a body number has two digits.
QString subscript(std::size_t i, std::size_t j) {
  const auto digits = [](std::size_t n) {
    QString out;
    for (const QChar c : QString::number(n)) out += QChar(0x2080 + c.digitValue());
    return out;
  };
  return digits(i) + (i > 9 || j > 9 ? QStringLiteral(",") : QString()) + digits(j);
}

QString label(std::size_t i, std::size_t j) { return QStringLiteral("I") + subscript(i, j); }

// A finite centre near enough to draw as a point (far ones run off the drawing).
bool near(const k::InstantCentre& centre, const k::InstantCentres& all) {
  return centre.kind == k::CentreKind::Finite && (centre.position - all.anchor).norm() <= k::kCentrodeReach * all.scale;
}

// Where an arrow to Iij (at infinity, or too far to draw) leaves from: the block's pin for a
// slide, else a near centre on a Kennedy line that located it.
std::optional<Eigen::Vector2d> arrowFoot(const k::InstantCentres& c, std::size_t i, std::size_t j) {
  const k::CentreOrigin& o = c.origin(i, j);
  if (o.rule == k::CentreRule::Slide) return o.pin;
  if (o.rule != k::CentreRule::Kennedy) return std::nullopt;
  for (const std::size_t via : o.via)
    for (const std::size_t end : {i, j})
      if (near(c.centre(end, via), c)) return c.centre(end, via).position;
  return std::nullopt;
}

// A label on a white box beside a point (pixels), `gap` away: upper left, where the point
// names (placed away from the links) and the ground hatching (below) usually are not; else the
// nearest place around the point, at the four corners and sides and then farther out, whose
// box stays off the boxes already `taken` (the point names, the other centres' labels); where
// none is free, the one overlapping least. A label near the view's edge is moved in, so a
// centre at the edge still reads. The box drawn joins `taken`.
void drawLabel(QPainter* painter, const QPointF& at, double gap, const QString& text, std::vector<QRectF>& taken) {
  const QFontMetricsF metrics(painter->font());
  const QSizeF size(metrics.horizontalAdvance(text) + 4.0, metrics.height());
  const QRectF view = painter->viewport();
  const auto boxAt = [&](double dx, double dy, double distance) {
    const QPointF corner(dx < 0   ? -distance - size.width()
                         : dx > 0 ? distance
                                  : -0.5 * size.width(),
                         dy < 0   ? -distance - size.height()
                         : dy > 0 ? distance
                                  : -0.5 * size.height());
    QRectF box(at + corner, size);
    box.translate(std::max(0.0, view.left() - box.left()), std::max(0.0, view.top() - box.top()));
    box.translate(std::min(0.0, view.right() - box.right()), std::min(0.0, view.bottom() - box.bottom()));
    return box;
  };
  const auto overlap = [&](const QRectF& box) {
    double area = 0.0;
    for (const QRectF& t : taken) {
      const QRectF common = t.intersected(box);
      area += common.isValid() ? common.width() * common.height() : 0.0;
    }
    return area;
  };
  static constexpr std::pair<int, int> kAround[] = {{-1, -1}, {-1, 1}, {1, 1},  {1, -1},
                                                    {0, -1},  {0, 1},  {-1, 0}, {1, 0}};
  QRectF best = boxAt(-1, -1, gap);
  double bestOverlap = overlap(best);
  for (int ring = 0; ring < 4 && bestOverlap > 0.0; ++ring)
    for (const auto& [dx, dy] : kAround) {
      const QRectF box = boxAt(dx, dy, gap + ring * size.height());
      if (const double o = overlap(box); o < bestOverlap) best = box, bestOverlap = o;
      if (bestOverlap == 0.0) break;
    }
  painter->fillRect(best, colors().labelBox);
  painter->drawText(best, Qt::AlignCenter, text);
  taken.push_back(best);
}

// The boxes of the scene's point names and other canvas labels, in the pixels `sceneToPixels`
// maps to.
std::vector<QRectF> labelBoxes(const QGraphicsScene* scene, const QTransform& sceneToPixels) {
  std::vector<QRectF> boxes;
  if (scene == nullptr) return boxes;
  for (const QGraphicsItem* item : scene->items()) {
    const auto* label = dynamic_cast<const LabelItem*>(item);
    if (label != nullptr && label->isVisible() && !label->text().isEmpty())
      boxes.push_back(label->deviceTransform(sceneToPixels).mapRect(label->boundingRect()));
  }
  return boxes;
}

void drawArrow(QPainter* painter, const QPointF& from, const QPointF& unit, double length, double head) {
  const QPointF tip = from + unit * length;
  const QPointF side(-unit.y(), unit.x());
  painter->drawLine(from, tip);
  painter->drawLine(tip, tip - unit * head + side * 0.5 * head);
  painter->drawLine(tip, tip - unit * head - side * 0.5 * head);
}

}  // namespace

InstantCentresItem::InstantCentresItem(QGraphicsItem* parent) : QGraphicsItem(parent) { setZValue(canvas::z::kArrows); }

void InstantCentresItem::setCentrodes(const k::Centrodes& centrodes) {
  m_centrodes = centrodes;
  updateBounds();
}

void InstantCentresItem::setCentres(const CentresAtPose& centres) {
  m_centres = centres.centres;
  m_frame = centres.frame;
  m_reason = centres.reason;
  updateBounds();
}

QString InstantCentresItem::unresolvedNote() const {
  if (!m_centres) return {};
  QStringList names;
  for (std::size_t i = 1; i <= m_centres->bodyCount(); ++i)
    for (std::size_t j = i + 1; j <= m_centres->bodyCount(); ++j)
      if (m_centres->centre(i, j).kind == k::CentreKind::Unresolved) names << label(i, j);
  if (names.isEmpty()) return {};
  return QObject::tr("%1: Kennedy's theorem does not reach %2")
      .arg(names.join(QStringLiteral(", ")), names.size() == 1 ? QObject::tr("it") : QObject::tr("them"));
}

void InstantCentresItem::setPresentationScale(double factor) {
  m_scale = factor;
  update();
}

void InstantCentresItem::updateBounds() {
  // The points' extent, kept as corners: QRectF::united ignores a rectangle of no size, so a
  // box grown from points that way stayed at the last point alone, and the item, culled by
  // that box, went undrawn wherever its last point lay off screen (the shaper's centres).
  std::optional<QRectF> extent;
  const auto include = [&](const Eigen::Vector2d& p) {
    const QPointF q = toQt(p);
    if (!extent) extent = QRectF(q, q);
    extent->setLeft(std::min(extent->left(), q.x()));
    extent->setRight(std::max(extent->right(), q.x()));
    extent->setTop(std::min(extent->top(), q.y()));
    extent->setBottom(std::max(extent->bottom(), q.y()));
  };
  if (m_centres)
    for (const k::InstantCentre& c : m_centres->centres)
      if (near(c, *m_centres)) include(c.position);
  for (const auto& run : m_centrodes.fixed)
    for (const Eigen::Vector2d& p : run) include(p);
  if (m_frame)
    for (const auto& run : m_centrodes.moving)
      for (const Eigen::Vector2d& p : run) include(m_frame->toWorld(p));
  const QRectF box = extent.value_or(QRectF());
  // Marks, arrows and labels are drawn in pixels around these points.
  const double margin = 0.25 * std::max({box.width(), box.height(), m_centres ? m_centres->scale : 0.0});
  prepareGeometryChange();
  m_bounds = box.adjusted(-margin, -margin, margin, margin);
  update();
}

QRectF InstantCentresItem::boundingRect() const { return m_bounds; }

void InstantCentresItem::paint(QPainter* painter, const QStyleOptionGraphicsItem*, QWidget*) {
  const QTransform toPixels = painter->worldTransform();
  std::vector<QRectF> taken = labelBoxes(scene(), sceneTransform().inverted() * toPixels);
  const std::size_t names = taken.size();
  const auto px = [&](const Eigen::Vector2d& p) { return toPixels.map(toQt(p)); };
  painter->save();
  painter->resetTransform();
  painter->setRenderHint(QPainter::Antialiasing);
  painter->setBrush(Qt::NoBrush);

  // The centrodes first, under everything: fixed solid, moving dashed on the coupler.
  painter->setPen(QPen(colors().centre, 1.5 * m_scale));
  for (const auto& run : m_centrodes.fixed) {
    QPolygonF line;
    for (const Eigen::Vector2d& p : run) line << px(p);
    painter->drawPolyline(line);
  }
  if (m_frame) {
    painter->setPen(QPen(colors().movingCentrode, 1.5 * m_scale, Qt::DashLine));
    for (const auto& run : m_centrodes.moving) {
      QPolygonF line;
      for (const Eigen::Vector2d& p : run) line << px(m_frame->toWorld(p));
      painter->drawPolyline(line);
    }
  }
  if (!m_centres) {
    painter->restore();
    return;
  }
  const k::InstantCentres& c = *m_centres;

  // Kennedy's lines: the two that located each secondary centre, drawn across the finite
  // centres each holds.
  painter->setPen(QPen(colors().kennedyLine, 1.0 * m_scale, Qt::DashLine));
  const std::size_t n = c.bodyCount();
  for (std::size_t i = 1; i <= n; ++i)
    for (std::size_t j = i + 1; j <= n; ++j) {
      const k::CentreOrigin& o = c.origin(i, j);
      if (o.rule != k::CentreRule::Kennedy || c.centre(i, j).kind == k::CentreKind::Indeterminate) continue;
      for (const std::size_t via : o.via) {
        std::vector<QPointF> points;
        for (const k::InstantCentre* centre : {&c.centre(i, via), &c.centre(j, via), &c.centre(i, j)})
          if (near(*centre, c)) points.push_back(px(centre->position));
        QLineF span;
        for (std::size_t a = 0; a < points.size(); ++a)
          for (std::size_t b = a + 1; b < points.size(); ++b)
            if (QLineF(points[a], points[b]).length() > span.length()) span = QLineF(points[a], points[b]);
        if (span.length() > 0.0) painter->drawLine(span);
      }
    }

  // The centres: a dot and a label, or an arrow towards one at infinity (or too far to draw).
  QFont font = painter->font();
  font.setPointSizeF(canvas::kLabelPointSize * m_scale);
  font.setBold(true);
  painter->setFont(font);
  const double dot = kCentreDotPx * m_scale;
  // Centres at one point (a pin that joins three links) share one label: "I₁₃, I₁₄".
  std::vector<std::pair<QPointF, QString>> named;
  for (std::size_t i = 1; i <= n; ++i)
    for (std::size_t j = i + 1; j <= n; ++j) {
      const k::InstantCentre& centre = c.centre(i, j);
      painter->setPen(QPen(colors().centre, 1.5 * m_scale));
      if (near(centre, c)) {
        const QPointF at = px(centre.position);
        painter->setBrush(colors().centre);
        painter->drawEllipse(at, dot, dot);
        painter->setBrush(Qt::NoBrush);
        const auto same = std::find_if(named.begin(), named.end(),
                                       [&](const auto& other) { return QLineF(other.first, at).length() < 1.5; });
        if (same != named.end()) same->second += QStringLiteral(", ") + label(i, j);
        else named.emplace_back(at, label(i, j));
        continue;
      }
      const auto foot = arrowFoot(c, i, j);
      if (!foot || (centre.kind != k::CentreKind::Finite && centre.kind != k::CentreKind::AtInfinity)) continue;
      const Eigen::Vector2d direction =
          centre.kind == k::CentreKind::AtInfinity ? centre.direction : Eigen::Vector2d(centre.position - *foot);
      const QPointF from = px(*foot);
      QPointF unit = px(*foot + direction) - from;
      const double length = std::hypot(unit.x(), unit.y());
      if (!(length > 0.0) || !std::isfinite(length)) continue;
      unit /= length;
      drawArrow(painter, from, unit, kFarArrowPx * m_scale, 8.0 * m_scale);
      drawLabel(painter, from + unit * (kFarArrowPx + 4.0) * m_scale, 0.0, label(i, j) + QStringLiteral(" ∞"), taken);
    }
  for (const auto& [at, text] : named) drawLabel(painter, at, dot + 2.0, text, taken);
  // What Kennedy's theorem leaves open, under the frame's pin the drawing measures from.
  if (const QString note = unresolvedNote(); !note.isEmpty()) {
    const QFontMetricsF metrics(painter->font());
    drawLabel(painter, px(c.anchor) + QPointF(metrics.horizontalAdvance(note) / 2.0, 3.0 * metrics.height()), 0.0, note,
              taken);
  }
  painter->restore();
  m_drawnLabels.assign(taken.begin() + static_cast<std::ptrdiff_t>(names), taken.end());
}

}  // namespace linkwright::ui
