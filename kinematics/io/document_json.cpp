#include "kinematics/io/document_json.h"

#include "kinematics/io/dynamics_json.h"
#include "kinematics/io/json.h"
#include "kinematics/io/json_reader.h"
#include "kinematics/io/law_json.h"
#include "kinematics/io/mechanism_json.h"
#include "kinematics/io/synthesis_json.h"
#include "kinematics/model/mechanism_check.h"
#include "kinematics/model/number_text.h"
#include "kinematics/model/validate.h"

#include <cmath>
#include <sstream>

namespace linkwright::kinematics::io {
namespace {

Error documentError(const std::string& path, const std::string& why) {
  return Error{ErrorCode::InvalidValue, path, path + " " + why};
}

// Returns the file's version (1 … kDocumentVersion), or the error.
Result<int> checkHeader(const JsonValue& root, JsonReader& r) {
  const auto format = r.string(root, "format", "format");
  if (r.error) return *r.error;
  if (*format != "linkwright")
    return documentError("format", "must be \"linkwright\" (got \"" + *format + "\"): not a Linkwright document");
  const auto version = r.number(root, "version", "version");
  if (r.error) return *r.error;
  if (*version != std::floor(*version) || *version < 1)
    return documentError("version", "must be a whole number from 1 (got " + formatShort(*version) + ")");
  if (*version > kDocumentVersion)
    return Error{ErrorCode::InvalidValue, "version",
                 "this file is document version " + formatShort(*version) +
                     ", written by a newer Linkwright; this one reads up to version " +
                     std::to_string(kDocumentVersion)};
  return static_cast<int>(*version);
}

// A version 1 or 2 four-bar, by its lengths: read into the mechanism makeFourBar builds.
struct FourBarMembers {
  FourBarLengths lengths;
  std::string lengthUnit = "mm";
  Branch branch = Branch::Open;
  std::optional<CouplerPointSpec> couplerPoint;
};

FourBarMembers readFourBar(const JsonValue& mech, JsonReader& r) {
  FourBarMembers f;
  if (const auto unit = r.string(mech, "length_unit", "mechanism.length_unit")) f.lengthUnit = *unit;
  if (const auto branch = r.string(mech, "branch", "mechanism.branch")) {
    if (*branch == "open") f.branch = Branch::Open;
    else if (*branch == "crossed") f.branch = Branch::Crossed;
    else r.fail("mechanism.branch", "must be \"open\" or \"crossed\" (got \"" + *branch + "\")");
  }
  if (const JsonValue* l = r.object(mech, "lengths", "mechanism.lengths")) {
    f.lengths.frame = r.number(*l, "frame", "mechanism.lengths.frame").value_or(0.0);
    f.lengths.crank = r.number(*l, "crank", "mechanism.lengths.crank").value_or(0.0);
    f.lengths.coupler = r.number(*l, "coupler", "mechanism.lengths.coupler").value_or(0.0);
    f.lengths.rocker = r.number(*l, "rocker", "mechanism.lengths.rocker").value_or(0.0);
  }
  if (const JsonValue* p = r.object(mech, "coupler_point", "mechanism.coupler_point", false)) {
    CouplerPointSpec spec;
    spec.along = r.number(*p, "along", "mechanism.coupler_point.along").value_or(0.0);
    spec.across = r.number(*p, "across", "mechanism.coupler_point.across").value_or(0.0);
    f.couplerPoint = spec;
  }
  return f;
}

// Maps checkDesign's field names onto document paths, so the message names what is in the file.
std::string documentPath(const std::string& field, const InputKeys& keys) {
  if (field == "lengths" || field.rfind("lengths.", 0) == 0) return "mechanism." + field;
  if (field == "couplerPoint.along") return "mechanism.coupler_point.along";
  if (field == "couplerPoint.across") return "mechanism.coupler_point.across";
  if (field == "omega") return "driver." + keys.rate;
  if (field == "alpha") return "driver." + keys.acceleration;
  if (field == "fromDeg") return "analysis." + keys.from;
  if (field == "toDeg") return "analysis." + keys.to;
  if (field == "from time") return "analysis.from_time_s";
  if (field == "to time") return "analysis.to_time_s";
  if (field == "law.start") return "driver.law." + keys.lawStart;
  if (field == "law.rise") return "driver.law." + keys.lawRise;
  if (field == "law.duration") return "driver.law.duration_s";
  if (field == "law.rampTime") return "driver.law.ramp_time_s";
  if (field.rfind("law peak ", 0) == 0) return "driver.law's " + field.substr(4);
  if (field.rfind("the law's ", 0) == 0) return "driver.law's " + field.substr(10);
  return "analysis." + field;
}

InputKeys keysOf(const Mechanism& m) { return inputKeys(inputKind(m), m.lengthUnit); }

// The driver, analysis and dynamics members.
void writeMotion(std::ostream& s, const Design& d) {
  const InputKeys keys = keysOf(d.mechanism);
  s << "\n  },\n  \"driver\": {\"" << keys.rate << "\": " << formatJsonNumber(d.omega) << ", \"" << keys.acceleration
    << "\": " << formatJsonNumber(d.alpha);
  if (d.time) {
    s << ",\n    \"law\": ";
    writeLaw(s, d.time->law, keys);
  }
  s << "},\n  \"analysis\": {\"" << keys.from << "\": " << formatJsonNumber(d.fromDeg) << ", \"" << keys.to
    << "\": " << formatJsonNumber(d.toDeg) << ", \"samples\": " << d.samples;
  if (d.time)
    s << ", \"from_time_s\": " << formatJsonNumber(d.time->fromTime)
      << ", \"to_time_s\": " << formatJsonNumber(d.time->toTime);
  s << "}";
  writeDynamicsMember(s, d.dynamics);
  if (d.synthesis) writeSynthesisMember(s, *d.synthesis);
  s << "\n}\n";
}

void readMotion(const JsonValue& root, const InputKeys& keys, JsonReader& r, Design& d) {
  const JsonValue* law = nullptr;
  if (const JsonValue* drv = r.object(root, "driver", "driver")) {
    d.omega = r.number(*drv, keys.rate, "driver." + keys.rate).value_or(0.0);
    d.alpha = r.number(*drv, keys.acceleration, "driver." + keys.acceleration).value_or(0.0);
    law = r.object(*drv, "law", "driver.law", false);
  }
  if (const JsonValue* a = r.object(root, "analysis", "analysis")) {
    d.fromDeg = r.number(*a, keys.from, "analysis." + keys.from).value_or(0.0);
    d.toDeg = r.number(*a, keys.to, "analysis." + keys.to).value_or(0.0);
    const double samples = r.number(*a, "samples", "analysis.samples").value_or(0.0);
    if (!r.error && (samples != std::floor(samples) || samples < 2 || samples > 1e7))
      r.fail("analysis.samples", "must be a whole number from 2 to 10000000 (got " + formatShort(samples) + ")");
    else d.samples = static_cast<std::size_t>(samples);
    // A law puts the analysis on a time base (version 4).
    if (law != nullptr) {
      auto read = readLaw(*law, "driver.law", keys, r);
      const double from = r.number(*a, "from_time_s", "analysis.from_time_s").value_or(0.0);
      const double to = r.number(*a, "to_time_s", "analysis.to_time_s").value_or(0.0);
      if (read) d.time = TimeBase{std::move(*read), from, to};
    }
  }
}

void writeLinkage(std::ostream& s, const Design& d) {
  s << "    \"type\": \"linkage\",\n    \"kind\": " << jsonQuote(d.kind)
    << ",\n    \"length_unit\": " << jsonQuote(d.mechanism.lengthUnit) << ",\n";
  writeMechanismMembers(s, d.mechanism);
  writeMotion(s, d);
}

// A design check's error restated with the document path, so the message names what is in
// the file (a check's message starts with its own field name, or else is quoted whole).
std::optional<Error> inDocument(std::optional<Error> e, const InputKeys& keys = inputKeys(InputKind::Angle, "")) {
  if (!e) return std::nullopt;
  const std::string path = documentPath(e->field, keys);
  const bool named = e->message.rfind(e->field, 0) == 0;
  return Error{e->code, path, path + (named ? e->message.substr(e->field.size()) : ": " + e->message)};
}

// A four-bar's lengths and coupler point are checked by their document names; the built
// mechanism (its spread of lengths) as a four-bar.
Result<Mechanism> buildRead(const FourBarMembers& f) {
  if (auto e = checkFourBarLengths(f.lengths))
    return *inDocument(Error{e->code, "lengths." + e->field, "lengths." + e->message});
  if (f.couplerPoint) {
    if (auto e = inDocument(checkCoordinate(f.couplerPoint->along, "couplerPoint.along"))) return *e;
    if (auto e = inDocument(checkCoordinate(f.couplerPoint->across, "couplerPoint.across"))) return *e;
  }
  auto m = makeFourBar(f.lengths, f.branch, f.lengthUnit, f.couplerPoint);
  if (!m) return *inDocument(m.error());
  return m;
}

std::optional<Error> checkRead(const Design& d) {
  if (auto e = checkMechanism(d.mechanism)) return Error{e->code, "mechanism." + e->field, "mechanism." + e->message};
  const InputKeys keys = keysOf(d.mechanism);
  const InputKind kind = inputKind(d.mechanism);
  if (auto e = inDocument(checkDriveAndGrid(d.omega, d.alpha, d.fromDeg, d.toDeg, d.samples, kind), keys)) return e;
  if (d.time)
    if (auto e = inDocument(checkTimeBase(*d.time, kind), keys)) return e;
  return checkDocumentDynamics(d.mechanism, d.dynamics);
}

// Version 3 added "dynamics", version 4 the driver's "law", version 5 drivers other than a
// crank (points driven along a path, linear actuators), version 6 the synthesis targets and
// version 7 springs among the loads: a design is written as the oldest version that holds it,
// so older Linkwrights still open it, or refuse it rather than drop what they do not know.
int versionFor(const Design& design) {
  if (!design.dynamics.loads.springs.empty()) return 7;
  if (design.synthesis) return 6;
  if (inputKind(design.mechanism) != InputKind::Angle) return 5;
  if (design.time) return 4;
  return design.dynamics.empty() ? 2 : 3;
}

}  // namespace

std::string writeDocument(const Design& design) {
  std::ostringstream s;
  s << "{\n  \"format\": \"linkwright\",\n  \"version\": " << versionFor(design) << ",\n  \"mechanism\": {\n";
  writeLinkage(s, design);
  return s.str();
}

Result<Design> readDocument(std::string_view text) {
  const Result<JsonValue> parsed = parseJson(text);
  if (!parsed) return Error{ErrorCode::InvalidValue, "json", "not valid JSON: " + parsed.error().message};
  const JsonValue& root = *parsed;
  if (!root.is_object()) return documentError("document", "must be a JSON object");
  JsonReader r;
  const Result<int> version = checkHeader(root, r);
  if (!version) return version.error();
  const JsonValue* mech = r.object(root, "mechanism", "mechanism");
  const std::string type = mech != nullptr ? r.string(*mech, "type", "mechanism.type").value_or("") : "";
  if (r.error) return *r.error;
  // Version 1 knew four-bars only; version 2 added general linkages. Migration is reading.
  Design d;
  if (type == "four-bar") {
    const FourBarMembers f = readFourBar(*mech, r);
    readMotion(root, inputKeys(InputKind::Angle, f.lengthUnit), r, d);
    d.dynamics = readDynamicsMember(root, r);
    if (r.error) return *r.error;
    auto built = buildRead(f);
    if (!built) return built.error();
    d.kind = "four-bar";
    d.mechanism = std::move(*built);
    if (auto e = checkRead(d)) return *e;
    return d;
  }
  if (type != "linkage" || *version < 2)
    return documentError("mechanism.type", std::string("must be \"four-bar\"") +
                                               (*version < 2 ? "" : " or \"linkage\"") + " in a version " +
                                               std::to_string(*version) + " document (got \"" + type + "\")");
  d.kind = r.string(*mech, "kind", "mechanism.kind").value_or("");
  const std::string unit = r.string(*mech, "length_unit", "mechanism.length_unit").value_or("");
  d.mechanism = readMechanismMembers(*mech, "mechanism", r);
  d.mechanism.lengthUnit = unit;
  if (r.error) return *r.error;
  readMotion(root, keysOf(d.mechanism), r, d);
  d.dynamics = readDynamicsMember(root, r);
  d.synthesis = readSynthesisMember(root, unit, r);
  if (r.error) return *r.error;
  if (auto e = checkRead(d)) return *e;
  return d;
}

}  // namespace linkwright::kinematics::io
