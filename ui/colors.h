#pragma once
// Every colour the designer draws with, in one table. Links, sliders and transmission angles
// have one colour each, shared by the canvas and the plots so that a link is the same colour
// in the drawing and on every chart: link 0 is the crank (orange), 1 the coupler (blue), 2 the
// rocker (green), as in a four-bar; further links (six-bars, quick returns) take the colours
// after them. Joint-force curves take a palette distinct from the links'.

#include <QColor>

#include <array>
#include <cstddef>

namespace linkwright::ui {

inline constexpr std::array<QColor, 8> kLinkPalette{
    QColor{230, 85, 13},  QColor{49, 130, 189}, QColor{49, 163, 84}, QColor{166, 118, 29},
    QColor{23, 150, 170}, QColor{188, 80, 144}, QColor{90, 90, 160}, QColor{120, 120, 40},
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

/// The colour of the `ordinal`-th joint's force curves.
inline QColor jointForceColor(std::size_t ordinal) {
  static constexpr std::array<QColor, 8> palette{
      QColor{31, 119, 180}, QColor{214, 39, 40},  QColor{44, 160, 44}, QColor{148, 103, 189},
      QColor{255, 127, 14}, QColor{23, 190, 207}, QColor{140, 86, 75}, QColor{127, 127, 127},
  };
  return palette[ordinal % palette.size()];
}

// The canvas.
inline constexpr QColor kCrankColor = kLinkPalette[0];
inline constexpr QColor kCouplerColor = kLinkPalette[1];
inline constexpr QColor kRockerColor = kLinkPalette[2];
inline constexpr QColor kCouplerPointColor{117, 107, 177};
inline constexpr int kBodyFillAlpha = 45;
inline constexpr QColor kFrameColor{90, 90, 90};
inline constexpr QColor kPinOutlineColor{40, 40, 40};
inline constexpr QColor kPinFillColor{255, 255, 255};
inline constexpr QColor kGroundFillColor{225, 225, 225};
inline constexpr QColor kHotColor{255, 200, 0, 110};
inline constexpr QColor kVelocityColor{197, 27, 125};
inline constexpr QColor kAccelerationColor{0, 128, 128};
inline constexpr QColor kFeasibleColor{140, 200, 90, 130};
inline constexpr QColor kInfeasibleColor{150, 150, 150};
inline constexpr QColor kInfeasibleFillColor{150, 150, 150, 40};
inline constexpr QColor kLabelColor{50, 50, 50};
inline constexpr QColor kLabelBoxColor{255, 255, 255, 235};
inline constexpr QColor kRefusalColor{190, 20, 20};
inline constexpr QColor kGridColor{232, 232, 232};
inline constexpr QColor kGridAxisColor{200, 200, 200};
inline constexpr QColor kGridLabelColor{150, 150, 150};

// The plots.
inline constexpr QColor kCrankCursorColor{0xc0, 0x20, 0x20};
inline constexpr QColor kLimitLineColor{0x55, 0x55, 0x55};
inline constexpr QColor kLimitPointColor{0, 0, 0};
// Another tool's rows over the plots (File ▸ Compare…): hollow in the curve's colour where they
// agree, filled red where they are beyond the tolerance, as the dialog's rows are highlighted.
inline constexpr QColor kComparedRowFillColor{255, 255, 255};
inline constexpr QColor kFlaggedRowColor{0xd1, 0x34, 0x38};
inline constexpr QColor kFlaggedRowBackground{255, 205, 200};

// The panels and the message banner.
inline constexpr QColor kGrashofCrankBadgeColor{0x1b, 0x7f, 0x3b};   ///< the crank turns fully
inline constexpr QColor kGrashofRockerBadgeColor{0xa1, 0x5c, 0x00};  ///< it does not
inline constexpr QColor kLinkageBadgeColor{0x3b, 0x5b, 0x92};
inline constexpr QColor kErrorBannerColor{0xfd, 0xe7, 0xe9};
inline constexpr QColor kErrorBannerBorderColor{0xd1, 0x34, 0x38};
inline constexpr QColor kInfoBannerColor{0xe7, 0xf0, 0xfd};
inline constexpr QColor kInfoBannerBorderColor{0x2b, 0x6c, 0xb0};

}  // namespace linkwright::ui
