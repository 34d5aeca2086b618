#include "app/cli/commands.h"

namespace linkwright::cli {

namespace k = kinematics;

kinematics::Result<ResolvedFourBar> resolveFourBar(const Invocation& inv) {
  ResolvedFourBar r;
  if (inv.example) {
    r.example = k::findFourBarExample(*inv.example);
    if (!r.example) {
      if (const auto other = k::findMechanismExample(*inv.example))
        return k::Error{k::ErrorCode::InvalidValue, "--example",
                        "--example: '" + *inv.example + "' is not a four-bar but a " + other->kind +
                            "; classify works on four-bars and shapers (try analyze or extremes)"};
      std::string names;
      for (const auto& e : k::fourBarExamples()) names += (names.empty() ? "" : ", ") + e.name;
      for (const auto& e : k::mechanismExamples()) names += ", " + e.name;
      return k::Error{k::ErrorCode::InvalidValue, "--example",
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

kinematics::Result<ResolvedMechanism> resolveMechanism(const Invocation& inv) {
  ResolvedMechanism r;
  if (inv.example) {
    if (auto other = k::findMechanismExample(*inv.example)) {
      if (inv.couplerPoint)
        return k::Error{k::ErrorCode::InvalidValue, "--coupler-point", "--coupler-point applies to four-bars, not to " + other->name};
      if (inv.branch)
        return k::Error{k::ErrorCode::InvalidValue, "--branch", "--branch applies to four-bars, not to " + other->name};
      r.mechanism = std::move(other->mechanism);
      r.defaults = {other->omega, 0.0, other->fromDeg, other->toDeg, other->stepDeg};
      return r;
    }
  }
  auto fb = resolveFourBar(inv);
  if (!fb) return fb.error();
  const auto couplerPoint = inv.couplerPoint ? inv.couplerPoint : (fb->example ? fb->example->couplerPoint : std::nullopt);
  auto m = k::makeFourBar(fb->lengths, fb->branch, fb->lengthUnit, couplerPoint);
  if (!m) return m.error();
  r.mechanism = std::move(*m);
  if (const auto& e = fb->example) r.defaults = {e->omega, e->alpha, e->fromDeg, e->toDeg, e->stepDeg};
  r.fourBar = std::move(*fb);
  return r;
}

} // namespace linkwright::cli
