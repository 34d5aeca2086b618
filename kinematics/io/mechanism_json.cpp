#include "kinematics/io/mechanism_json.h"

#include "kinematics/model/number_text.h"

#include <map>
#include <sstream>

namespace linkwright::kinematics::io {
namespace {

const char* branchName(Branch b) { return b == Branch::Open ? "open" : "crossed"; }

// Writes one point's members after its name; names of points and links come from `m`.
class PointWriter {
public:
  PointWriter(std::ostream& out, const Mechanism& m) : m_out(out), m_m(m) {}

  void operator()(const GroundPoint& g) { m_out << "\"type\": \"ground\"" << xy(g.position); }
  void operator()(const CrankPoint& c) {
    m_out << "\"type\": \"crank\", \"pivot\": " << point(c.pivot) << ", \"length\": " << formatJsonNumber(c.length)
          << ", \"phase_rad\": " << formatJsonNumber(c.phase);
  }
  void operator()(const PathPoint& d) { m_out << "\"type\": \"path\", \"path\": " << path(d.path); }
  void operator()(const ActuatorPoint& a) {
    m_out << "\"type\": \"actuator\", \"first\": " << point(a.first) << ", \"length\": " << formatJsonNumber(a.length)
          << ", \"base\": " << point(a.base) << ", \"branch\": \"" << branchName(a.branch) << "\"";
  }
  void operator()(const RrrPoint& r) {
    m_out << "\"type\": \"rrr\", \"first\": " << point(r.first)
          << ", \"first_length\": " << formatJsonNumber(r.firstLength) << ", \"second\": " << point(r.second)
          << ", \"second_length\": " << formatJsonNumber(r.secondLength) << ", \"branch\": \"" << branchName(r.branch)
          << "\"";
  }
  void operator()(const RrpPoint& p) {
    m_out << "\"type\": \"rrp\", \"first\": " << point(p.first) << ", \"length\": " << formatJsonNumber(p.length)
          << ", \"branch\": \"" << branchName(p.branch) << "\", \"guide\": " << guide(p.guide);
  }
  void operator()(const RprPoint& s) {
    m_out << "\"type\": \"rpr\", \"pivot\": " << point(s.pivot) << ", \"through\": " << point(s.through)
          << ", \"length\": " << formatJsonNumber(s.length);
  }
  void operator()(const PrpPoint& q) {
    m_out << "\"type\": \"prp\", \"first_guide\": " << guide(q.first) << ", \"second_guide\": " << guide(q.second);
  }
  void operator()(const AttachedPoint& a) {
    m_out << "\"type\": \"attached\", \"link\": " << jsonQuote(m_m.links[a.link.index].name)
          << ", \"along\": " << formatJsonNumber(a.along) << ", \"across\": " << formatJsonNumber(a.across);
  }
  void operator()(const FreePoint& f) { m_out << "\"type\": \"free\"" << xy(f.guess); }

private:
  std::string point(PointId id) const { return jsonQuote(m_m.points[id.index].name); }
  static std::string xy(const Eigen::Vector2d& p) {
    return ", \"x\": " + formatJsonNumber(p.x()) + ", \"y\": " + formatJsonNumber(p.y());
  }
  static std::string path(const PathShape& shape) {
    if (const auto* line = std::get_if<PolylinePath>(&shape)) {
      std::string s = "{\"shape\": \"polyline\", \"vertices\": [";
      for (std::size_t k = 0; k < line->vertices.size(); ++k)
        s += std::string(k == 0 ? "" : ", ") + "{\"x\": " + formatJsonNumber(line->vertices[k].x()) +
             ", \"y\": " + formatJsonNumber(line->vertices[k].y()) + "}";
      return s + "]}";
    }
    const auto& arc = std::get<ArcPath>(shape);
    return "{\"shape\": \"arc\"" + xy(arc.centre) + ", \"radius\": " + formatJsonNumber(arc.radius) +
           ", \"start_angle_rad\": " + formatJsonNumber(arc.startAngle) +
           ", \"sweep_rad\": " + formatJsonNumber(arc.sweep) + "}";
  }
  std::string guide(const Guide& g) const {
    std::string s = "{";
    if (g.link) s += "\"link\": " + jsonQuote(m_m.links[g.link->index].name) + ", ";
    return s + "\"x\": " + formatJsonNumber(g.point.x()) + ", \"y\": " + formatJsonNumber(g.point.y()) +
           ", \"angle_rad\": " + formatJsonNumber(g.angle) + "}";
  }

