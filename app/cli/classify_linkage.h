#pragma once
// classify for any linkage other than a plain four-bar (see classify_linkage.cpp).

#include "app/cli/exit_codes.h"

#include "kinematics/model/mechanism.h"

#include <iosfwd>
#include <string>

namespace linkwright::cli {

/// Prints mobility, the crank ranges that do not assemble, and every dyad's transmission
/// angle extremes (text, or JSON with `json`). NotAssemblable if it assembles nowhere.
ExitCode classifyLinkage(const std::string& kind, const kinematics::Mechanism& mechanism, bool json, std::ostream& out,
                         std::ostream& err);

}  // namespace linkwright::cli
