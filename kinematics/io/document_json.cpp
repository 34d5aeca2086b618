#include "kinematics/io/document_json.h"

#include "kinematics/io/json.h"
#include "kinematics/io/number_format.h"

#include <cmath>
#include <sstream>

namespace linkwright::kinematics::io {
namespace {

using Type = JsonValue::Type;

Error documentError(const std::string& path, const std::string& why) {
  return Error{ErrorCode::InvalidValue, path, path + " " + why};
}

// Typed access to members; each failure names the member's full path.
class Reader {
public:
  std::optional<Error> error;

  const JsonValue* object(const JsonValue& parent, const std::string& key, const std::string& path, bool required = true) {
    const JsonValue* v = member(parent, key, path, required);
    if (v != nullptr && v->type != Type::Object) return fail(path, "must be an object");
    return v;
  }

  std::optional<double> number(const JsonValue& parent, const std::string& key, const std::string& path) {
    const JsonValue* v = member(parent, key, path, true);
    if (v == nullptr) return std::nullopt;
    if (v->type != Type::Number) {
      fail(path, "must be a number");
      return std::nullopt;
    }
    return v->number;
  }

  std::optional<std::string> string(const JsonValue& parent, const std::string& key, const std::string& path) {
    const JsonValue* v = member(parent, key, path, true);
    if (v == nullptr) return std::nullopt;
    if (v->type != Type::String) {
      fail(path, "must be a string");
      return std::nullopt;
    }
    return v->string;
  }

