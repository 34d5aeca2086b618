#pragma once
// The refined extremes of one tabulated column (sweep_columns.h) over a sweep: the samples
// bracket each extreme and analysis/extrema.h's search refines it on poses solved between them.
// `linkwright-cli extremes` and the lab report (kinematics/report/) both print these, so the
// two hold the same numbers.

#include "kinematics/analysis/extrema.h"
#include "kinematics/io/sweep_columns.h"

#include <optional>

namespace linkwright::kinematics::io {

/// The extremes of `column` over `sweep` (a sweep of `mechanism` over `spec` holding the
/// column's quantity), in the column's unit; rates are searched only where the samples are
/// ok, positions where they assembled. Nullopt where the column has no value at all.
std::optional<Extrema> columnExtrema(const Mechanism& mechanism, const SweepSpec& spec, const SweepResult& sweep,
                                     const SweepColumn& column);

}  // namespace linkwright::kinematics::io
