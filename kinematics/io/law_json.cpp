#include "kinematics/io/law_json.h"

#include "kinematics/model/number_text.h"

namespace linkwright::kinematics::io {
namespace {

std::string number(double value) { return formatJsonNumber(value); }

void writeList(std::ostream& out, const std::vector<double>& values) {
  out << '[';
  for (std::size_t i = 0; i < values.size(); ++i) out << (i ? ", " : "") << number(values[i]);
  out << ']';
}

struct LawWriter {
  std::ostream& out;
  const InputKeys& keys;

  std::string key(const std::string& name) const { return '"' + name + "\": "; }
  void operator()(const ConstantVelocity& l) const {
    out << R"({"type": "constant", )" << key(keys.lawStart) << number(l.start) << ", " << key(keys.lawVelocity)
        << number(l.velocity) << '}';
  }
  void operator()(const RampToSpeed& l) const {
    out << R"({"type": "ramp", )" << key(keys.lawStart) << number(l.start) << ", " << key(keys.lawVelocity)
        << number(l.velocity) << R"(, "ramp_time_s": )" << number(l.rampTime) << '}';
  }
  void rise(const char* type, double start, double rise, double duration) const {
    out << R"({"type": ")" << type << "\", " << key(keys.lawStart) << number(start) << ", " << key(keys.lawRise)
        << number(rise) << R"(, "duration_s": )" << number(duration) << '}';
  }
  void operator()(const CycloidalRise& l) const { rise("cycloidal", l.start, l.rise, l.duration); }
  void operator()(const PolynomialRise& l) const { rise("345", l.start, l.rise, l.duration); }
  void operator()(const TableLaw& l) const {
    out << R"({"type": "table", "time_s": )";
    writeList(out, l.time);
    out << ", " << key(keys.lawTable);
    writeList(out, l.position);
    out << '}';
  }
};

std::vector<double> readList(const JsonValue& parent, const std::string& key, const std::string& path, JsonReader& r) {
  std::vector<double> values;
  const JsonValue* list = r.array(parent, key, path + "." + key);
  if (list == nullptr) return values;
  for (std::size_t i = 0; i < list->size(); ++i) {
    const JsonValue& item = (*list)[i];
    if (!item.is_number()) {
      r.fail(path + "." + key + "[" + std::to_string(i) + "]", "must be a number");
      return values;
    }
    values.push_back(item.get<double>());
  }
  return values;
}

}  // namespace

InputKeys inputKeys(InputKind kind, const std::string& u) {
  if (kind == InputKind::Angle)
    return {"omega_rad_s", "alpha_rad_s2",   "from_deg", "to_deg",
            "start_rad",   "velocity_rad_s", "rise_rad", "angle_rad"};
  return {"velocity_" + u + "_s", "acceleration_" + u + "_s2", "from_" + u, "to_" + u,
          "start_" + u,           "velocity_" + u + "_s",      "rise_" + u, "position_" + u};
}

void writeLaw(std::ostream& out, const MotionLaw& law, const InputKeys& keys) { std::visit(LawWriter{out, keys}, law); }

std::optional<MotionLaw> readLaw(const JsonValue& value, const std::string& path, const InputKeys& keys,
                                 JsonReader& r) {
  const auto type = r.string(value, "type", path + ".type");
  if (!type) return std::nullopt;
  const auto num = [&](const std::string& key) { return r.number(value, key, path + "." + key).value_or(0.0); };
  std::optional<MotionLaw> law;
  if (*type == "constant") law = ConstantVelocity{num(keys.lawStart), num(keys.lawVelocity)};
  else if (*type == "ramp") law = RampToSpeed{num(keys.lawStart), num(keys.lawVelocity), num("ramp_time_s")};
  else if (*type == "cycloidal") law = CycloidalRise{num(keys.lawStart), num(keys.lawRise), num("duration_s")};
  else if (*type == "345") law = PolynomialRise{num(keys.lawStart), num(keys.lawRise), num("duration_s")};
  else if (*type == "table") {
    auto time = readList(value, "time_s", path, r);
    auto angle = readList(value, keys.lawTable, path, r);
    if (r.error) return std::nullopt;
    // Named by the document's own keys: makeTableLaw knows them only as times and positions.
    if (time.size() != angle.size()) {
      r.fail(path + "." + keys.lawTable, "has " + std::to_string(angle.size()) + " values but " + path +
                                             ".time_s has " + std::to_string(time.size()) +
                                             ": the two lists must have the same length, one value per time");
      return std::nullopt;
    }
    auto table = makeTableLaw(std::move(time), std::move(angle));
    if (!table) {
      r.fail(path, table.error().message);
      return std::nullopt;
    }
    law = std::move(*table);
  } else {
    r.fail(path + ".type",
           "must be \"constant\", \"ramp\", \"cycloidal\", \"345\" or \"table\" (got \"" + *type + "\")");
  }
  if (r.error) return std::nullopt;
  return law;
}

}  // namespace linkwright::kinematics::io
