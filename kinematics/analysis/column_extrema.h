#pragma once
// The refined extremes of one tabulated column (sweep_columns.h) over a sweep: the samples
// bracket each extreme and extrema.h's search refines it on poses solved between them.
// `linkwright-cli extremes` and the lab report (kinematics/report/) both print these, so the
// two hold the same numbers. A column is scanned window by window (sweepInWindows), so the
// extremes of 10⁷ samples need no more memory than those of 361.

#include "kinematics/analysis/extrema.h"
#include "kinematics/solve/sweep_columns.h"

#include <optional>

namespace linkwright::kinematics {

/// A column's samples gathered window by window; rates only where the samples are ok,
/// positions where they assembled.
class ColumnExtremaScan {
public:
  explicit ColumnExtremaScan(SweepColumn column) : m_column(std::move(column)) {}
  /// Samples [first, first + part.size()) of the sweep, in order.
  void add(const SweepResult& part, std::size_t first);
  /// The refined extremes in the column's unit over the samples added (a sweep of
  /// `mechanism` over `spec`); nullopt where the column had no value at all.
  std::optional<Extrema> refine(const Mechanism& mechanism, const SweepSpec& spec) const;
  const SweepColumn& column() const { return m_column; }

private:
  SweepColumn m_column;
  SampledExtrema m_sampled;
  double m_near = 0.0;  // the last value: the search's poses unwrap angles next to it
};

/// The extremes of `column` over the whole `sweep` (a sweep of `mechanism` over `spec`
/// holding the column's quantity), as above.
std::optional<Extrema> columnExtrema(const Mechanism& mechanism, const SweepSpec& spec, const SweepResult& sweep,
                                     const SweepColumn& column);

}  // namespace linkwright::kinematics
