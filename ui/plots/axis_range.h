#pragma once
// Axis ranges for the plots, as plain numbers (applied to QValueAxis by the chart views):
// rounded bounds with a small margin around the data, and the crank-angle axis over the
// design's analysis grid. Also maps a crank angle of any turn into that grid's range.

#include "ui/plots/angle_unit.h"

#include <optional>

#include <utility>
#include <vector>

namespace linkwright::ui {

/// A value axis: bounds on multiples of `step`, `decimals` enough to print the tick labels.
struct AxisRange {
  double min = 0.0;
  double max = 1.0;
  double step = 0.25;
  int tickCount = 5;
  int decimals = 2;
  bool operator==(const AxisRange&) const = default;
};

/// 1, 2, 2.5 or 5 times a power of ten, the smallest such ≥ `raw` (> 0).
double niceStep(double raw);
/// Digits after the decimal point needed to print multiples of `step` exactly (at most 6).
int decimalsFor(double step);

/// A range holding [lo, hi] with a margin of 5 % of the span each side, its bounds rounded out
/// to a nice step, with at most about `maxTicks` ticks. A flat extent (lo == hi) is widened
/// by 10 % of its value (±1 at zero); no data (non-finite or lo > hi) gives [0, 1].
AxisRange niceValueRange(double lo, double hi, int maxTicks = 6);

/// Whether a value axis showing `shown` may stay as it is for data spanning [lo, hi] while
/// they keep changing (a drag): it still holds them and they fill at least half of it.
/// Labels that stay put are easier to follow, and a chart whose axes stay put is not laid out
/// again; the plots return to niceValueRange once the data settle.
bool keepsRange(const AxisRange& shown, double lo, double hi);

/// Whether the data a value axis shows have settled or are still changing frame after frame
/// (a drag: a new sweep came within PlotPanel::kDataSettleMs of the last).
enum class DataFlow { Settled, Changing };

/// The range an axis takes for data spanning [lo, hi] that it no longer keeps (keepsRange).
/// Settled data get niceValueRange. Data that keep changing get room: the data widened by a
/// fifth of their span each side (or a tenth, or a twentieth, where rounding out to a coarser
/// step would leave the data less than half the axis, which keepsRange would not keep), so
/// the next frames of a drag fit it too and the chart is not laid out and repainted whole on
/// each. The panels fit the axis tightly again once the data settle.
AxisRange refittedRange(double lo, double hi, DataFlow flow, int maxTicks = 6);

/// The span of `values` worth showing: their full range, unless a few samples spike far out
/// (rates next to a toggle position grow without bound), in which case the span of the bulk
/// (by default the 5th to 95th percentile: `tail` left out at each end) widened by half its
/// width on each side. Reorders `values`.
std::pair<double, double> robustSpan(std::vector<double>& values, double tail = 0.05);

/// The crank axis: exactly the grid [fromDeg, toDeg] in `unit`, ticks anchored at 0 every
/// `step` (15°, 30°, 45°, 90°, ... or a nice step in rad), about 8 intervals at most.
AxisRange crankAxisRange(double fromDeg, double toDeg, AngleUnit unit);

/// `angleDeg` moved by whole turns into [fromDeg, toDeg] (the smallest such value), or nullopt
/// if no turn of it lies there (a grid shorter than a turn that misses this angle).
std::optional<double> wrapIntoRange(double angleDeg, double fromDeg, double toDeg);

}  // namespace linkwright::ui
