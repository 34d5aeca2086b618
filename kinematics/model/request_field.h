#pragma once
// What a capability's request is made of, written once for every front end: each field's key,
// the designer's label, its unit, its accepted range, its default and one line of help. The CLI
// spells the key as an option (gear_ratio → --gear-ratio), Python as a keyword (gear_ratio), the
// designer as its label; the CLI's --help, the Python docstrings and the designer's tooltips
// and ranges are read off the same list, so a field added to a request reaches all three. A
// value is checked against its field here, and the refusal names the field as the front end
// that took it spells it, the value and the range.

#include "kinematics/model/result.h"

#include <atomic>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace linkwright::kinematics {

/// Who took the value, for the field's name in a message.
enum class FrontEnd { Cli, Python, Designer };

struct RequestField {
  enum class Kind { Number, Count };
  std::string key;    ///< "gear_ratio": Python's keyword; the CLI's option is --gear-ratio
  std::string label;  ///< the designer's: "Gear ratio"
  std::string unit;   ///< as typed: "rpm", "N·m"; "" for a pure number
  Kind kind = Kind::Number;
  double minimum = 0.0;         ///< the accepted range, in the field's unit
  double maximum = 0.0;         ///<
  bool minimumIncluded = true;  ///< whether the range's ends are accepted
  bool maximumIncluded = true;  ///<
  bool zeroRefused = false;     ///< 0 refused inside the range (a speed: either sign, not 0)
  std::optional<double> value;  ///< the default; nullopt: unset unless given (defaultText says what then)
  std::string defaultText;      ///< for help: "1", "the design's speed", "chosen for the accuracy"
  std::string help;             ///< one line, no unit or range (they are added)
};

/// What a front end was given: the field's key → its value in the field's unit. Fields not
/// given are left out.
using RequestValues = std::map<std::string, double>;

/// The field's name as `frontEnd` spells it: "--gear-ratio", "gear_ratio", "Gear ratio".
std::string fieldName(const RequestField& field, FrontEnd frontEnd);
/// The same for a key with no field of its own (an option that only combines others): the
/// designer, which has no label for it, says the key.
std::string fieldName(const std::string& key, FrontEnd frontEnd);

/// The accepted range in words, with the unit: "above 0 and at most 1", "from 4 to 100000",
/// "from -1e6 to 1e6 rpm, not 0".
std::string rangeText(const RequestField& field);

/// One line of help: the text, the unit, the range and the default.
std::string helpText(const RequestField& field);

/// Error (field: the key) unless `value` is in the field's range (a whole number for a count):
/// "--efficiency must be from 0.01 to 1 (got 5)".
std::optional<Error> checkField(const RequestField& field, double value, FrontEnd frontEnd);

/// Each given value checked against its field in `fields`; a key none of them has is refused.
/// Nullopt when all fit.
std::optional<Error> checkValues(const std::vector<RequestField>& fields, const RequestValues& given,
                                 FrontEnd frontEnd);

/// The field of `fields` whose key is `key`, or null.
const RequestField* findField(const std::vector<RequestField>& fields, const std::string& key);

/// What a long run is given besides its request: a flag another thread may set to stop it (it
/// then ends with ErrorCode::Cancelled), and where it reports how far it has come (done, of
/// total, in the run's own unit).
struct RunControl {
  const std::atomic<bool>* cancel = nullptr;
  std::function<void(std::size_t done, std::size_t total)> progress;
  bool cancelled() const { return cancel != nullptr && cancel->load(std::memory_order_relaxed); }
};

/// The Error a cancelled run ends with.
Error cancelledError();

}  // namespace linkwright::kinematics
