#include "kinematics/io/synthesis_json.h"

#include "kinematics/design/synthesis_ranges.h"
#include "kinematics/model/number_text.h"
#include "kinematics/model/units.h"
#include "kinematics/model/validate.h"

#include <cmath>
#include <string_view>

namespace linkwright::kinematics::io {
namespace {

std::string num(double value) { return formatJsonNumber(value); }

std::string pair(const Eigen::Vector2d& p) { return "[" + num(p.x()) + ", " + num(p.y()) + "]"; }

std::string list(const std::vector<double>& values) {
  std::string text = "[";
  for (std::size_t i = 0; i < values.size(); ++i) text += (i ? ", " : "") + num(values[i]);
  return text + "]";
}

void writeMotion(std::ostream& out, const MotionTargets& m) {
  out << R"("motion": {"poses": [)";
  for (std::size_t i = 0; i < m.poses.size(); ++i)
    out << (i ? ", " : "") << R"({"x": )" << num(m.poses[i].point.x()) << R"(, "y": )" << num(m.poses[i].point.y())
        << R"(, "angle_rad": )" << num(m.poses[i].angle) << '}';
  out << R"(], "circle_point_a": )" << pair(m.circlePoints.a) << R"(, "circle_point_b": )" << pair(m.circlePoints.b)
      << R"(, "centre_a": )" << num(m.centreA) << R"(, "centre_b": )" << num(m.centreB) << R"(, "full_turn": )"
      << (m.needsFullRotation ? "true" : "false") << '}';
}

void writePath(std::ostream& out, const PathTarget& p, const PathSearch& search) {
  out << R"("path": {"targets": [)";
  for (std::size_t i = 0; i < p.points.size(); ++i) out << (i ? ", " : "") << pair(p.points[i]);
  out << R"(], "timing_rad": )" << list(p.timing) << R"(, "timing_from": ")"
      << (p.timingReference == TimingReference::Frame ? "frame" : "start") << R"(", "full_turn": )"
      << (p.needsFullRotation ? "true" : "false") << R"(, "starts": )" << search.starts << R"(, "seed": )"
      << search.seed << '}';
}

// The range of a number as the designer's field for it holds it (synthesis_ranges.h), and
// how a message states it.
struct Range {
  double max;
  std::string text;
};

Range lengthRange(const std::string& unit) { return {kMaxTargetValue, "±1e9 " + unit}; }
const Range kPlain{kMaxTargetValue, "±1e9"};
// The fields show degrees; 1e9 degrees is 17453292.5 rad, stated rounded down.
const Range kAngle{degToRad(kMaxTargetValue), "±1.7453e7 rad (1e9 degrees)"};

// Records that `value` at `field` is outside `range`, unless an error is recorded already.
void checkWithin(double value, const std::string& field, const Range& range, JsonReader& r) {
  if (r.error || (std::isfinite(value) && std::abs(value) <= range.max)) return;
  r.error = Error{ErrorCode::InvalidValue, field,
                  field + " must be finite and within " + range.text + " (got " + formatNumber(value) + ")"};
}

// Reads members of one object, each error naming its full path.
struct Members {
  const JsonValue& object;
  std::string path;
  JsonReader& r;

  double number(const std::string& key) const { return r.number(object, key, path + "." + key).value_or(0.0); }
  double number(const std::string& key, const Range& range) const {
    const double v = number(key);
    checkWithin(v, path + "." + key, range, r);
    return v;
  }
  std::string text(const std::string& key) const { return r.string(object, key, path + "." + key).value_or(""); }
  std::optional<double> optionalNumber(const std::string& key, const Range& range) const {
    if (!JsonReader::has(object, key)) return std::nullopt;
    return number(key, range);
  }
  bool flag(const std::string& key) const {
    const JsonValue* v = findMember(object, key);
    if (v == nullptr || !v->is_boolean()) {
      r.fail(path + "." + key, "must be true or false");
      return false;
    }
    return v->get<bool>();
  }
  // One of `names`, as its index; an error lists them.
  int choice(const std::string& key, std::initializer_list<std::string_view> names) const {
    const std::string got = text(key);
    int i = 0;
    std::string all;
    for (const std::string_view name : names) {
      if (got == name) return i;
      all += (all.empty() ? "\"" : ", \"") + std::string(name) + "\"";
      ++i;
    }
    if (!r.error) r.fail(path + "." + key, "must be one of " + all + " (got \"" + got + "\")");
    return 0;
  }
  // A whole number in [lo, hi].
  double whole(const std::string& key, double lo, double hi) const {
    const double v = number(key);
    if (!r.error && (v != std::floor(v) || v < lo || v > hi))
      r.fail(path + "." + key, "must be a whole number from " + formatShort(lo) + " to " + formatShort(hi) + " (got " +
                                   formatShort(v) + ")");
    return v;
  }
  std::vector<double> numbers(const std::string& key, const Range& range) const {
    std::vector<double> values;
    const JsonValue* a = r.array(object, key, path + "." + key);
    for (std::size_t i = 0; a != nullptr && i < a->size(); ++i) {
      const std::string item = path + "." + key + "[" + std::to_string(i) + "]";
      if (!(*a)[i].is_number()) {
        r.fail(item, "must be a number");
        break;
      }
      values.push_back((*a)[i].get<double>());
      checkWithin(values.back(), item, range, r);
    }
    return values;
  }
  // An array member of at most `most` items (the rows the designer's table and the CLI take).
  const JsonValue* list(const std::string& key, std::size_t most) const {
    const JsonValue* a = r.array(object, key, path + "." + key);
    if (a != nullptr && a->size() > most && !r.error)
      r.fail(path + "." + key,
             "must have at most " + std::to_string(most) + " items (got " + std::to_string(a->size()) + ")");
    return r.error ? nullptr : a;
  }
  std::optional<Members> child(const std::string& key) const {
    const JsonValue* o = r.object(object, key, path + "." + key);
    if (o == nullptr) return std::nullopt;
    return Members{*o, path + "." + key, r};
  }
};