  std::nullptr_t fail(const std::string& path, const std::string& why) {
    if (!error) error = documentError(path, why);
    return nullptr;
  }

private:
  const JsonValue* member(const JsonValue& parent, const std::string& key, const std::string& path, bool required) {
    if (error) return nullptr;
    const JsonValue* v = parent.find(key);
    if (v == nullptr && required) return fail(path, "is missing");
    return v;
  }
};

std::optional<Error> checkHeader(const JsonValue& root, Reader& r) {
  const auto format = r.string(root, "format", "format");
  if (r.error) return r.error;
  if (*format != "linkwright") return documentError("format", "must be \"linkwright\" (got \"" + *format + "\"): not a Linkwright document");
  const auto version = r.number(root, "version", "version");
  if (r.error) return r.error;
  if (*version != std::floor(*version) || *version < 1)
    return documentError("version", "must be a whole number from 1 (got " + formatShort(*version) + ")");
  if (*version > kDocumentVersion)
    return Error{ErrorCode::InvalidValue, "version",
                 "this file is document version " + formatShort(*version) + ", written by a newer Linkwright; this one reads up to version " +
                     std::to_string(kDocumentVersion)};
  return std::nullopt;
}

void readMechanism(const JsonValue& mech, Reader& r, FourBarDesign& d) {
  const auto type = r.string(mech, "type", "mechanism.type");
  if (type && *type != "four-bar") r.fail("mechanism.type", "must be \"four-bar\" (got \"" + *type + "\")");
  if (const auto unit = r.string(mech, "length_unit", "mechanism.length_unit")) d.lengthUnit = *unit;
  if (const auto branch = r.string(mech, "branch", "mechanism.branch")) {
    if (*branch == "open") d.branch = Branch::Open;
    else if (*branch == "crossed") d.branch = Branch::Crossed;
    else r.fail("mechanism.branch", "must be \"open\" or \"crossed\" (got \"" + *branch + "\")");
  }
  if (const JsonValue* l = r.object(mech, "lengths", "mechanism.lengths")) {
    d.lengths.frame = r.number(*l, "frame", "mechanism.lengths.frame").value_or(0.0);
    d.lengths.crank = r.number(*l, "crank", "mechanism.lengths.crank").value_or(0.0);
    d.lengths.coupler = r.number(*l, "coupler", "mechanism.lengths.coupler").value_or(0.0);
    d.lengths.rocker = r.number(*l, "rocker", "mechanism.lengths.rocker").value_or(0.0);
  }
  if (const JsonValue* p = r.object(mech, "coupler_point", "mechanism.coupler_point", false)) {
    CouplerPointSpec spec;
    spec.along = r.number(*p, "along", "mechanism.coupler_point.along").value_or(0.0);
    spec.across = r.number(*p, "across", "mechanism.coupler_point.across").value_or(0.0);
    d.couplerPoint = spec;
  }
}

// Maps checkDesign's field names onto document paths, so the message names what is in the file.
std::string documentPath(const std::string& field) {
  if (field.rfind("lengths.", 0) == 0) return "mechanism." + field;
  if (field == "couplerPoint.along") return "mechanism.coupler_point.along";
  if (field == "couplerPoint.across") return "mechanism.coupler_point.across";
  if (field == "omega") return "driver.omega_rad_s";
  if (field == "alpha") return "driver.alpha_rad_s2";
  if (field == "fromDeg") return "analysis.from_deg";
  if (field == "toDeg") return "analysis.to_deg";
  return "analysis." + field;
}

} // namespace

std::string writeDocument(const FourBarDesign& d) {
  std::ostringstream s;
  const auto& l = d.lengths;
  s << "{\n  \"format\": \"linkwright\",\n  \"version\": " << kDocumentVersion << ",\n";
  s << "  \"mechanism\": {\n    \"type\": \"four-bar\",\n    \"length_unit\": " << jsonQuote(d.lengthUnit)
    << ",\n    \"branch\": \"" << (d.branch == Branch::Open ? "open" : "crossed") << "\",\n";
  s << "    \"lengths\": {\"frame\": " << formatDouble(l.frame) << ", \"crank\": " << formatDouble(l.crank)
    << ", \"coupler\": " << formatDouble(l.coupler) << ", \"rocker\": " << formatDouble(l.rocker) << "}";
  if (d.couplerPoint)
    s << ",\n    \"coupler_point\": {\"along\": " << formatDouble(d.couplerPoint->along)
      << ", \"across\": " << formatDouble(d.couplerPoint->across) << "}";
  s << "\n  },\n  \"driver\": {\"omega_rad_s\": " << formatDouble(d.omega) << ", \"alpha_rad_s2\": " << formatDouble(d.alpha)
    << "},\n  \"analysis\": {\"from_deg\": " << formatDouble(d.fromDeg) << ", \"to_deg\": " << formatDouble(d.toDeg)
    << ", \"samples\": " << d.samples << "}\n}\n";
  return s.str();
}

Result<FourBarDesign> readDocument(std::string_view text) {
  const Result<JsonValue> parsed = parseJson(text);
  if (!parsed) return Error{ErrorCode::InvalidValue, "json", "not valid JSON: " + parsed.error().message};
  const JsonValue& root = *parsed;
  if (root.type != Type::Object) return documentError("document", "must be a JSON object");
  Reader r;
  if (auto e = checkHeader(root, r)) return *e;
  FourBarDesign d;
  if (const JsonValue* mech = r.object(root, "mechanism", "mechanism")) readMechanism(*mech, r, d);
  if (const JsonValue* drv = r.object(root, "driver", "driver")) {
    d.omega = r.number(*drv, "omega_rad_s", "driver.omega_rad_s").value_or(0.0);
    d.alpha = r.number(*drv, "alpha_rad_s2", "driver.alpha_rad_s2").value_or(0.0);
  }
  if (const JsonValue* a = r.object(root, "analysis", "analysis")) {
    d.fromDeg = r.number(*a, "from_deg", "analysis.from_deg").value_or(0.0);
    d.toDeg = r.number(*a, "to_deg", "analysis.to_deg").value_or(0.0);
    const double samples = r.number(*a, "samples", "analysis.samples").value_or(0.0);
    if (!r.error && (samples != std::floor(samples) || samples < 2 || samples > 1e7))
      r.fail("analysis.samples", "must be a whole number from 2 to 10000000 (got " + formatShort(samples) + ")");
    else d.samples = static_cast<std::size_t>(samples);
  }
  if (r.error) return *r.error;
  if (auto e = checkDesign(d)) {
    const std::string path = documentPath(e->field);
    // checkDesign's message starts with its own field name: restate it with the document path.
    const std::string reason = e->message.substr(std::min(e->message.size(), e->message.find(' ')));
    return Error{e->code, path, path + reason};
  }
  return d;
}

} // namespace linkwright::kinematics::io
