#include "kinematics/design/balance_request.h"

#include "kinematics/design/sweep_grid.h"
#include "kinematics/dynamics/machine_request.h"
#include "kinematics/dynamics/spring_balance.h"

#include <algorithm>
#include <tuple>

namespace linkwright::kinematics {
namespace {

Error prefixed(Error e, const std::string& key, FrontEnd frontEnd) {
  const std::string name = fieldName(key, frontEnd);
  e.message = name + ": " + e.message;
  e.field = name;
  return e;
}

Result<BalanceRun> bySpring(const Design& design, const BalanceRequest& r) {
  const auto balance = balanceBySpring(design.mechanism, design.dynamics, designTurn(design),
                                       springEndOf(r.spring->first), springEndOf(r.spring->second));
  if (!balance) return prefixed(balance.error(), "spring", r.frontEnd);
  BalanceRun run;
  run.method = BalanceMethod::Spring;
  run.balanced = design;
  run.balanced.dynamics = balance->balanced;
  run.spring = *balance;
  return run;
}

Result<BalanceRun> bySearchedSpring(const Design& design, const BalanceRequest& r) {
  auto found = searchSpringBalance(design.mechanism, design.dynamics, designTurn(design), *r.springSearch);
  if (!found) return prefixed(found.error(), "spring_search", r.frontEnd);
  BalanceRun run;
  run.method = BalanceMethod::SpringSearch;
  run.balanced = design;
  run.balanced.mechanism = found->mechanism;
  run.balanced.dynamics = found->balance.balanced;
  run.spring = found->balance;
  run.placement = std::move(*found);
  return run;
}

}  // namespace

SpringEnd springEndOf(const std::string& text) {
  const auto colon = text.find(':');
  if (colon == std::string::npos) return {"", text};
  return {text.substr(0, colon), text.substr(colon + 1)};
}

std::optional<Error> checkBalanceRequest(const BalanceRequest& r) {
  const char* spring = r.spring ? "spring" : r.springSearch ? "spring_search" : nullptr;
  if (spring == nullptr) return std::nullopt;
  for (const auto& [given, key, what] :
       {std::tuple{r.fraction.has_value(), "fraction", "the share of the reciprocating mass"},
        {r.radius.has_value(), "radius", "the counterweights' distance from their pivots"}})
    if (given)
      return Error{ErrorCode::InvalidValue, fieldName(key, r.frontEnd),
                   fieldName(key, r.frontEnd) + " sets " + what + ", and a spring balance (" +
                       fieldName(spring, r.frontEnd) + ") makes no counterweight: give one or the other"};
  if (r.spring && r.springSearch)
    return Error{ErrorCode::InvalidValue, fieldName("spring_search", r.frontEnd),
                 fieldName("spring_search", r.frontEnd) + ": give the spring's ends (" +
                     fieldName("spring", r.frontEnd) + ") or have them searched (" +
                     fieldName("spring_search", r.frontEnd) + "), not both"};
  return std::nullopt;
}

Result<BalanceRun> runBalance(const Design& design, const BalanceRequest& r) {
  if (auto e = checkBalanceRequest(r)) return *e;
  if (r.springSearch) return bySearchedSpring(design, r);
  if (r.spring) return bySpring(design, r);
  BalanceOptions options;
  options.reciprocatingFraction = r.fraction.value_or(options.reciprocatingFraction);
  options.radius = r.radius.value_or(options.radius);
  auto balance = balanceShakingForce(design.mechanism, design.dynamics, options);
  if (!balance) {
    const std::string& field = balance.error().field;
    if (field == "fraction" || field == "radius") return prefixed(balance.error(), field, r.frontEnd);
    return balance.error();
  }
  BalanceRun run;
  run.balanced = design;
  run.balanced.dynamics = balance->balanced;
  // Converged as machine's figures are: on the design's own grid the peaks and RMS were only
  // as good as that grid.
  const MachineDefaults turn = machineDefaultsOf(sweepGridOf(design));
  auto before = runMachine(design.mechanism, design.dynamics, turn, {});
  auto after = runMachine(design.mechanism, run.balanced.dynamics, turn, {});
  if (before && after) {
    run.turnSamples = std::max(before->samples, after->samples);
    run.converged = before->converged && after->converged;
    run.before = std::move(before->duty);
    run.after = std::move(after->duty);
  } else {
    run.noTurn = (before ? after.error() : before.error()).message;
  }
  run.weights = std::move(*balance);
  return run;
}

}  // namespace linkwright::kinematics
