#include "kinematics/analysis/link_drawing.h"

#include "kinematics/model/number_text.h"
#include "kinematics/model/validate.h"
#include "kinematics/model/vec2.h"
#include "kinematics/solve/rigid_bodies.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <set>
#include <utility>

namespace linkwright::kinematics {
namespace {

// Andrew's monotone chain, counter-clockwise, collinear and repeated points dropped.
std::vector<Eigen::Vector2d> convexHull(std::vector<Eigen::Vector2d> p) {
  std::sort(p.begin(), p.end(), [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  p.erase(std::unique(p.begin(), p.end()), p.end());
  if (p.size() < 3) return p;
  std::vector<Eigen::Vector2d> hull(2 * p.size());
  std::size_t k = 0;
  const auto add = [&](const Eigen::Vector2d& q, std::size_t floor) {
    while (k >= floor && cross(hull[k - 1] - hull[k - 2], q - hull[k - 2]) <= 0.0) --k;
    hull[k++] = q;
  };
  for (const Eigen::Vector2d& q : p) add(q, 2);
  const std::size_t lower = k + 1;
  for (std::size_t i = p.size() - 1; i-- > 0;) add(p[i], lower);
  hull.resize(k - 1);
  return hull;
}

Error drawingError(const std::string& field, const std::string& message) {
  return Error{ErrorCode::InvalidValue, field, message};
}

Outline rectangle(const Eigen::Vector2d& centre, const Eigen::Vector2d& along, double length, double height) {
  const Eigen::Vector2d u = along * (length / 2.0);
  const Eigen::Vector2d v = perp(along) * (height / 2.0);
  return {{centre - u - v, 0.0}, {centre + u - v, 0.0}, {centre + u + v, 0.0}, {centre - u + v, 0.0}};
}

std::vector<Hole> holesAt(const std::vector<PointId>& points, const Pose& pose, double diameter) {
  std::vector<Hole> holes;
  for (const PointId p : points) holes.push_back({p, pose.position[p.index], diameter});
  return holes;
}

// The centres of the ends of the slot of a slotted link on `body`, if the body is one: on the
// line pivot → tip, reaching the pin.
std::optional<std::pair<Eigen::Vector2d, Eigen::Vector2d>> slotOf(const Mechanism& m, const BodyModel& model,
                                                                  BodyId body, const Pose& pose, double d, double w) {
  for (const PrismaticJoint& joint : model.prismatics) {
    const auto* rpr = std::get_if<RprPoint>(&m.points[joint.slider.point.index].definition);
    if (rpr == nullptr || !(joint.guide == body)) continue;
    const Eigen::Vector2d pivot = pose.position[rpr->pivot.index];
    const Eigen::Vector2d u = prismaticDirection(m, joint, pose);
    const double pin = (pose.position[joint.pin.index] - pivot).dot(u);
    const double web = w / 2.0 - d / 2.0;
    const double from = std::min(pin, d + web);
    const double to = std::max(pin, rpr->length - d - web);
    return std::pair{Eigen::Vector2d(pivot + from * u), Eigen::Vector2d(pivot + std::max(from, to) * u)};
  }
  return std::nullopt;
}

DrawingLayer groundLayer(const Body& ground, const Pose& pose, double d, double w) {
  DrawingLayer layer{"GROUND", {}, holesAt(ground.points, pose, d), {}};
  for (const Hole& h : layer.holes) {
    layer.lines.push_back({h.centre - Eigen::Vector2d(w / 2.0, 0.0), h.centre + Eigen::Vector2d(w / 2.0, 0.0)});
    layer.lines.push_back({h.centre - Eigen::Vector2d(0.0, w / 2.0), h.centre + Eigen::Vector2d(0.0, w / 2.0)});
  }
  return layer;
}

DrawingLayer bodyLayer(const Mechanism& m, const BodyModel& model, BodyId id, const Pose& pose, double d, double w) {
  const Body& body = model.bodies[id.index];
  DrawingLayer layer{body.name, {}, holesAt(body.points, pose, d), {}};
  if (body.kind == BodyKind::Slider) {
    for (const PrismaticJoint& joint : model.prismatics)
      if (joint.block == id)
        layer.outlines.push_back(
            rectangle(pose.position[joint.pin.index], prismaticDirection(m, joint, pose), 2.0 * w, w));
    return layer;
  }
  std::vector<Eigen::Vector2d> centres;
  for (const Hole& h : layer.holes) centres.push_back(h.centre);
  const auto slot = slotOf(m, model, id, pose, d, w);
  if (slot) {
    centres.push_back(slot->first);
    centres.push_back(slot->second);
  }
  layer.outlines.push_back(roundedHull(centres, w / 2.0));
  if (slot) layer.outlines.push_back(roundedHull({slot->first, slot->second}, d / 2.0));
  return layer;
}

// Gives each layer a DXF-legal name that no earlier layer has (CAD programs ignore case).
void nameLayers(std::vector<DrawingLayer>& layers) {
  std::set<std::string> taken;
  const auto upper = [](std::string s) {
    for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return s;
  };
  for (DrawingLayer& layer : layers) {
    const std::string base = dxfLayerName(layer.name);
    std::string name = base;
    for (int n = 2; taken.count(upper(name)) != 0; ++n) name = base + "_" + std::to_string(n);
    taken.insert(upper(name));
    layer.name = name;
  }
}

// `x` > 0 to two significant digits, divided or multiplied by an exact power of ten so that
// 2.999999999999999 becomes 3 and 0.20000000000000004 becomes 0.2.
double twoDigits(double x) {
  if (!(std::isfinite(x) && x > 0.0)) return x;
  const int e = static_cast<int>(std::floor(std::log10(x))) - 1;
  if (e >= 0) {
    const double p = std::pow(10.0, e);
    return std::round(x / p) * p;
  }
  const double q = std::pow(10.0, -e);
  return std::round(x * q) / q;
}

Result<BodyModel> bodiesAt(const Mechanism& mechanism, const Pose& pose) {
  if (!pose.assembled || pose.position.size() != mechanism.points.size())
    return Error{ErrorCode::NotAssemblable, "pose", "the drawing needs an assembled pose of the mechanism"};
  return bodiesOf(mechanism);
}

double spacing(const BodyModel& model, const Pose& pose) {
  double shortest = std::numeric_limits<double>::infinity();
  for (const Body& body : model.bodies) {
    if (body.kind != BodyKind::Rigid) continue;
    for (std::size_t i = 0; i < body.points.size(); ++i)
      for (std::size_t j = i + 1; j < body.points.size(); ++j)
        shortest =
            std::min(shortest, (pose.position[body.points[i].index] - pose.position[body.points[j].index]).norm());
  }
  return shortest;
}

}  // namespace

Outline roundedHull(const std::vector<Eigen::Vector2d>& centres, double radius) {
  const std::vector<Eigen::Vector2d> hull = convexHull(centres);
  if (hull.size() == 1) {
    const Eigen::Vector2d r(radius, 0.0);
    return {{hull[0] - r, 1.0}, {hull[0] + r, 1.0}};
  }
  Outline outline;
  const std::size_t n = hull.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d in = (hull[i] - hull[(i + n - 1) % n]).normalized();
    const Eigen::Vector2d out = (hull[(i + 1) % n] - hull[i]).normalized();
    // Counter-clockwise hull: the outward normal of an edge is its direction turned clockwise.
    const Eigen::Vector2d normalIn(in.y(), -in.x());
    const Eigen::Vector2d normalOut(out.y(), -out.x());
    const double turn = std::abs(std::atan2(cross(in, out), in.dot(out)));
    outline.push_back({hull[i] + radius * normalIn, std::tan(turn / 4.0)});
    outline.push_back({hull[i] + radius * normalOut, 0.0});
  }
  return outline;
}

Result<double> shortestJointSpacing(const Mechanism& mechanism, const Pose& pose) {
  auto model = bodiesAt(mechanism, pose);
  if (!model) return model.error();
  return spacing(*model, pose);
}

Result<LinkDrawing> linkDrawing(const Mechanism& mechanism, const Pose& pose, const DrawingOptions& options) {
  auto model = bodiesAt(mechanism, pose);
  if (!model) return model.error();
  const double shortest = spacing(*model, pose);
  const double d = options.holeDiameter.value_or(twoDigits(shortest / 5.0));
  if (!(std::isfinite(d) && d > 0.0))
    return drawingError("holeDiameter", "hole diameter must be positive and finite (got " + formatNumber(d) + ")");
  if (!(d < shortest))
    return drawingError("holeDiameter", "hole diameter must be less than " + formatNumber(shortest) + " " +
                                            mechanism.lengthUnit +
                                            ", the shortest distance between two joints on one link, or the holes "
                                            "meet (got " +
                                            formatNumber(d) + ")");
  const double w = options.plateWidth.value_or(2.0 * d);
  if (!(std::isfinite(w) && w > d))
    return drawingError("plateWidth", "plate width must be finite and more than the hole diameter " + formatNumber(d) +
                                          " " + mechanism.lengthUnit + " (got " + formatNumber(w) + ")");
  LinkDrawing drawing{mechanism.lengthUnit, d, w, {}};
  drawing.layers.push_back(groundLayer(model->bodies[kGroundBody.index], pose, d, w));
  for (const BodyKind kind : {BodyKind::Rigid, BodyKind::Slider})
    for (std::size_t b = 1; b < model->bodies.size(); ++b)
      if (model->bodies[b].kind == kind) drawing.layers.push_back(bodyLayer(mechanism, *model, BodyId{b}, pose, d, w));
  nameLayers(drawing.layers);
  return drawing;
}

std::string dxfLayerName(const std::string& name) {
  std::string out;
  for (const char c : name) {
    const bool keep = std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '-' || c == '$';
    out += keep ? c : '_';
  }
  return out.empty() ? "PART" : out;
}

}  // namespace linkwright::kinematics