// An [x, y] pair of lengths at `path`, each within `range`.
Eigen::Vector2d readPair(const JsonValue& value, const std::string& path, const Range& range, JsonReader& r) {
  if (!value.is_array() || value.size() != 2 || !value[0].is_number() || !value[1].is_number()) {
    r.fail(path, "must be a pair of numbers [x, y]");
    return Eigen::Vector2d::Zero();
  }
  const Eigen::Vector2d p(value[0].get<double>(), value[1].get<double>());
  checkWithin(p.x(), path + "[0]", range, r);
  checkWithin(p.y(), path + "[1]", range, r);
  return p;
}

void readMotion(const Members& m, const Range& length, MotionTargets& out) {
  const JsonValue* poses = m.list("poses", 3);
  for (std::size_t i = 0; poses != nullptr && i < poses->size(); ++i) {
    const Members pose{(*poses)[i], m.path + ".poses[" + std::to_string(i) + "]", m.r};
    out.poses.push_back({{pose.number("x", length), pose.number("y", length)}, pose.number("angle_rad", kAngle)});
  }
  if (const JsonValue* a = findMember(m.object, "circle_point_a"))
    out.circlePoints.a = readPair(*a, m.path + ".circle_point_a", length, m.r);
  if (const JsonValue* b = findMember(m.object, "circle_point_b"))
    out.circlePoints.b = readPair(*b, m.path + ".circle_point_b", length, m.r);
  out.centreA = m.number("centre_a", length);
  out.centreB = m.number("centre_b", length);
  out.needsFullRotation = m.flag("full_turn");
}

void readPath(const Members& m, const Range& length, PathTarget& out, PathSearch& search) {
  const JsonValue* targets = m.list("targets", 10);
  for (std::size_t i = 0; targets != nullptr && i < targets->size(); ++i)
    out.points.push_back(readPair((*targets)[i], m.path + ".targets[" + std::to_string(i) + "]", length, m.r));
  if (m.list("timing_rad", 10) != nullptr) out.timing = m.numbers("timing_rad", kAngle);
  out.timingReference =
      m.choice("timing_from", {"start", "frame"}) == 1 ? TimingReference::Frame : TimingReference::Start;
  out.needsFullRotation = m.flag("full_turn");
  search.starts = static_cast<int>(m.whole("starts", 1, 100000));
  search.seed = static_cast<std::uint32_t>(m.whole("seed", 0, 4294967295.0));
}

}  // namespace

