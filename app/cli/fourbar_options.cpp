#include "app/cli/commands.h"

namespace linkwright::cli {

kinematics::Result<ResolvedFourBar> resolveFourBar(const Invocation& inv) {
  ResolvedFourBar r;
  if (inv.example) {
    r.example = kinematics::findFourBarExample(*inv.example);
    if (!r.example) {
      std::string names;
      for (const auto& e : kinematics::fourBarExamples()) names += (names.empty() ? "" : ", ") + e.name;
      return kinematics::Error{kinematics::ErrorCode::InvalidValue, "--example",
                               "--example: no example named '" + *inv.example + "' (available: " + names + ")"};
    }
    r.lengths = r.example->lengths;
    r.lengthUnit = r.example->lengthUnit;
    r.branch = r.example->branch;
  } else {
    r.lengths = *inv.fourBar;
    r.lengthUnit = inv.lengthUnit;
  }
  if (inv.branch) r.branch = *inv.branch;
  return r;
}

} // namespace linkwright::cli