  std::ostream& m_out;
  const Mechanism& m_m;
};

// Reads point definitions, resolving point and link names to ids.
class PointReader {
public:
  PointReader(JsonReader& r, const std::map<std::string, std::size_t>& points,
              const std::map<std::string, std::size_t>& links)
      : m_r(r), m_points(points), m_links(links) {}

  PointDefinition read(const JsonValue& v, const std::string& path) {
    const std::string type = m_r.string(v, "type", path + ".type").value_or("");
    if (m_r.error) return GroundPoint{};
    if (type == "ground") return GroundPoint{xy(v, path)};
    if (type == "crank")
      return CrankPoint{point(v, "pivot", path), positive(v, "length", path), number(v, "phase_rad", path)};
    if (type == "path") {
      const JsonValue* shape = m_r.object(v, "path", path + ".path");
      return PathPoint{shape ? pathShape(*shape, path + ".path") : PathShape{}};
    }
    if (type == "actuator")
      return ActuatorPoint{point(v, "first", path), positive(v, "length", path), point(v, "base", path),
                           branch(v, path)};
    if (type == "rrr")
      return RrrPoint{point(v, "first", path), positive(v, "first_length", path), point(v, "second", path),
                      positive(v, "second_length", path), branch(v, path)};
    if (type == "rrp") {
      const JsonValue* g = m_r.object(v, "guide", path + ".guide");
      return RrpPoint{point(v, "first", path), positive(v, "length", path), g ? guide(*g, path + ".guide") : Guide{},
                      branch(v, path)};
    }
    if (type == "rpr") return RprPoint{point(v, "pivot", path), point(v, "through", path), positive(v, "length", path)};
    if (type == "prp") {
      const JsonValue* a = m_r.object(v, "first_guide", path + ".first_guide");
      const JsonValue* b = m_r.object(v, "second_guide", path + ".second_guide");
      if (a == nullptr || b == nullptr) return GroundPoint{};
      return PrpPoint{guide(*a, path + ".first_guide"), guide(*b, path + ".second_guide")};
    }
    if (type == "attached")
      return AttachedPoint{link(v, "link", path), number(v, "along", path), number(v, "across", path)};
    if (type == "free") return FreePoint{xy(v, path)};
    m_r.fail(path + ".type",
             "must be one of ground, crank, path, actuator, rrr, rrp, rpr, prp, attached, free (got \"" + type + "\")");
    return GroundPoint{};
  }

  PointId point(const JsonValue& v, const std::string& key, const std::string& path) {
    const std::string name = m_r.string(v, key, path + "." + key).value_or("");
    if (m_r.error) return {};
    const auto it = m_points.find(name);
    if (it == m_points.end()) m_r.fail(path + "." + key, "names no point of this mechanism (got \"" + name + "\")");
    return it == m_points.end() ? PointId{} : PointId{it->second};
  }

  double positive(const JsonValue& v, const std::string& key, const std::string& path) {
    return m_r.positive(v, key, path + "." + key).value_or(1.0);
  }

private:
  double number(const JsonValue& v, const std::string& key, const std::string& path) {
    return m_r.number(v, key, path + "." + key).value_or(0.0);
  }
  Eigen::Vector2d xy(const JsonValue& v, const std::string& path) {
    return {number(v, "x", path), number(v, "y", path)};
  }
  Branch branch(const JsonValue& v, const std::string& path) {
    const std::string b = m_r.string(v, "branch", path + ".branch").value_or("open");
    if (b != "open" && b != "crossed")
      m_r.fail(path + ".branch", "must be \"open\" or \"crossed\" (got \"" + b + "\")");
    return b == "crossed" ? Branch::Crossed : Branch::Open;
  }
  LinkId link(const JsonValue& v, const std::string& key, const std::string& path) {
    const std::string name = m_r.string(v, key, path + "." + key).value_or("");
    if (m_r.error) return {};
    const auto it = m_links.find(name);
    if (it == m_links.end()) m_r.fail(path + "." + key, "names no link of this mechanism (got \"" + name + "\")");
    return it == m_links.end() ? LinkId{} : LinkId{it->second};
  }
  PathShape pathShape(const JsonValue& v, const std::string& path) {
    const std::string shape = m_r.string(v, "shape", path + ".shape").value_or("");
    if (shape == "arc")
      return ArcPath{xy(v, path), positive(v, "radius", path), number(v, "start_angle_rad", path),
                     number(v, "sweep_rad", path)};
    if (shape != "polyline") {
      m_r.fail(path + ".shape", "must be \"polyline\" or \"arc\" (got \"" + shape + "\")");
      return PolylinePath{};
    }
    PolylinePath line;
    const JsonValue* vertices = m_r.array(v, "vertices", path + ".vertices");
    if (vertices == nullptr) return line;
    for (std::size_t k = 0; k < vertices->size(); ++k) {
      const JsonValue& vertex = (*vertices)[k];
      const std::string at = path + ".vertices[" + std::to_string(k) + "]";
      if (!vertex.is_object()) {
        m_r.fail(at, "must be an object with x and y");
        return line;
      }
      line.vertices.push_back(xy(vertex, at));
    }
    return line;
  }
  Guide guide(const JsonValue& g, const std::string& path) {
    Guide out;
    if (JsonReader::has(g, "link")) out.link = link(g, "link", path);
    out.point = xy(g, path);
    out.angle = number(g, "angle_rad", path);
    return out;
  }