void writeSynthesisMember(std::ostream& out, const SynthesisTargets& t) {
  out << ",\n  \"synthesis\": {\"problem\": \"" << problemName(t.problem) << "\",\n    ";
  out << R"("swing": {"swing_rad": )" << num(t.swing.swing) << R"(, "time_ratio": )" << num(t.swing.timeRatio)
      << R"(, "length": )" << num(t.swing.length) << R"(, "fixed": ")"
      << (t.swing.scale == SwingScale::Frame ? "frame" : "rocker") << "\"},\n    ";
  out << R"("slider": {"stroke": )" << num(t.slider.stroke) << R"(, "time_ratio": )" << num(t.slider.timeRatio)
      << R"(, "fixed": ")" << (t.slider.choice == SliderChoice::Offset ? "offset" : "rod") << R"(", "value": )"
      << num(t.slider.value) << "},\n    ";
  out << R"("shaper": {"stroke": )" << num(t.shaper.stroke) << R"(, "time_ratio": )" << num(t.shaper.timeRatio)
      << R"(, "crank": )" << num(t.shaper.crank) << R"(, "link": )" << num(t.shaper.link);
  if (t.shaper.guideHeight) out << R"(, "guide_height": )" << num(*t.shaper.guideHeight);
  out << "},\n    ";
  const FunctionSpec& f = t.function;
  out << R"("function": {"name": )" << jsonQuote(f.function) << R"(, "x0": )" << num(f.x0) << R"(, "x1": )" << num(f.x1)
      << R"(, "input_start_rad": )" << num(f.inputStart) << R"(, "input_span_rad": )" << num(f.inputSpan)
      << R"(, "output_start_rad": )" << num(f.outputStart) << R"(, "output_span_rad": )" << num(f.outputSpan)
      << R"(, "frame": )" << num(f.frame) << R"(, "points": )" << list(f.points) << R"(, "count": )" << f.count
      << "},\n    ";
  writeMotion(out, t.motion);
  out << ",\n    ";
  writePath(out, t.path, t.pathSearch);
  out << ",\n    "
      << R"("bounds": {"min_transmission_rad": )" << num(t.bounds.minTransmission);
  if (t.bounds.maxLinkLength) out << R"(, "max_link": )" << num(*t.bounds.maxLinkLength);
  if (t.bounds.maxLinkRatio) out << R"(, "max_ratio": )" << num(*t.bounds.maxLinkRatio);
  out << "}}";
}

std::optional<SynthesisTargets> readSynthesisMember(const JsonValue& root, const std::string& unit, JsonReader& r) {
  const JsonValue* object = r.object(root, "synthesis", "synthesis", false);
  if (object == nullptr) return std::nullopt;
  const Members s{*object, "synthesis", r};
  // Every number within the range of the designer's field for it (synthesis_ranges.h).
  const Range length = lengthRange(unit);
  SynthesisTargets t;
  t.problem =
      static_cast<SynthesisProblem>(s.choice("problem", {"swing", "slider", "shaper", "function", "motion", "path"}));
  if (const auto m = s.child("swing")) {
    t.swing = {m->number("swing_rad", kAngle), m->number("time_ratio", kPlain), m->number("length", length),
               m->choice("fixed", {"rocker", "frame"}) == 1 ? SwingScale::Frame : SwingScale::Rocker, unit};
  }
  if (const auto m = s.child("slider")) {
    t.slider = {m->number("stroke", length), m->number("time_ratio", kPlain),
                m->choice("fixed", {"rod", "offset"}) == 1 ? SliderChoice::Offset : SliderChoice::Rod,
                m->number("value", length), unit};
  }
  if (const auto m = s.child("shaper")) {
    t.shaper = {m->number("stroke", length), m->number("time_ratio", kPlain),           m->number("crank", length),
                m->number("link", length),   m->optionalNumber("guide_height", length), unit};
  }
  if (const auto m = s.child("function")) {
    FunctionSpec& f = t.function;
    f.function = m->text("name");
    f.x0 = m->number("x0", kPlain);
    f.x1 = m->number("x1", kPlain);
    f.inputStart = m->number("input_start_rad", kAngle);
    f.inputSpan = m->number("input_span_rad", kAngle);
    f.outputStart = m->number("output_start_rad", kAngle);
    f.outputSpan = m->number("output_span_rad", kAngle);
    f.frame = m->number("frame", length);
    f.points = m->numbers("points", kPlain);
    f.count = static_cast<std::size_t>(m->whole("count", 3, 1000));
  }
  if (const auto m = s.child("motion")) readMotion(*m, length, t.motion);
  if (const auto m = s.child("path")) readPath(*m, length, t.path, t.pathSearch);
  t.path.lengthUnit = unit;
  if (const auto m = s.child("bounds")) {
    t.bounds.minTransmission =
        m->number("min_transmission_rad", Range{degToRad(kMaxTransmissionBoundDeg), "±17453.29 rad (1e6 degrees)"});
    t.bounds.maxLinkLength = m->optionalNumber("max_link", length);
    if (t.bounds.maxLinkLength && !r.error)
      if (auto e = checkLength(*t.bounds.maxLinkLength, "synthesis.bounds.max_link", "(the longest link allowed)"))
        r.error = e;
    t.bounds.maxLinkRatio = m->optionalNumber("max_ratio", kPlain);
    if (t.bounds.maxLinkRatio && !r.error && !(*t.bounds.maxLinkRatio >= 1.0 && *t.bounds.maxLinkRatio <= 1e6))
      r.fail("synthesis.bounds.max_ratio",
             "must be between 1 and 1e6 (longest / shortest link; got " + formatNumber(*t.bounds.maxLinkRatio) + ")");
  }
  if (r.error) return std::nullopt;
  return t;
}

}  // namespace linkwright::kinematics::io
