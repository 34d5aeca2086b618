#include "ui/classroom/cognates_view.h"

#include "ui/colors.h"

#include <QPainter>
#include <QPainterPath>

#include <algorithm>

namespace linkwright::ui {

namespace {
constexpr double kMarginPx = 16.0;
constexpr double kLinkWidthPx = 3.0;
constexpr double kPinRadiusPx = 4.0;

QPointF toQt(const Eigen::Vector2d& p) { return {p.x(), p.y()}; }
}  // namespace

CognatesView::CognatesView(QWidget* parent) : QWidget(parent) {
  setMinimumSize(320, 240);
  setAutoFillBackground(true);
  QPalette p = palette();
  p.setColor(QPalette::Window, colors().canvasBackground);
  setPalette(p);
}

QColor CognatesView::colorOf(int fourBar) { return linkColor(static_cast<std::size_t>(std::clamp(fourBar, 0, 2))); }

void CognatesView::setCurve(const QPolygonF& curve, const QRectF& extent) {
  m_curve = curve;
  m_extent = extent;
  update();
}

void CognatesView::setJoints(const std::optional<std::array<kinematics::FourBarJoints, 3>>& joints) {
  m_joints = joints;
  update();
}

void CognatesView::paintEvent(QPaintEvent*) {
  if (m_extent.isEmpty()) return;
  QPainter painter(this);
  painter.setRenderHint(QPainter::Antialiasing);
  // World to widget: one scale both ways, y up, the extent centred.
  const QRectF area = QRectF(rect()).adjusted(kMarginPx, kMarginPx, -kMarginPx, -kMarginPx);
  const double scale = std::min(area.width() / m_extent.width(), area.height() / m_extent.height());
  QTransform world;
  world.translate(area.center().x(), area.center().y());
  world.scale(scale, -scale);
  world.translate(-m_extent.center().x(), -m_extent.center().y());

  painter.setPen(QPen(colors().frame, 1.5));
  painter.drawPolyline(world.map(m_curve));
  if (!m_joints) return;
  for (int i = 2; i >= 0; --i) {  // the original on top
    const kinematics::FourBarJoints& j = (*m_joints)[static_cast<std::size_t>(i)];
    const QColor color = colorOf(i);
    painter.setPen(QPen(color, kLinkWidthPx, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
    painter.setBrush(QColor(color.red(), color.green(), color.blue(), 40));
    const QPointF o2 = world.map(toQt(j.o2)), o4 = world.map(toQt(j.o4)), b = world.map(toQt(j.b)),
                  c = world.map(toQt(j.c)), p = world.map(toQt(j.p));
    painter.drawLine(o2, b);
    painter.drawPolygon(QPolygonF({b, c, p}));  // the coupler, a plate carrying P
    painter.drawLine(o4, c);
    painter.setBrush(colors().canvasBackground);
    for (const QPointF& pin : {b, c}) painter.drawEllipse(pin, kPinRadiusPx, kPinRadiusPx);
    painter.setBrush(color);
    for (const QPointF& pivot : {o2, o4})
      painter.drawRect(QRectF(pivot.x() - kPinRadiusPx, pivot.y() - kPinRadiusPx, 2 * kPinRadiusPx, 2 * kPinRadiusPx));
  }
  painter.setPen(QPen(colors().frame, 2.0));
  painter.setBrush(Qt::NoBrush);
  painter.drawEllipse(world.map(toQt((*m_joints)[0].p)), 2.0 * kPinRadiusPx, 2.0 * kPinRadiusPx);
}

}  // namespace linkwright::ui
