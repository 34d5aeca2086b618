#pragma once
// What lays a chart out besides its size: the room its axes' labels and titles take
// (plot_axes.h) and which curves the legend lists. A chart whose inputs are unchanged keeps
// its plot area, so a drag that only moves the curves, or moves an axis to labels of the same
// width, skips the alignment of the plot areas.

#include <QMargins>

#include <utility>
#include <vector>

namespace linkwright::ui {

struct ChartLayoutInputs {
  QMargins axesRoom;
  std::vector<bool> legend;  ///< per curve: listed or not
  bool operator==(const ChartLayoutInputs&) const = default;

  /// Stores this into `last`; true if it differs from what `last` held.
  bool replace(ChartLayoutInputs& last) {
    if (*this == last) return false;
    last = std::move(*this);
    return true;
  }
};

}  // namespace linkwright::ui
