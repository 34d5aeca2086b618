#pragma once
// The options only `compare` takes (--map, --offset, --tolerance) and its bare arguments
// (the document, then the other tool's table), parsed into the Invocation; errors name the
// option and what is accepted.

#include "app/cli/arguments.h"

#include "kinematics/model/result.h"

#include <optional>
#include <string>

namespace linkwright::cli {

/// Applies --map, --offset or --tolerance; nullopt also for an option that is not compare's.
std::optional<kinematics::Error> applyCompareOption(Invocation& invocation, const std::string& option,
                                                    const std::string& value);

/// A bare argument of compare: the first is the table; a second makes the first the document.
std::optional<kinematics::Error> takeCompareArgument(Invocation& invocation, const std::string& argument);

/// What compare needs besides the mechanism: the table and --map.
std::optional<kinematics::Error> checkCompare(const Invocation& invocation);

}  // namespace linkwright::cli
