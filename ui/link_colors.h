#pragma once
// One colour per moving link, per slider and per transmission angle, shared by the canvas and
// the plots so that a link is the same colour in the drawing and on every chart. Link 0 is
// the crank (orange), 1 the coupler (blue), 2 the rocker (green), as in a four-bar; further
// links (six-bars, quick returns) take the colours after them.

#include <QColor>

#include <array>
#include <cstddef>

namespace linkwright::ui {

inline constexpr std::array<QColor, 8> kLinkPalette{
    QColor{230, 85, 13},   QColor{49, 130, 189}, QColor{49, 163, 84},  QColor{166, 118, 29},
    QColor{23, 150, 170},  QColor{188, 80, 144}, QColor{90, 90, 160},  QColor{120, 120, 40},
};

/// The colour of moving link `index` (Mechanism::links order).
inline QColor linkColor(std::size_t index) { return kLinkPalette[index % kLinkPalette.size()]; }

/// The colour of a slider's block and of its position curves (`ordinal`: 0 for the first slider).
inline QColor sliderColor(std::size_t ordinal) {
  static constexpr std::array<QColor, 3> palette{QColor{117, 107, 177}, QColor{214, 39, 40}, QColor{60, 60, 60}};
  return palette[ordinal % palette.size()];
}

/// The colour of the transmission angle at the `ordinal`-th dyad joint that has one.
inline QColor transmissionColor(std::size_t ordinal) {
  static constexpr std::array<QColor, 3> palette{QColor{140, 86, 75}, QColor{110, 110, 110}, QColor{200, 140, 60}};
  return palette[ordinal % palette.size()];
}

} // namespace linkwright::ui
