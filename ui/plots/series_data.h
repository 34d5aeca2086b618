#pragma once
// Turns sweep columns into plot points: x = the time or the crank angle (plot_x_axis.h), y = one
// quantity, angles in the plot's angle unit (lengths in the mechanism's). Samples that carry no value are left out and break the line into runs, so a
// curve never bridges a range the linkage cannot reach: positions exist where the sample is
// assembled, rates (ω, α) only where it is ok (the sweep stores placeholder zeros at toggle
// and unassembled samples, which must never be plotted). The ratios (velocity ratio, mechanical
// advantage) come from the sweep's AdvantageSeries, where Finite; the advantage also breaks
// where it changes sign, which it does only through infinity (the output at rest).

#include "ui/plots/angle_unit.h"
#include "ui/plots/plot_quantity.h"
#include "ui/plots/plot_x_axis.h"

#include "kinematics/analysis/advantage_sweep.h"
#include "kinematics/solve/sweep.h"

#include <QList>
#include <QPointF>

namespace linkwright::ui {

/// The points of one quantity, split into runs of consecutive plottable samples.
struct SeriesRuns {
  QList<QList<QPointF>> runs;  ///< each run in sweep order; no run is empty
  double minY = 0.0;           ///< over all runs; meaningless when there are no points
  double maxY = 0.0;

  qsizetype pointCount() const;
  bool empty() const { return runs.isEmpty(); }
};

/// True if the sweep holds `quantity` at `sample` (assembled for angles, ok for ω and α, and
/// the column computed at all; a ratio Finite in `ratios`, its series of the sweep).
bool hasValue(const kinematics::SweepResult& sweep, PlotQuantity quantity, std::size_t sample,
              const kinematics::AdvantageSeries* ratios = nullptr);

/// Fills `out` with the plottable samples of `quantity`, x from `x` (a crank angle by default).
/// Reuses `out`'s lists: one allocation per run, none per point. No runs if the sweep did not
/// compute the column (or, for a ratio, `ratios` is null or not of this sweep).
void buildSeriesRuns(const kinematics::SweepResult& sweep, PlotQuantity quantity, AngleUnit unit, SeriesRuns& out,
                     const XSource& x = {}, const kinematics::AdvantageSeries* ratios = nullptr);

}  // namespace linkwright::ui
