#include "kinematics/io/dynamics_json.h"

#include "kinematics/io/json.h"
#include "kinematics/model/number_text.h"

#include <cmath>

namespace linkwright::kinematics::io {
namespace {

std::string xy(const Eigen::Vector2d& v, const char* x, const char* y) {
  return "\"" + std::string(x) + "\": " + formatJsonNumber(v.x()) + ", \"" + y + "\": " + formatJsonNumber(v.y());
}

std::string linkMember(const LinkMass& l) {
  std::string s = jsonQuote(l.link) + ": {\"mass_kg\": " + formatJsonNumber(l.mass);
  if (l.centre)
    s += ", \"centre\": {\"along\": " + formatJsonNumber(l.centre->along) +
         ", \"across\": " + formatJsonNumber(l.centre->across) + "}";
  if (l.inertia) s += ", \"inertia_kg_m2\": " + formatJsonNumber(*l.inertia);
  return s + "}";
}

std::string guideMember(int guide) { return guide == 0 ? "" : ", \"guide\": " + std::to_string(guide); }

std::string forceMember(const PointForce& f) {
  const std::string at = f.link.empty() ? "\"slider\": " + jsonQuote(f.point) + guideMember(f.guide)
                                        : "\"link\": " + jsonQuote(f.link) + ", \"point\": " + jsonQuote(f.point);
  return "{" + at + ", " + xy(f.force, "x_N", "y_N") + "}";
}

// Writes `"name": [` items `]` (or `{` `}`), one item a line.
template <typename T, typename F>
void writeList(std::ostream& out, bool& first, const char* name, const std::vector<T>& items, F item,
               bool object = false) {
  if (items.empty()) return;
  out << (first ? "\n" : ",\n") << "    \"" << name << "\": " << (object ? "{" : "[");
  first = false;
  for (std::size_t k = 0; k < items.size(); ++k) out << (k == 0 ? "\n" : ",\n") << "      " << item(items[k]);
  out << "\n    " << (object ? "}" : "]");
}

int readGuide(const JsonValue& v, const std::string& path, JsonReader& r) {
  if (!JsonReader::has(v, "guide")) return 0;
  const double g = r.number(v, "guide", path + ".guide").value_or(0.0);
  if (!r.error && (g != std::floor(g) || g < 0.0 || g > 1.0))
    r.fail(path + ".guide", "must be 0 or 1 (got " + formatShort(g) + ")");
  return static_cast<int>(g);
}

void readLinks(const JsonValue& d, JsonReader& r, LinkageDynamics& out) {
  const JsonValue* links = r.object(d, "links", "dynamics.links", false);
  if (links == nullptr) return;
  for (const auto& [name, v] : links->items()) {
    if (r.error) break;
    const std::string path = "dynamics.links." + name;
    if (!v.is_object()) {
      r.fail(path, "must be an object");
      break;
    }
    LinkMass l{name, r.number(v, "mass_kg", path + ".mass_kg").value_or(0.0), std::nullopt, std::nullopt};
    if (const JsonValue* c = r.object(v, "centre", path + ".centre", false))
      l.centre = LinkFramePoint{r.number(*c, "along", path + ".centre.along").value_or(0.0),
                                r.number(*c, "across", path + ".centre.across").value_or(0.0)};
    if (JsonReader::has(v, "inertia_kg_m2")) l.inertia = r.number(v, "inertia_kg_m2", path + ".inertia_kg_m2");
    out.links.push_back(l);
  }
}

// Calls item(value, path) for each object of the array member `key` of `d`.
template <typename F>
void readArray(const JsonValue& d, const std::string& key, JsonReader& r, F item) {
  const JsonValue* list = r.array(d, key, "dynamics." + key, false);
  for (std::size_t k = 0; list != nullptr && k < list->size() && !r.error; ++k) {
    const std::string path = "dynamics." + key + "[" + std::to_string(k) + "]";
    if (!(*list)[k].is_object()) {
      r.fail(path, "must be an object");
      break;
    }
    item((*list)[k], path);
  }
}

PointForce readForce(const JsonValue& v, const std::string& path, JsonReader& r) {
  PointForce f;
  if (JsonReader::has(v, "slider")) {
    f.point = r.string(v, "slider", path + ".slider").value_or("");
    f.guide = readGuide(v, path, r);
  } else {
    f.link = r.string(v, "link", path + ".link").value_or("");
    f.point = r.string(v, "point", path + ".point").value_or("");
  }
  f.force = {r.number(v, "x_N", path + ".x_N").value_or(0.0), r.number(v, "y_N", path + ".y_N").value_or(0.0)};
  return f;
}

// "links[1].mass" → 1 and "mass": the index and the member after it in a checkDynamics field.
std::pair<std::size_t, std::string> indexed(const std::string& field, std::size_t open) {
  const std::size_t close = field.find(']', open);
  const std::size_t index = std::stoul(field.substr(open + 1, close - open - 1));
  return {index, close + 2 <= field.size() ? field.substr(close + 2) : std::string()};
}

std::string renamed(const std::string& member) {
  if (member == "mass") return "mass_kg";
  if (member == "inertia") return "inertia_kg_m2";
  if (member == "torque") return "torque_N_m";
  if (member == "force.x") return "x_N";
  if (member == "force.y") return "y_N";
  if (member == "stiffness") return "stiffness_N_m";
  if (member == "freeLength") return "free_length";
  if (member == "preload") return "preload_N";
  return member;
}

// checkDynamics' field ("links[1].mass", "loads.forces[0].force.x") as a document path.
std::string documentPath(const std::string& field, const LinkageDynamics& d) {
  if (field.rfind("links[", 0) == 0) {
    const auto [k, member] = indexed(field, 5);
    return "dynamics.links." + d.links[k].link + (member == "link" ? "" : "." + renamed(member));
  }
  if (field.rfind("sliders[", 0) == 0)
    return "dynamics." + field.substr(0, field.find(']') + 2) + renamed(indexed(field, 7).second);
  if (field.rfind("loads.gravity", 0) == 0) return "dynamics.gravity_m_s2" + field.substr(13);
  if (field.rfind("loads.torques[", 0) == 0) {
    const auto [k, member] = indexed(field, 13);
    return "dynamics.torques[" + std::to_string(k) + "]." + renamed(member);
  }
  if (field.rfind("loads.forces[", 0) == 0) {
    const auto [k, member] = indexed(field, 12);
    const bool slider = d.loads.forces[k].link.empty();
    return "dynamics.forces[" + std::to_string(k) + "]." + (slider && member == "point" ? "slider" : renamed(member));
  }
  if (field.rfind("loads.springs[", 0) == 0) {
    const auto [k, member] = indexed(field, 13);
    return "dynamics.springs[" + std::to_string(k) + "]." + renamed(member);
  }
  return "dynamics." + field;
}

std::string springEnd(const SpringEnd& end) {
  return "{" + (end.link.empty() ? std::string() : "\"link\": " + jsonQuote(end.link) + ", ") +
         "\"point\": " + jsonQuote(end.point) + "}";
}

SpringEnd readSpringEnd(const JsonValue& spring, const std::string& key, const std::string& path, JsonReader& r) {
  const JsonValue* end = r.object(spring, key, path + "." + key);
  if (end == nullptr) return {};
  SpringEnd out;
  if (JsonReader::has(*end, "link")) out.link = r.string(*end, "link", path + "." + key + ".link").value_or("");
  out.point = r.string(*end, "point", path + "." + key + ".point").value_or("");
  return out;
}

}  // namespace

void writeDynamicsMember(std::ostream& out, const LinkageDynamics& d) {
  if (d.empty()) return;
  out << ",\n  \"dynamics\": {";
  bool first = true;
  writeList(out, first, "links", d.links, linkMember, true);
  writeList(out, first, "sliders", d.sliders, [](const SliderMass& s) {
    return "{\"point\": " + jsonQuote(s.point) + guideMember(s.guide) + ", \"mass_kg\": " + formatJsonNumber(s.mass) +
           ", \"inertia_kg_m2\": " + formatJsonNumber(s.inertia) + "}";
  });
  if (d.loads.gravity) {
    out << (first ? "\n" : ",\n") << "    \"gravity_m_s2\": {" << xy(*d.loads.gravity, "x", "y") << "}";
    first = false;
  }
  writeList(out, first, "torques", d.loads.torques, [](const LinkTorque& t) {
    return "{\"link\": " + jsonQuote(t.link) + ", \"torque_N_m\": " + formatJsonNumber(t.torque) + "}";
  });
  writeList(out, first, "forces", d.loads.forces, forceMember);
  writeList(out, first, "springs", d.loads.springs, [](const Spring& sp) {
    return "{\"name\": " + jsonQuote(sp.name) + ", \"first\": " + springEnd(sp.first) +
           ", \"second\": " + springEnd(sp.second) + ", \"stiffness_N_m\": " + formatJsonNumber(sp.stiffness) +
           ", \"free_length\": " + formatJsonNumber(sp.freeLength) +
           ", \"preload_N\": " + formatJsonNumber(sp.preload) + "}";
  });
  out << "\n  }";
}

LinkageDynamics readDynamicsMember(const JsonValue& root, JsonReader& r) {
  LinkageDynamics out;
  const JsonValue* d = r.object(root, "dynamics", "dynamics", false);
  if (d == nullptr) return out;
  readLinks(*d, r, out);
  readArray(*d, "sliders", r, [&](const JsonValue& v, const std::string& path) {
    SliderMass s{r.string(v, "point", path + ".point").value_or(""), readGuide(v, path, r),
                 r.number(v, "mass_kg", path + ".mass_kg").value_or(0.0), 0.0};
    if (JsonReader::has(v, "inertia_kg_m2"))
      s.inertia = r.number(v, "inertia_kg_m2", path + ".inertia_kg_m2").value_or(0.0);
    out.sliders.push_back(s);
  });
  if (const JsonValue* g = r.object(*d, "gravity_m_s2", "dynamics.gravity_m_s2", false))
    out.loads.gravity = Eigen::Vector2d(r.number(*g, "x", "dynamics.gravity_m_s2.x").value_or(0.0),
                                        r.number(*g, "y", "dynamics.gravity_m_s2.y").value_or(0.0));
  readArray(*d, "torques", r, [&](const JsonValue& v, const std::string& path) {
    out.loads.torques.push_back({r.string(v, "link", path + ".link").value_or(""),
                                 r.number(v, "torque_N_m", path + ".torque_N_m").value_or(0.0)});
  });
  readArray(*d, "forces", r,
            [&](const JsonValue& v, const std::string& path) { out.loads.forces.push_back(readForce(v, path, r)); });
  readArray(*d, "springs", r, [&](const JsonValue& v, const std::string& path) {
    Spring sp;
    if (JsonReader::has(v, "name")) sp.name = r.string(v, "name", path + ".name").value_or("");
    sp.first = readSpringEnd(v, "first", path, r);
    sp.second = readSpringEnd(v, "second", path, r);
    sp.stiffness = r.number(v, "stiffness_N_m", path + ".stiffness_N_m").value_or(0.0);
    sp.freeLength = r.number(v, "free_length", path + ".free_length").value_or(0.0);
    if (JsonReader::has(v, "preload_N")) sp.preload = r.number(v, "preload_N", path + ".preload_N").value_or(0.0);
    out.loads.springs.push_back(sp);
  });
  return out;
}

std::optional<Error> checkDocumentDynamics(const Mechanism& mechanism, const LinkageDynamics& dynamics) {
  auto e = checkDynamics(mechanism, dynamics);
  if (!e) return e;
  const std::string path = documentPath(e->field, dynamics);
  const std::string reason = e->message.substr(std::min(e->message.size(), e->field.size()));
  return Error{e->code, path, path + reason};
}

}  // namespace linkwright::kinematics::io
