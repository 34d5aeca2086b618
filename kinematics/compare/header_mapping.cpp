#include "kinematics/compare/header_mapping.h"

#include <algorithm>
#include <cctype>
#include <regex>

namespace linkwright::kinematics::compare {
namespace {

// Lower case, Greek letters spelt out, spaces and underscores dropped, ² and sec as the unit
// names have them: "Angular acceleration, α_3 , rad/s ²" → "angularacceleration,alpha3,rad/s2".
std::string flatten(const std::string& header) {
  const std::pair<std::string, std::string> spelt[] = {{"θ", "theta"}, {"Θ", "theta"}, {"ω", "omega"}, {"Ω", "omega"},
                                                       {"α", "alpha"}, {"²", "2"},     {"°", "deg"},   {"**2", "2"},
                                                       {"^2", "2"},    {"/sec", "/s"}};
  std::string text;
  for (const char c : header)
    if (c != ' ' && c != '_' && c != '\t') text += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const auto& [from, to] : spelt)
    for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
      text.replace(at, from.size(), to);
  return text;
}

// The unit the header names after `from`: the text in the first brackets ("(deg)", "[rad/s]"),
// else the first unit name in the text, longest names first so that "rad/s2" is not read as
// "rad". "" when it names none; nullopt when it names one that does not fit `dimension`.
std::optional<std::string> unitNamed(const std::string& text, std::size_t from, Dimension dimension,
                                     const std::string& lengthUnit) {
  const std::string tail = text.substr(std::min(from, text.size()));
  const std::size_t open = tail.find_first_of("([");
  if (open != std::string::npos) {
    const std::size_t close = tail.find(tail[open] == '(' ? ')' : ']', open);
    const std::string inside = tail.substr(open + 1, close == std::string::npos ? std::string::npos : close - open - 1);
    if (findUnit(dimension, lengthUnit, inside)) return inside;
    return std::nullopt;
  }
  static const char* const kNames[] = {"rad/s2", "deg/s2", "rad/s", "deg/s", "rpm", "rad", "deg", "min", "ms"};
  for (const char* name : kNames)
    if (tail.find(name) != std::string::npos) {
      if (findUnit(dimension, lengthUnit, name)) return std::string(name);
      return std::nullopt;
    }
  return std::string();
}

struct Proposal {
  enum class Kind { None, CrankAngle, Time, Quantity } kind = Kind::None;
  std::string key;   // Kind::Quantity
  std::string unit;  // "" for the first unit
};

Proposal fromSymbol(const std::string& text, const Mechanism& m) {
  static const std::regex symbol("(theta|omega|alpha)([1-9])");
  const auto begin = std::sregex_iterator(text.begin(), text.end(), symbol);
  const std::ptrdiff_t count = std::distance(begin, std::sregex_iterator());
  if (count != 1) return {};
  const std::smatch& match = *begin;
  const std::string kind = match[1].str(), link = match[2].str();
  const std::size_t after = static_cast<std::size_t>(match.position(0) + match.length(0));
  if (link == "2" && kind == "theta") {
    const auto unit = unitNamed(text, after, Dimension::Angle, m.lengthUnit);
    return unit ? Proposal{Proposal::Kind::CrankAngle, "", *unit} : Proposal{};
  }
  const std::string body = link == "3" ? "coupler" : link == "4" ? "rocker" : "";
  if (body.empty()) return {};
  const std::string key = body + (kind == "theta" ? "_angle" : kind == "omega" ? "_omega" : "_alpha");
  const auto quantity = findQuantity(m, key);
  if (!quantity) return {};
  const auto unit = unitNamed(text, after, quantity->dimension, m.lengthUnit);
  return unit ? Proposal{Proposal::Kind::Quantity, key, *unit} : Proposal{};
}

Proposal propose(const std::string& header, const Mechanism& m) {
  std::string implied;
  if (header == "time_s") return {Proposal::Kind::Time, "", "s"};
  if (header.ends_with("angle_deg") && header.starts_with("crank")) return {Proposal::Kind::CrankAngle, "", "deg"};
  if (const auto q = findQuantity(m, header, &implied); q && !implied.empty())
    return {Proposal::Kind::Quantity, q->key, implied};
  const std::string text = flatten(header);
  if (text.find("crankangle") != std::string::npos) {
    const auto unit = unitNamed(text, 0, Dimension::Angle, m.lengthUnit);
    return unit ? Proposal{Proposal::Kind::CrankAngle, "", *unit} : Proposal{};
  }
  static const std::regex time("(time|t)([(\\[,].*)?");
  if (std::regex_match(text, time)) {
    const auto unit = unitNamed(text, 0, Dimension::Time, m.lengthUnit);
    return unit ? Proposal{Proposal::Kind::Time, "", *unit} : Proposal{};
  }
  return fromSymbol(text, m);
}

}  // namespace

ColumnMapping proposeColumnMapping(const io::NumericTable& table, const Mechanism& m) {
  ColumnMapping mapping;
  std::optional<AxisColumn> time;
  for (std::size_t c = 0; c < table.labels.size(); ++c) {
    const Proposal p = propose(table.labels[c], m);
    switch (p.kind) {
    case Proposal::Kind::None: break;
    case Proposal::Kind::CrankAngle:
      if (!mapping.axis)
        mapping.axis =
            AxisColumn{c, AxisKind::CrankAngle, *findUnit(Dimension::Angle, "", p.unit.empty() ? "deg" : p.unit)};
      break;
    case Proposal::Kind::Time:
      if (!time) time = AxisColumn{c, AxisKind::Time, *findUnit(Dimension::Time, "", p.unit.empty() ? "s" : p.unit)};
      break;
    case Proposal::Kind::Quantity: {
      const CompareQuantity q = *findQuantity(m, p.key);
      const auto unit =
          p.unit.empty() ? unitsFor(q.dimension, m.lengthUnit).front() : *findUnit(q.dimension, m.lengthUnit, p.unit);
      const bool taken = std::any_of(mapping.columns.begin(), mapping.columns.end(),
                                     [&](const MappedColumn& other) { return other.quantity.key == q.key; });
      if (!taken) mapping.columns.push_back(MappedColumn{c, q, unit});
      break;
    }
    }
  }
  if (!mapping.axis) mapping.axis = time;
  return mapping;
}

}  // namespace linkwright::kinematics::compare
