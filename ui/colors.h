#pragma once
// Every colour the designer draws with, in one table per theme. Links, sliders and transmission
// angles have one colour each, shared by the canvas and the plots so that a link is the same
// colour in the drawing and on every chart: link 0 is the crank (orange), 1 the coupler (blue),
// 2 the rocker (green), as in a four-bar; further links (six-bars, quick returns) take the
// colours after them. Joint-force curves take a palette distinct from the links'.
//
// Two themes: Normal, and HighContrast for a projector (View ▸ High contrast, --high-contrast):
// black text and white backgrounds on the canvas and the charts, link colours after the
// Okabe–Ito palette darkened until each has a contrast ratio of at least 4.5:1 against white
// (WCAG 2) and the first three (crank, coupler, rocker) differ in lightness as well as hue, so
// they stay apart for colour-blind viewers; thicker grid axes, opaque label boxes.
//
// The theme is one process-wide setting, like QApplication::palette(): a look, not model state.
// MainWindow::setHighContrast sets it and then has the canvas and the charts redraw and take
// their colours anew; everything else reads colors() when it draws.

#include <QColor>

#include <array>
#include <cstddef>
#include <optional>

namespace linkwright::ui {

enum class Theme { Normal, HighContrast };

/// A chart's frame and text; the Normal theme keeps Qt Charts' own (chart_palette.h).
struct ChartColors {
  QColor background;
  QColor text;      ///< title, axis labels and titles, legend
  QColor axisLine;  ///< the axes' own lines
  QColor grid;
};

struct Palette {
  // Shared by the canvas and the plots.
  std::array<QColor, 8> links;
  std::array<QColor, 3> sliders;
  std::array<QColor, 3> transmissions;
  std::array<QColor, 8> jointForces;

  // The canvas.
  QColor canvasBackground;
  QColor couplerPoint;
  int bodyFillAlpha;
  QColor frame;
  QColor pinOutline;
  QColor pinFill;
  QColor groundFill;
  QColor hot;
  QColor velocity;
  QColor acceleration;
  QColor feasible;
  QColor infeasible;
  QColor infeasibleFill;
  QColor label;
  QColor labelBox;
  QColor refusal;
  QColor grid;
  QColor gridAxis;
  double gridAxisWidthPx;  ///< the grid's x = 0 and y = 0 lines, at presentation scale 1
  QColor gridLabel;

  // The classroom: instant centres on the canvas, the polygons' arrows by kind of term.
  QColor centre;          ///< the centres, their labels and the fixed centrode
  QColor kennedyLine;     ///< the lines through three centres
  QColor movingCentrode;  ///< the coupler's centrode, carried with it
  /// Per kinematics::VectorTerm, in its order: absolute, relative, normal, tangential,
  /// sliding, Coriolis.
  std::array<QColor, 6> polygonTerms;

  // The plots.
  std::optional<ChartColors> chart;  ///< nullopt: Qt Charts' light theme as it comes
  QColor crankCursor;
  QColor limitLine;
  QColor limitPoint;
  // Another tool's rows over the plots (File ▸ Compare…): hollow in the curve's colour where
  // they agree, filled red where they are beyond the tolerance, as the dialog's rows are
  // highlighted.
  QColor comparedRowFill;
  QColor flaggedRow;
  QColor flaggedRowBackground;

  // The panels and the message banner.
  QColor grashofCrankBadge;   ///< the crank turns fully
  QColor grashofRockerBadge;  ///< it does not
  QColor linkageBadge;
  QColor errorBanner;
  QColor errorBannerBorder;
  QColor infoBanner;
  QColor infoBannerBorder;
};

/// The table of `theme`.
const Palette& paletteOf(Theme theme);
/// The theme drawn with now (Normal at start).
Theme theme();
/// Switches the theme; the caller has the views redraw (MainWindow::setHighContrast).
void setTheme(Theme theme);
/// The current theme's table.
inline const Palette& colors() { return paletteOf(theme()); }

/// The colour of moving link `index` (Mechanism::links order).
inline QColor linkColor(std::size_t index) { return colors().links[index % colors().links.size()]; }

/// The colour of a slider's block and of its position curves (`ordinal`: 0 for the first slider).
inline QColor sliderColor(std::size_t ordinal) { return colors().sliders[ordinal % colors().sliders.size()]; }

/// The colour of the transmission angle at the `ordinal`-th dyad joint that has one.
inline QColor transmissionColor(std::size_t ordinal) {
  return colors().transmissions[ordinal % colors().transmissions.size()];
}

/// The colour of the `ordinal`-th joint's force curves.
inline QColor jointForceColor(std::size_t ordinal) {
  return colors().jointForces[ordinal % colors().jointForces.size()];
}

}  // namespace linkwright::ui