  JsonReader& m_r;
  const std::map<std::string, std::size_t>& m_points;
  const std::map<std::string, std::size_t>& m_links;
};

// The names in an array of {"name": …} objects, in order; a repeat is an error.
std::map<std::string, std::size_t> names(const JsonValue& list, const std::string& path, JsonReader& r) {
  std::map<std::string, std::size_t> out;
  for (std::size_t i = 0; i < list.size() && !r.error; ++i) {
    const std::string at = path + "[" + std::to_string(i) + "]";
    if (!list[i].is_object()) {
      r.fail(at, "must be an object");
      break;
    }
    const std::string name = r.string(list[i], "name", at + ".name").value_or("");
    if (!r.error && !out.emplace(name, i).second) r.fail(at + ".name", "repeats the name '" + name + "'");
  }
  return out;
}

}  // namespace

void writeMechanismMembers(std::ostream& out, const Mechanism& m) {
  out << "    \"points\": [";
  for (std::size_t i = 0; i < m.points.size(); ++i) {
    out << (i == 0 ? "\n" : ",\n") << "      {\"name\": " << jsonQuote(m.points[i].name) << ", ";
    std::visit(PointWriter{out, m}, m.points[i].definition);
    out << "}";
  }
  out << "\n    ],\n    \"links\": [";
  for (std::size_t k = 0; k < m.links.size(); ++k)
    out << (k == 0 ? "\n" : ",\n") << "      {\"name\": " << jsonQuote(m.links[k].name)
        << ", \"first\": " << jsonQuote(m.points[m.links[k].first.index].name)
        << ", \"second\": " << jsonQuote(m.points[m.links[k].second.index].name) << "}";
  out << "\n    ]";
  if (m.constraints.empty()) return;
  out << ",\n    \"constraints\": [";
  for (std::size_t c = 0; c < m.constraints.size(); ++c)
    out << (c == 0 ? "\n" : ",\n") << "      {\"first\": " << jsonQuote(m.points[m.constraints[c].first.index].name)
        << ", \"second\": " << jsonQuote(m.points[m.constraints[c].second.index].name)
        << ", \"length\": " << formatJsonNumber(m.constraints[c].length) << "}";
  out << "\n    ]";
}

Mechanism readMechanismMembers(const JsonValue& mech, const std::string& path, JsonReader& r) {
  Mechanism m;
  const JsonValue* points = r.array(mech, "points", path + ".points");
  const JsonValue* links = r.array(mech, "links", path + ".links");
  const JsonValue* constraints = r.array(mech, "constraints", path + ".constraints", false);
  if (r.error) return m;
  const auto pointIds = names(*points, path + ".points", r);
  const auto linkIds = names(*links, path + ".links", r);
  PointReader reader(r, pointIds, linkIds);
  for (std::size_t i = 0; i < points->size() && !r.error; ++i) {
    const std::string at = path + ".points[" + std::to_string(i) + "]";
    const JsonValue& v = (*points)[i];
    m.points.push_back({v.at("name").get<std::string>(), reader.read(v, at)});
  }
  for (std::size_t k = 0; k < links->size() && !r.error; ++k) {
    const std::string at = path + ".links[" + std::to_string(k) + "]";
    const JsonValue& v = (*links)[k];
    m.links.push_back({v.at("name").get<std::string>(), reader.point(v, "first", at), reader.point(v, "second", at)});
  }
  for (std::size_t c = 0; constraints != nullptr && c < constraints->size() && !r.error; ++c) {
    const std::string at = path + ".constraints[" + std::to_string(c) + "]";
    const JsonValue& v = (*constraints)[c];
    if (!v.is_object()) {
      r.fail(at, "must be an object");
      break;
    }
    m.constraints.push_back(
        {reader.point(v, "first", at), reader.point(v, "second", at), reader.positive(v, "length", at)});
  }
  return m;
}

}  // namespace linkwright::kinematics::io
