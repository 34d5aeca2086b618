#pragma once
// What lays a chart out besides its size: the axes' ranges and titles and which curves the
// legend lists. A chart whose inputs are unchanged keeps its plot area, so a drag that only
// moves the curves (most frames) skips the layout and the alignment of the plot areas.

#include "ui/plots/axis_range.h"

#include <QString>

#include <utility>
#include <vector>

namespace linkwright::ui {

struct ChartLayoutInputs {
  AxisRange x;
  AxisRange y;
  QString xTitle;
  QString yTitle;
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
