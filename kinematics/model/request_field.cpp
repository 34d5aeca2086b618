#include "kinematics/model/request_field.h"

#include "kinematics/model/number_text.h"

#include <algorithm>
#include <cmath>

namespace linkwright::kinematics {
namespace {

// A range's end as a person writes it: 1e-6 and 1e6, not 1e-06 and 1e+06.
std::string endText(double v) { return formatCompact(v, 6); }

// A value quoted back: a count as the whole number it is, anything else as typed.
std::string valueText(double v, const RequestField& f) {
  if (f.kind == RequestField::Kind::Count && std::floor(v) == v && std::abs(v) < 1e18)
    return std::to_string(static_cast<long long>(v));
  return formatNumber(v);
}

std::string withUnit(const std::string& text, const RequestField& f) {
  return f.unit.empty() ? text : text + " " + f.unit;
}

}  // namespace

std::string fieldName(const RequestField& f, FrontEnd frontEnd) {
  switch (frontEnd) {
  case FrontEnd::Cli: {
    std::string option = "--" + f.key;
    std::replace(option.begin(), option.end(), '_', '-');
    return option;
  }
  case FrontEnd::Python: return f.key;
  case FrontEnd::Designer: return f.label;
  }
  return f.key;
}

std::string fieldName(const std::string& key, FrontEnd frontEnd) {
  RequestField field;
  field.key = key;
  field.label = key;
  return fieldName(field, frontEnd);
}

std::string rangeText(const RequestField& f) {
  const std::string low = endText(f.minimum), high = endText(f.maximum);
  std::string text;
  if (f.minimumIncluded && f.maximumIncluded) text = "from " + low + " to " + withUnit(high, f);
  else if (f.maximumIncluded) text = "above " + low + " and at most " + withUnit(high, f);
  else if (f.minimumIncluded) text = "at least " + low + " and below " + withUnit(high, f);
  else text = "between " + low + " and " + withUnit(high, f) + ", exclusive";
  if (f.zeroRefused) text += ", not 0";
  if (f.kind == RequestField::Kind::Count) text = "a whole number " + text;
  return text;
}

std::string helpText(const RequestField& f) {
  std::string text = f.help + ": " + rangeText(f);
  const std::string fallback = f.value ? endText(*f.value) : f.defaultText;
  if (!fallback.empty()) text += " (default " + fallback + ")";
  return text;
}

std::optional<Error> checkField(const RequestField& f, double value, FrontEnd frontEnd) {
  const bool above = f.minimumIncluded ? value >= f.minimum : value > f.minimum;
  const bool below = f.maximumIncluded ? value <= f.maximum : value < f.maximum;
  const bool whole = f.kind == RequestField::Kind::Number || std::floor(value) == value;
  if (above && below && whole && !(f.zeroRefused && value == 0.0)) return std::nullopt;
  return Error{ErrorCode::InvalidValue, f.key,
               fieldName(f, frontEnd) + " must be " + rangeText(f) + " (got " + withUnit(valueText(value, f), f) + ")"};
}

const RequestField* findField(const std::vector<RequestField>& fields, const std::string& key) {
  const auto found = std::find_if(fields.begin(), fields.end(), [&](const RequestField& f) { return f.key == key; });
  return found == fields.end() ? nullptr : &*found;
}

std::optional<Error> checkValues(const std::vector<RequestField>& fields, const RequestValues& given,
                                 FrontEnd frontEnd) {
  for (const auto& [key, value] : given) {
    const RequestField* field = findField(fields, key);
    if (field == nullptr) return Error{ErrorCode::InvalidValue, key, "no field '" + key + "' in this request"};
    if (auto e = checkField(*field, value, frontEnd)) return e;
  }
  return std::nullopt;
}

Error cancelledError() { return Error{ErrorCode::Cancelled, "", "cancelled"}; }

}  // namespace linkwright::kinematics
