#pragma once
// The canvas's look in one place: pixel sizes at presentation scale 1 and the stacking order
// of the items (its colours are in ui/colors.h). Sizes are in device-independent pixels; items
// multiply them by the view's presentation scale (2 for a projector).

#include "ui/colors.h"

namespace linkwright::ui::canvas {

inline constexpr double kLinkWidthPx = 6.0;
inline constexpr double kFrameWidthPx = 1.0;
inline constexpr double kPathWidthPx = 1.5;
inline constexpr double kOutlineWidthPx = 1.5;
inline constexpr double kPinRadiusPx = 5.0;
inline constexpr double kDotRadiusPx = 4.5;
inline constexpr double kHotRadiusPx = 11.0;
inline constexpr double kPickRadiusPx = 12.0;
inline constexpr double kArrowWidthPx = 2.0;
inline constexpr double kArrowHeadPx = 10.0;
inline constexpr double kRangeArcWidthPx = 10.0;
inline constexpr double kLabelPointSize = 9.0;

/// Stacking order, back to front.
namespace z {
inline constexpr double kFrame = 0;
inline constexpr double kSlideway = 0.5;
inline constexpr double kRange = 1;
inline constexpr double kPath = 2;
inline constexpr double kCouplerTriangle = 3;
inline constexpr double kLinks = 4;
inline constexpr double kGround = 5;
inline constexpr double kBlocks = 5.5;
inline constexpr double kPins = 6;
inline constexpr double kArrows = 7;
inline constexpr double kLabels = 8;
inline constexpr double kMessage = 9;
}  // namespace z

}  // namespace linkwright::ui::canvas
