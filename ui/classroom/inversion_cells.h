#pragma once
// What the Inversions window shows for a design (issue 21, the classroom): for a four-bar or a
// slider-crank, its four inversions from the core (kinematics/analysis/inversions.h), each as a
// cell: which link is grounded, the textbook class, which link is driven, and a design to
// animate, or the core's note when the model cannot build that inversion. The cells keep the
// physical links recognisable: a moving link keeps the colour it has in the designer (the
// original frame, which moves in three of the four, takes the palette's fourth colour) and a
// four-bar's joints keep their names. Any other linkage has no cells, only the reason.

#include "kinematics/design/design.h"

#include <QColor>
#include <QString>

#include <optional>
#include <vector>

namespace linkwright::ui {

/// One inversion, ready to show.
struct InversionCell {
  QString title;      ///< "Ground: crank"
  QString className;  ///< the core's textbook name: "double-crank (drag link)"
  QString detail;     ///< which link is driven and whether it turns fully
  /// The inversion to animate (ω as the source design's, a full turn on its grid); none when
  /// the core cannot build it.
  std::optional<kinematics::Design> design;
  QString note;                    ///< why there is no design (the core's note)
  std::vector<QColor> linkColors;  ///< per link of design's mechanism, its physical link's colour
};

/// The inversions of a design, or why it has none.
struct InversionSet {
  QString heading;                   ///< the chain and its lengths: "Four-bar chain frame 100, crank 40, … mm"
  std::vector<InversionCell> cells;  ///< four, grounding frame, crank, coupler (rod), rocker (slider)
  QString unavailable;               ///< non-empty when there are no cells: why
};

/// The inversions of `design`'s four-bar or slider-crank.
InversionSet inversionSet(const kinematics::Design& design);

/// Why `design` has no inversions to show (it is neither a four-bar nor a slider-crank), or
/// nullopt when it has.
std::optional<QString> inversionsUnavailable(const kinematics::Design& design);

}  // namespace linkwright::ui
