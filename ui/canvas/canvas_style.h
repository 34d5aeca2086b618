#pragma once
// The canvas's look in one place: colours, pixel sizes at presentation scale 1 and the
// stacking order of the items. Sizes are in device-independent pixels; items multiply them by
// the view's presentation scale (2 for a projector).

#include <QColor>

namespace linkwright::ui::canvas {

inline constexpr QColor kCrankColor{230, 85, 13};
inline constexpr QColor kCouplerColor{49, 130, 189};
inline constexpr QColor kRockerColor{49, 163, 84};
inline constexpr QColor kCouplerPointColor{117, 107, 177};
inline constexpr int kBodyFillAlpha = 45;
inline constexpr QColor kFrameColor{90, 90, 90};
inline constexpr QColor kPinOutlineColor{40, 40, 40};
inline constexpr QColor kPinFillColor{255, 255, 255};
inline constexpr QColor kHotColor{255, 200, 0, 110};
inline constexpr QColor kVelocityColor{197, 27, 125};
inline constexpr QColor kAccelerationColor{0, 128, 128};
inline constexpr QColor kFeasibleColor{140, 200, 90, 130};
inline constexpr QColor kInfeasibleColor{150, 150, 150};
inline constexpr QColor kInfeasibleFillColor{150, 150, 150, 40};
inline constexpr QColor kLabelColor{50, 50, 50};
inline constexpr QColor kRefusalColor{190, 20, 20};
inline constexpr QColor kGridColor{232, 232, 232};
inline constexpr QColor kGridAxisColor{200, 200, 200};
inline constexpr QColor kGridLabelColor{150, 150, 150};

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
} // namespace z

} // namespace linkwright::ui::canvas
