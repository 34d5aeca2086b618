#include "kinematics/synthesis/time_ratio.h"

#include "kinematics/model/number_text.h"
#include "kinematics/model/units.h"
#include "kinematics/model/validate.h"

#include <cmath>

namespace linkwright::kinematics {

std::optional<Error> checkTimeRatio(double q, const std::string& field) {
  if (std::isfinite(q) && q >= 1.0 && q <= kMaxTimeRatio) return std::nullopt;
  return Error{
      ErrorCode::InvalidValue, field,
      field + " must be finite and between 1 and " + formatNumber(kMaxTimeRatio) + " (got " + formatNumber(q) + ")"};
}

double timeRatioAngle(double q) { return kPi * (q - 1.0) / (q + 1.0); }

}  // namespace linkwright::kinematics
