#include "app/cli/commands.h"

#include "kinematics/design/sweep_grid.h"
#include "kinematics/model/driver.h"
#include "kinematics/model/validate.h"

namespace linkwright::cli {
namespace {

using kinematics::Error;

// The grid fields as the options spell them.
const kinematics::GridFieldNames kOptionNames{"--rpm",      "--omega",     "--alpha",     "--from",      "--to",
                                              "--step",     "--samples",   "--law",       "--ramp-time", "--rise",
                                              "--duration", "--law-table", "--from-time", "--to-time",   "--step-time"};

kinematics::SweepGridRequest gridRequest(const Invocation& inv) {
  return {inv.rpm, inv.omega, inv.alpha, inv.fromDeg, inv.toDeg, inv.stepDeg, inv.samples};
}

// The core names a field by its neutral key; the CLI's errors name the option.
Error spelled(Error e) {
  using F = kinematics::GridField;
  for (const auto field : {F::Rpm, F::Omega, F::Alpha, F::Start, F::Stop, F::Step, F::Samples, F::Law, F::RampTime,
                           F::Rise, F::Duration, F::LawTable, F::FromTime, F::ToTime, F::StepTime})
    if (e.field == kinematics::gridFieldKey(field)) {
      e.field = kOptionNames[field];
      break;
    }
  return e;
}

}  // namespace

// The input domain (kinematics/model/validate.h, driver.h), named by the option the user
// typed: --from, --to and --step in degrees for a crank, in the length unit for a linear driver.
std::optional<Error> checkDriveOptions(const Invocation& inv, kinematics::InputKind kind) {
  if (auto e = kinematics::checkGridRequest(gridRequest(inv), kind, kOptionNames)) return spelled(*e);
  return std::nullopt;
}

const kinematics::GridFieldNames& gridOptionNames() { return kOptionNames; }

std::optional<Error> checkAtOption(const Invocation& inv, const GridDefaults& d) {
  using namespace kinematics;
  const InputDomain domain = inputDomain(d.input);
  const bool angle = d.input == InputKind::Angle;
  // On a time base --at is an instant (s); else the input, in degrees or the length unit.
  const double max = d.time ? 1e6 : angle ? kMaxAngleDeg : domain.position;
  const char* unit = d.time ? "s" : angle ? "degrees" : domain.positionUnit;
  for (const double at : inv.atDeg)
    if (auto e = checkMagnitude(at, "--at", max, unit)) return e;
  return std::nullopt;
}

// The grid rule is the core's (kinematics/design/sweep_grid.h), --law's time base included.
kinematics::Result<kinematics::SweepSpec> sweepSpecFor(const Invocation& inv, const GridDefaults& d) {
  auto request = gridRequest(inv);
  if (inv.law) {
    auto withLaw = lawRequest(inv, d, std::move(request));
    if (!withLaw) return withLaw.error();
    request = std::move(withLaw).value();
  }
  auto spec = kinematics::sweepGridSpec(request, d, kOptionNames);
  if (!spec) return spelled(spec.error());
  return spec;
}

}  // namespace linkwright::cli
