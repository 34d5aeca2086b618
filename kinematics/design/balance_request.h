#pragma once
// `balance` as one request for every front end: counterweights that balance a design's shaking
// force (kinematics/dynamics/force_balance.h), or the spring between two given points, or from
// a point searched on a link to one searched on the frame, that makes the RMS driving torque
// least (spring_balance.h, spring_search.h). The request's combinations are checked here, the
// refusal naming the fields as the front end spells them (--fraction, fraction); the run gives
// the balanced design (the one linkwright-cli balance writes) and what the balance gains over a
// turn. linkwright-cli balance and Python's Linkage.balance fill it alike.

#include "kinematics/design/design.h"
#include "kinematics/dynamics/force_balance.h"
#include "kinematics/dynamics/machine_duty.h"
#include "kinematics/dynamics/spring_search.h"
#include "kinematics/model/request_field.h"

#include <optional>
#include <string>
#include <utility>

namespace linkwright::kinematics {

/// What a balance is asked for: counterweights (fraction, radius) or one spring.
struct BalanceRequest {
  std::optional<double> fraction;  ///< slider-crank: the share of the reciprocating mass, [0, 1]
  std::optional<double> radius;    ///< each counterweight's distance in lengths of its link, [0.1, 10]
  /// The spring's two ends, each "LINK:POINT" (a point on that link's body) or "POINT" (a ground point).
  std::optional<std::pair<std::string, std::string>> spring;
  std::optional<std::string> springSearch;  ///< the link the searched spring starts on
  FrontEnd frontEnd = FrontEnd::Cli;        ///< who asked: the spelling of the fields in refusals
};

/// "crank:B" as the point B on crank's body; "S" alone as the ground point S (the frame).
SpringEnd springEndOf(const std::string& text);

/// Error unless the request is one balance: a spring (given or searched) takes neither fraction
/// nor radius, and spring and spring_search are not both given.
std::optional<Error> checkBalanceRequest(const BalanceRequest& request);

enum class BalanceMethod { Counterweights, Spring, SpringSearch };

/// A balance made, and the design with it.
struct BalanceRun {
  BalanceMethod method = BalanceMethod::Counterweights;
  Design balanced;                      ///< the design with the counterweights or the spring
  std::optional<ForceBalance> weights;  ///< Counterweights: what was added
  /// Counterweights: one turn's figures before and after, each converged as `machine`'s are
  /// (machine_request.h: within kMachineTolerance, on the grid the run chose); `noTurn` says
  /// why there is no turn.
  std::optional<MachineDuty> before, after;
  std::size_t turnSamples = 0;  ///< of the finer of the two turns read, both ends counted
  bool converged = true;        ///< both turns' figures within the tolerance
  std::string noTurn;
  std::optional<SpringBalance> spring;       ///< Spring and SpringSearch: the spring found
  std::optional<SpringPlacement> placement;  ///< SpringSearch: where its ends were put
};

/// The balance the request asks for on `design`. Errors: checkBalanceRequest's, then the
/// balance's own, their field the request's as the front end spells it and its message
/// prefixed with it where the CLI's was ("--spring: …", "fraction: …").
Result<BalanceRun> runBalance(const Design& design, const BalanceRequest& request);

}  // namespace linkwright::kinematics
