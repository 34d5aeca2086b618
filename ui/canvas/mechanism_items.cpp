#include "ui/canvas/mechanism_items.h"

#include "ui/canvas/actuator_item.h"
#include "ui/canvas/canvas_style.h"
#include "ui/canvas/coupler_path_item.h"
#include "ui/canvas/driven_path_item.h"
#include "ui/canvas/ground_pivot_item.h"
#include "ui/canvas/joint_handle_item.h"
#include "ui/canvas/label_item.h"
#include "ui/canvas/link_item.h"
#include "ui/canvas/slider_block_item.h"
#include "ui/canvas/slideway_item.h"
#include "ui/canvas/slotted_link_item.h"
#include "ui/canvas/workspace_item.h"
#include "ui/colors.h"
#include "ui/geometry.h"
#include "ui/number_text.h"

#include "kinematics/model/path_shape.h"
#include "kinematics/solve/guide_line.h"
#include "kinematics/solve/law_inverse.h"

#include <QGraphicsLineItem>
#include <QGraphicsPolygonItem>
#include <QGraphicsScene>
#include <QPainterPath>
#include <QPen>

#include <algorithm>
#include <cmath>

namespace linkwright::ui {

namespace k = kinematics;

namespace {

constexpr double kLabelDistancePx = 9.0;
constexpr double kSliderLabelDistancePx = 24.0;  // clear of the block and the slideway's hatching
constexpr double kBlockLengthPx = 44.0;
constexpr double kBlockHeightPx = 26.0;
constexpr double kSlotBlockLengthPx = 26.0;
constexpr double kSlotBlockHeightPx = 10.0;
// A plate's sides are bars too, a little narrower than the link's own.
constexpr double kPlateSideFraction = 0.7;

QPen cosmeticPen(const QColor& color, double width, Qt::PenStyle style = Qt::SolidLine) {
  QPen pen(color, width, style, Qt::RoundCap, Qt::RoundJoin);
  pen.setCosmetic(true);
  return pen;
}

QPointF positionOf(const k::Pose& pose, k::PointId id) {
  return id.index < pose.position.size() ? toQt(pose.position[id.index]) : QPointF();
}

double length(const QPointF& v) { return std::hypot(v.x(), v.y()); }

// Along-line coordinates of points on a line (point G, unit u): where each projects.
double along(const k::GuideLine& line, const Eigen::Vector2d& p) { return line.direction.dot(p - line.point); }

QPointF onLine(const k::GuideLine& line, double t) { return toQt(line.point + t * line.direction); }

}  // namespace

template <typename Item>
Item* MechanismItems::add(Item* item) {
  m_scene->addItem(item);
  m_owned.push_back(item);
  return item;
}

QColor MechanismItems::colorOf(std::size_t link) const {
  return link < m_linkColors.size() ? m_linkColors[link] : linkColor(link);
}

MechanismItems::MechanismItems(QGraphicsScene* scene, const k::Mechanism& m, DrawingPlan plan,
                               std::vector<QColor> linkColors)
    : m_scene(scene), m_linkColors(std::move(linkColors)), m_plan(std::move(plan)) {
  const std::size_t points = m.points.size();
  m_links.assign(m.links.size(), nullptr);
  for (std::size_t l = 0; l < m.links.size(); ++l)
    if (m_plan.barLinks[l]) m_links[l] = add(new LinkItem(colorOf(l)));
  for (const BodyShape& body : m_plan.bodies) {
    auto* plate = add(new QGraphicsPolygonItem);
    QColor fill = colorOf(body.link.index);
    fill.setAlpha(colors().bodyFillAlpha);
    plate->setBrush(fill);
    plate->setPen(cosmeticPen(colorOf(body.link.index), kPlateSideFraction * canvas::kLinkWidthPx));
    plate->setZValue(canvas::z::kCouplerTriangle);
    m_bodies.push_back(plate);
  }
  for (const SlotShape& slot : m_plan.slottedLinks) {
    m_slots.push_back(add(new SlottedLinkItem(colorOf(slot.link.index))));
    // The block is a body of its own (the dyad's middle link): neutral, so it reads on the bar.
    m_slotBlocks.push_back(add(new SliderBlockItem(colors().frame, kSlotBlockLengthPx, kSlotBlockHeightPx)));
  }
  for (const SliderShape& slider : m_plan.sliders) {
    const k::Guide& guide = sliderGuide(m, slider);
    const QColor guideColor = guide.link ? colorOf(guide.link->index) : colors().frame;
    m_slideways.push_back(add(new SlidewayItem(slider.onGround, kBlockHeightPx + 2.0, guideColor)));
    m_blocks.push_back(add(new SliderBlockItem(sliderColor(slider.ordinal), kBlockLengthPx, kBlockHeightPx)));
  }
  m_groundSlideways.assign(m_plan.sliders.size(), QLineF());
  m_slotReach.assign(m_plan.slottedLinks.size(), 0.0);
  for (std::size_t i = 0; i < m_plan.frameLines.size(); ++i) {
    auto* line = add(new QGraphicsLineItem);
    line->setPen(cosmeticPen(colors().frame, canvas::kFrameWidthPx, Qt::DashLine));
    line->setZValue(canvas::z::kFrame);
    m_frameLines.push_back(line);
  }
  for (std::size_t i = 0; i < m_plan.constraintBars.size(); ++i)
    m_constraintBars.push_back(add(new LinkItem(colors().frame)));
  for (std::size_t i = 0; i < m_plan.drivenPaths.size(); ++i) {
    m_drivenPaths.push_back(add(new DrivenPathItem));
    m_vertexHandles.emplace_back();
    for (std::size_t v = 0; v < m_plan.pathVertices[i]; ++v)
      m_vertexHandles.back().push_back(add(new JointHandleItem(JointHandleItem::Style::Vertex)));
  }
  for (std::size_t i = 0; i < m_plan.actuators.size(); ++i) m_actuators.push_back(add(new ActuatorItem));
  for (std::size_t i = 0; i < m_plan.workspaces.size(); ++i) m_workspaces.push_back(add(new WorkspaceItem));
  m_grounds.assign(points, nullptr);
  m_joints.assign(points, nullptr);
  m_labels.assign(points, nullptr);
  m_paths.assign(points, nullptr);
  for (std::size_t i = 0; i < points; ++i) {
    if (m_plan.ground[i]) m_grounds[i] = add(new GroundPivotItem);
    else if (m_plan.attached[i])
      m_joints[i] = add(new JointHandleItem(JointHandleItem::Style::Dot, colors().couplerPoint));
    else m_joints[i] = add(new JointHandleItem(JointHandleItem::Style::Pin));
    m_labels[i] = add(new LabelItem);
    m_labels[i]->setText(pointDisplayName(m.points[i].name));
    if (m_plan.traced[i]) m_paths[i] = add(new CouplerPathItem);
  }
}

MechanismItems::~MechanismItems() {
  // Children (slideway and slot strokes) go with their parents.
  for (QGraphicsItem* item : m_owned) {
    m_scene->removeItem(item);
    delete item;
  }
}

QGraphicsItem* MechanismItems::handle(const DragHandle& h) const {
  const k::PointId p = h.point;
  if (h.pathVertex) {
    for (std::size_t d = 0; d < m_plan.drivenPaths.size(); ++d)
      if (m_plan.drivenPaths[d] == p && *h.pathVertex < m_vertexHandles[d].size())
        return m_vertexHandles[d][*h.pathVertex];
    return nullptr;
  }
  if (p.index >= m_grounds.size() || !m_plan.draggable[p.index]) return nullptr;
  return m_grounds[p.index] != nullptr ? static_cast<QGraphicsItem*>(m_grounds[p.index]) : m_joints[p.index];
}

LinkItem* MechanismItems::link(k::LinkId l) const { return l.index < m_links.size() ? m_links[l.index] : nullptr; }

SlottedLinkItem* MechanismItems::slottedLink(k::LinkId l) const {
  for (std::size_t i = 0; i < m_plan.slottedLinks.size(); ++i)
    if (m_plan.slottedLinks[i].link == l) return m_slots[i];
  return nullptr;
}

QGraphicsPolygonItem* MechanismItems::body(k::LinkId l) const {
  for (std::size_t i = 0; i < m_plan.bodies.size(); ++i)
    if (m_plan.bodies[i].link == l) return m_bodies[i];
  return nullptr;
}

CouplerPathItem* MechanismItems::path(k::PointId p) const {
  return p.index < m_paths.size() ? m_paths[p.index] : nullptr;
}

LabelItem* MechanismItems::label(k::PointId p) const { return p.index < m_labels.size() ? m_labels[p.index] : nullptr; }

void MechanismItems::setDesign(const k::Mechanism& m, const k::SweepResult& sweep, const k::Pose& pose,
                               double linkageSize, const std::optional<k::TimeBase>& time) {
  m_margin = 0.06 * linkageSize;
  // The same plan may come with other point names (an inversion renames its joints).
  for (std::size_t i = 0; i < m_labels.size() && i < m.points.size(); ++i)
    if (m_labels[i] != nullptr) m_labels[i]->setText(pointDisplayName(m.points[i].name));
  setDrivenDesign(m, sweep, pose, time);
  for (std::size_t i = 0; i < m_paths.size(); ++i)
    if (m_paths[i] != nullptr) m_paths[i]->setFromSweep(sweep, k::PointId{i});
  // The block's travel over the cycle, measured along its guide or its slot.
  const auto overCycle = [&](k::PointId p, auto&& measure, double& low, double& high) {
    bool any = false;
    if (p.index < sweep.position.size())
      for (std::size_t j = 0; j < sweep.size() && j < sweep.position[p.index].size(); ++j) {
        if (!sweep.assembled(j)) continue;
        const double t = measure(j);
        low = any ? std::min(low, t) : t;
        high = any ? std::max(high, t) : t;
        any = true;
      }
    return any;
  };
  for (std::size_t s = 0; s < m_plan.sliders.size(); ++s) {
    const SliderShape& slider = m_plan.sliders[s];
    if (!slider.onGround) continue;
    const k::GuideLine line = k::guideLineAt(m, sliderGuide(m, slider), pose);
    double low = along(line, pose.position[slider.joint.index]);
    double high = low;
    overCycle(
        slider.joint, [&](std::size_t j) { return along(line, sweep.position[slider.joint.index][j]); }, low, high);
    m_groundSlideways[s] = QLineF(onLine(line, low - m_margin), onLine(line, high + m_margin));
  }
  for (std::size_t s = 0; s < m_plan.slottedLinks.size(); ++s) {
    const SlotShape& slot = m_plan.slottedLinks[s];
    double low = (pose.position[slot.through.index] - pose.position[slot.pivot.index]).norm();
    double high = low;
    overCycle(
        slot.through,
        [&](std::size_t j) {
          return (sweep.position[slot.through.index][j] - sweep.position[slot.pivot.index][j]).norm();
        },
        low, high);
    m_slotReach[s] = high;
  }
  // Corner points, not QRectF::united: a rect of zero size is null and would be skipped.
  bool any = false;
  QPointF low, high;
  const auto include = [&](const QPointF& p) {
    low = any ? QPointF(std::min(low.x(), p.x()), std::min(low.y(), p.y())) : p;
    high = any ? QPointF(std::max(high.x(), p.x()), std::max(high.y(), p.y())) : p;
    any = true;
  };
  for (const QLineF& line : m_groundSlideways)
    if (!line.isNull()) {
      include(line.p1());
      include(line.p2());
    }
  // Where the slotted bars' far ends go over the cycle (placeSlots draws them this long).
  for (std::size_t s = 0; s < m_plan.slottedLinks.size(); ++s) {
    const SlotShape& slot = m_plan.slottedLinks[s];
    for (std::size_t j = 0; j < sweep.size() && slot.tip.index < sweep.position.size(); ++j) {
      if (!sweep.assembled(j)) continue;
      const QPointF pivot = toQt(sweep.position[slot.pivot.index][j]);
      const QPointF tip = toQt(sweep.position[slot.tip.index][j]);
      const double tipDistance = length(tip - pivot);
      if (tipDistance > 0.0) include(pivot + (tip - pivot) * (barLength(s, tipDistance) / tipDistance));
    }
  }
  // A driven point's whole path and a workspace's outer circle belong in the picture too: their
  // geometry, not their items' bounds, which count a cosmetic pen's pixels as scene units.
  const auto includePath = [&](const QPainterPath& path) {
    const QRectF r = path.boundingRect();
    include(r.topLeft());
    include(r.bottomRight());
  };
  for (const DrivenPathItem* item : m_drivenPaths) includePath(item->path());
  for (const WorkspaceItem* item : m_workspaces) includePath(item->path());
  m_extraExtent = any ? QRectF(low, high) : QRectF();
}

// The driven points' paths with the stretches no workspace reaches, the annuli, and the
// cylinders' barrels (a little shorter than each actuator's shortest length over the cycle).
void MechanismItems::setDrivenDesign(const k::Mechanism& m, const k::SweepResult& sweep, const k::Pose& pose,
                                     const std::optional<k::TimeBase>& time) {
  for (std::size_t w = 0; w < m_plan.workspaces.size(); ++w) {
    const WorkspaceShape& shape = m_plan.workspaces[w];
    const auto& r = std::get<k::RrrPoint>(m.points[shape.joint.index].definition);
    m_workspaces[w]->setAnnulus(positionOf(pose, shape.pivot), std::abs(r.firstLength - r.secondLength),
                                r.firstLength + r.secondLength);
  }
  const QString unit = QString::fromStdString(m.lengthUnit);
  for (std::size_t d = 0; d < m_plan.drivenPaths.size(); ++d) {
    const k::PointId point = m_plan.drivenPaths[d];
    const k::PathShape& path = std::get<k::PathPoint>(m.points[point.index].definition).path;
    std::vector<DrivenPathItem::Stretch> stretches;
    for (const WorkspaceShape& shape : m_plan.workspaces) {
      if (shape.driven != point) continue;
      const auto& r = std::get<k::RrrPoint>(m.points[shape.joint.index].definition);
      for (const auto& [from, to] :
           k::pathOutsideAnnulus(path, pose.position[shape.pivot.index], std::abs(r.firstLength - r.secondLength),
                                 r.firstLength + r.secondLength)) {
        const auto when = [&](double s) {
          const std::vector<double> t = time ? k::timesAtPosition(*time, s, 1) : std::vector<double>{};
          return t.empty() ? std::nullopt : std::optional<double>(t.front());
        };
        const std::optional<double> t0 = when(from), t1 = when(to);
        const QString label =
            t0 && t1 ? QObject::tr("outside %1–%2 s").arg(numberText(*t0, 'g', 4), numberText(*t1, 'g', 4))
                     : QObject::tr("outside s %1–%2 %3").arg(numberText(from, 'g', 4), numberText(to, 'g', 4), unit);
        stretches.push_back({from, to, label});
      }
    }
    m_drivenPaths[d]->setShape(path, stretches);
    if (const auto* line = std::get_if<k::PolylinePath>(&path))
      for (std::size_t v = 0; v < m_vertexHandles[d].size() && v < line->vertices.size(); ++v)
        m_vertexHandles[d][v]->setPos(toQt(line->vertices[v]));
  }
  for (std::size_t a = 0; a < m_plan.actuators.size(); ++a) {
    const ActuatorShape& shape = m_plan.actuators[a];
    double shortest = (pose.position[shape.end.index] - pose.position[shape.base.index]).norm();
    for (std::size_t j = 0; j < sweep.size() && shape.end.index < sweep.position.size(); ++j)
      if (sweep.assembled(j) && !sweep.position[shape.end.index].empty())
        shortest =
            std::min(shortest, (sweep.position[shape.end.index][j] - sweep.position[shape.base.index][j]).norm());
    m_actuators[a]->setBarrel(0.85 * shortest);
  }
}

double MechanismItems::barLength(std::size_t slot, double tipDistance) const {
  return std::max(tipDistance, m_slotReach[slot] + 0.8 * m_margin);
}

void MechanismItems::setPose(const k::Mechanism& m, const k::Pose& pose) {
  const auto at = [&](k::PointId id) { return positionOf(pose, id); };
  for (std::size_t l = 0; l < m_links.size(); ++l)
    if (m_links[l] != nullptr) m_links[l]->setEnds(at(m.links[l].first), at(m.links[l].second));
  for (std::size_t b = 0; b < m_bodies.size(); ++b) {
    QPolygonF corners;
    for (const k::PointId p : m_plan.bodies[b].corners) corners << at(p);
    m_bodies[b]->setPolygon(corners);
  }
  for (std::size_t i = 0; i < m_frameLines.size(); ++i)
    m_frameLines[i]->setLine(QLineF(at(m_plan.frameLines[i].first), at(m_plan.frameLines[i].second)));
  for (std::size_t i = 0; i < m_constraintBars.size(); ++i)
    m_constraintBars[i]->setEnds(at(m_plan.constraintBars[i].first), at(m_plan.constraintBars[i].second));
  for (std::size_t i = 0; i < m_actuators.size(); ++i)
    m_actuators[i]->setEnds(at(m_plan.actuators[i].base), at(m_plan.actuators[i].end));
  for (std::size_t i = 0; i < m_grounds.size(); ++i) {
    if (m_grounds[i] != nullptr) m_grounds[i]->setPos(at({i}));
    if (m_joints[i] != nullptr) m_joints[i]->setPos(at({i}));
  }
  placeSliders(m, pose);
  placeSlots(pose);
  placeLabels(m, pose);
}

void MechanismItems::placeSliders(const k::Mechanism& m, const k::Pose& pose) {
  for (std::size_t s = 0; s < m_plan.sliders.size(); ++s) {
    const SliderShape& slider = m_plan.sliders[s];
    const k::Guide& guide = sliderGuide(m, slider);
    const k::GuideLine line = k::guideLineAt(m, guide, pose);
    m_blocks[s]->place(positionOf(pose, slider.joint), toQt(line.direction));
    if (slider.onGround) {
      m_slideways[s]->setEnds(m_groundSlideways[s].p1(), m_groundSlideways[s].p2());
      continue;
    }
    // On a moving link: along the link, far enough to hold the block wherever it is now.
    const k::Link& carrier = m.links[guide.link->index];
    double low = along(line, pose.position[slider.joint.index]);
    double high = low;
    for (const k::PointId p : {carrier.first, carrier.second}) {
      low = std::min(low, along(line, pose.position[p.index]));
      high = std::max(high, along(line, pose.position[p.index]));
    }
    m_slideways[s]->setEnds(onLine(line, low - 0.5 * m_margin), onLine(line, high + 0.5 * m_margin));
  }
}

void MechanismItems::placeSlots(const k::Pose& pose) {
  for (std::size_t s = 0; s < m_plan.slottedLinks.size(); ++s) {
    const SlotShape& slot = m_plan.slottedLinks[s];
    const QPointF pivot = positionOf(pose, slot.pivot);
    const QPointF tip = positionOf(pose, slot.tip);
    const QPointF through = positionOf(pose, slot.through);
    const double tipDistance = length(tip - pivot);
    if (!(tipDistance > 0.0)) continue;
    const QPointF u = (tip - pivot) / tipDistance;
    // The slot runs from near the pivot to past the block's farthest reach; the bar covers both.
    const double slotEnd = m_slotReach[s] + 0.5 * m_margin;
    const double slotStart = std::min(0.25 * slotEnd, 0.6 * m_margin);
    m_slots[s]->setGeometry(pivot, pivot + barLength(s, tipDistance) * u, pivot + slotStart * u, pivot + slotEnd * u);
    m_slotBlocks[s]->place(through, u);
  }
}

void MechanismItems::placeLabels(const k::Mechanism& m, const k::Pose& pose) {
  for (std::size_t i = 0; i < m_labels.size(); ++i) {
    const QPointF at = positionOf(pose, {i});
    QPointF away(0.0, 0.0);
    for (const k::PointId n : m_plan.neighbours[i]) {
      const QPointF d = positionOf(pose, n) - at;
      const double l = length(d);
      if (l > 0.0) away -= d / l;
    }
    double distance = kLabelDistancePx;
    // Beside a pivot, a little above its base: its support is below and its links above.
    if (m_plan.ground[i]) away = QPointF(away.x() < 0.0 ? -1.0 : 1.0, 0.25);
    for (const SliderShape& slider : m_plan.sliders) {
      if (slider.joint.index != i || slider.guide != 0) continue;
      // Across the guide, on the side away from the rod.
      const k::GuideLine line = k::guideLineAt(m, sliderGuide(m, slider), pose);
      QPointF normal(-line.direction.y(), line.direction.x());
      if (QPointF::dotProduct(normal, away) < 0.0) normal = -normal;
      away = normal + 0.6 * toQt(line.direction);
      distance = kSliderLabelDistancePx;
    }
    if (length(away) < 1e-6) away = QPointF(1.0, 1.0);
    m_labels[i]->setPos(at);
    m_labels[i]->placeToward(away, distance);
  }
}

void MechanismItems::setPresentationScale(double factor) {
  for (LinkItem* l : m_links)
    if (l != nullptr) l->setPresentationScale(factor);
  for (LinkItem* l : m_constraintBars) l->setPresentationScale(factor);
  for (SlottedLinkItem* s : m_slots) s->setPresentationScale(factor);
  for (SlidewayItem* s : m_slideways) s->setPresentationScale(factor);
  for (DrivenPathItem* p : m_drivenPaths) p->setPresentationScale(factor);
  for (ActuatorItem* a : m_actuators) a->setPresentationScale(factor);
  for (WorkspaceItem* w : m_workspaces) w->setPresentationScale(factor);
  for (CouplerPathItem* p : m_paths)
    if (p != nullptr) p->setPresentationScale(factor);
  for (QGraphicsLineItem* line : m_frameLines)
    line->setPen(cosmeticPen(colors().frame, canvas::kFrameWidthPx * factor, Qt::DashLine));
  for (std::size_t b = 0; b < m_bodies.size(); ++b)
    m_bodies[b]->setPen(
        cosmeticPen(colorOf(m_plan.bodies[b].link.index), kPlateSideFraction * canvas::kLinkWidthPx * factor));
  const auto scaleAll = [factor](const auto& items) {
    for (QGraphicsItem* item : items)
      if (item != nullptr) item->setScale(factor);
  };
  scaleAll(m_grounds);
  scaleAll(m_joints);
  for (const auto& vertices : m_vertexHandles) scaleAll(vertices);
  scaleAll(m_labels);
  scaleAll(m_blocks);
  scaleAll(m_slotBlocks);
}

void MechanismItems::setHot(const std::optional<DragHandle>& handle) {
  for (std::size_t i = 0; i < m_grounds.size(); ++i) {
    const bool hot = handle && !handle->pathVertex && handle->point.index == i;
    if (m_grounds[i] != nullptr) m_grounds[i]->setHot(hot);
    if (m_joints[i] != nullptr) m_joints[i]->setHot(hot);
  }
  for (std::size_t d = 0; d < m_vertexHandles.size(); ++d)
    for (std::size_t v = 0; v < m_vertexHandles[d].size(); ++v)
      m_vertexHandles[d][v]->setHot(handle && handle->point == m_plan.drivenPaths[d] && handle->pathVertex == v);
}

}  // namespace linkwright::ui
