#include "ui/colors.h"

namespace linkwright::ui {

namespace {

const Palette kNormal{
    .links = {QColor{230, 85, 13}, QColor{49, 130, 189}, QColor{49, 163, 84}, QColor{166, 118, 29},
              QColor{23, 150, 170}, QColor{188, 80, 144}, QColor{90, 90, 160}, QColor{120, 120, 40}},
    .sliders = {QColor{117, 107, 177}, QColor{214, 39, 40}, QColor{60, 60, 60}},
    .transmissions = {QColor{140, 86, 75}, QColor{110, 110, 110}, QColor{200, 140, 60}},
    .jointForces = {QColor{31, 119, 180}, QColor{214, 39, 40}, QColor{44, 160, 44}, QColor{148, 103, 189},
                    QColor{255, 127, 14}, QColor{23, 190, 207}, QColor{140, 86, 75}, QColor{127, 127, 127}},
    .canvasBackground = QColor{255, 255, 255},
    .couplerPoint = QColor{117, 107, 177},
    .bodyFillAlpha = 45,
    .frame = QColor{90, 90, 90},
    .pinOutline = QColor{40, 40, 40},
    .pinFill = QColor{255, 255, 255},
    .groundFill = QColor{225, 225, 225},
    .hot = QColor{255, 200, 0, 110},
    .velocity = QColor{197, 27, 125},
    .acceleration = QColor{0, 128, 128},
    .feasible = QColor{140, 200, 90, 130},
    .infeasible = QColor{150, 150, 150},
    .infeasibleFill = QColor{150, 150, 150, 40},
    .label = QColor{50, 50, 50},
    .labelBox = QColor{255, 255, 255, 235},
    .refusal = QColor{190, 20, 20},
    .grid = QColor{232, 232, 232},
    .gridAxis = QColor{200, 200, 200},
    .gridAxisWidthPx = 1.0,
    .gridLabel = QColor{150, 150, 150},
    .centre = QColor{0, 121, 107},
    .kennedyLine = QColor{110, 110, 110},
    .movingCentrode = QColor{216, 108, 0},
    .polygonTerms = {QColor{40, 40, 40}, QColor{49, 130, 189}, QColor{230, 85, 13}, QColor{49, 163, 84},
                     QColor{117, 107, 177}, QColor{214, 39, 40}},
    .chart = std::nullopt,
    .crankCursor = QColor{0xc0, 0x20, 0x20},
    .limitLine = QColor{0x55, 0x55, 0x55},
    .limitPoint = QColor{0, 0, 0},
    .comparedRowFill = QColor{255, 255, 255},
    .flaggedRow = QColor{0xd1, 0x34, 0x38},
    .flaggedRowBackground = QColor{255, 205, 200},
    .grashofCrankBadge = QColor{0x1b, 0x7f, 0x3b},
    .grashofRockerBadge = QColor{0xa1, 0x5c, 0x00},
    .linkageBadge = QColor{0x3b, 0x5b, 0x92},
    .errorBanner = QColor{0xfd, 0xe7, 0xe9},
    .errorBannerBorder = QColor{0xd1, 0x34, 0x38},
    .infoBanner = QColor{0xe7, 0xf0, 0xfd},
    .infoBannerBorder = QColor{0x2b, 0x6c, 0xb0},
};

// Link colours: Okabe–Ito's vermillion, blue, bluish green, orange, a violet, reddish purple,
// near-black and a dark cyan, darkened to at least 4.5:1 against white. The crank, coupler and
// rocker are also a light, a dark and a light one (CIE L* 46, 28, 47), so that simulated
// protanopia, deuteranopia and tritanopia (Machado 2009) still leave them ΔE 25 or more apart.
const Palette kHighContrast{
    .links = {QColor{0xc4, 0x41, 0x00}, QColor{0x00, 0x3f, 0x88}, QColor{0x00, 0x80, 0x60}, QColor{0x94, 0x63, 0x00},
              QColor{0x80, 0x48, 0xb8}, QColor{0xb8, 0x28, 0x7a}, QColor{0x2a, 0x2a, 0x2a}, QColor{0x00, 0x70, 0x8a}},
    .sliders = {QColor{0x5e, 0x3c, 0x99}, QColor{0xb2, 0x18, 0x2b}, QColor{0x1b, 0x1b, 0x1b}},
    .transmissions = {QColor{0x7a, 0x4a, 0x3a}, QColor{0x4d, 0x4d, 0x4d}, QColor{0x8a, 0x5a, 0x00}},
    .jointForces = {QColor{0x00, 0x3f, 0x88}, QColor{0xb2, 0x18, 0x2b}, QColor{0x0b, 0x6f, 0x3f},
                    QColor{0x6a, 0x3d, 0x9a}, QColor{0x9a, 0x5a, 0x00}, QColor{0x00, 0x60, 0x7a},
                    QColor{0x7a, 0x4a, 0x3a}, QColor{0x4d, 0x4d, 0x4d}},
    .canvasBackground = QColor{255, 255, 255},
    .couplerPoint = QColor{0x5e, 0x3c, 0x99},
    .bodyFillAlpha = 40,
    .frame = QColor{0, 0, 0},
    .pinOutline = QColor{0, 0, 0},
    .pinFill = QColor{255, 255, 255},
    .groundFill = QColor{200, 200, 200},
    .hot = QColor{255, 190, 0, 150},
    .velocity = QColor{0x9c, 0x1f, 0x6e},
    .acceleration = QColor{0x00, 0x60, 0x6a},
    .feasible = QColor{60, 150, 40, 150},
    .infeasible = QColor{90, 90, 90},
    .infeasibleFill = QColor{90, 90, 90, 40},
    .label = QColor{0, 0, 0},
    .labelBox = QColor{255, 255, 255},
    .refusal = QColor{0xb0, 0x00, 0x20},
    .grid = QColor{215, 215, 215},
    .gridAxis = QColor{0, 0, 0},
    .gridAxisWidthPx = 2.0,
    .gridLabel = QColor{0, 0, 0},
    .centre = QColor{0x00, 0x5f, 0x55},
    .kennedyLine = QColor{0x40, 0x40, 0x40},
    .movingCentrode = QColor{0x9a, 0x4a, 0x00},
    // The links' dark tones, so a relative velocity reads as the coupler's blue.
    .polygonTerms = {QColor{0, 0, 0}, QColor{0x00, 0x3f, 0x88}, QColor{0xc4, 0x41, 0x00}, QColor{0x00, 0x80, 0x60},
                     QColor{0x5e, 0x3c, 0x99}, QColor{0xb2, 0x18, 0x2b}},
    .chart = ChartColors{QColor{255, 255, 255}, QColor{0, 0, 0}, QColor{0, 0, 0}, QColor{190, 190, 190}},
    .crankCursor = QColor{0xc0, 0x20, 0x20},  // as Normal: the charts keep the cursor they were made with
    .limitLine = QColor{0x30, 0x30, 0x30},
    .limitPoint = QColor{0, 0, 0},
    .comparedRowFill = QColor{255, 255, 255},
    .flaggedRow = QColor{0xb0, 0x00, 0x20},
    .flaggedRowBackground = QColor{255, 205, 200},
    .grashofCrankBadge = QColor{0x0b, 0x5f, 0x2b},
    .grashofRockerBadge = QColor{0x80, 0x48, 0x00},
    .linkageBadge = QColor{0x1b, 0x3b, 0x72},
    .errorBanner = QColor{0xfd, 0xe7, 0xe9},
    .errorBannerBorder = QColor{0xb0, 0x00, 0x20},
    .infoBanner = QColor{0xe7, 0xf0, 0xfd},
    .infoBannerBorder = QColor{0x00, 0x3f, 0x88},
};

// The one process-wide look (see colors.h): MainWindow sets it, the views read it.
Theme g_theme = Theme::Normal;

}  // namespace

const Palette& paletteOf(Theme theme) { return theme == Theme::HighContrast ? kHighContrast : kNormal; }

Theme theme() { return g_theme; }

void setTheme(Theme theme) { g_theme = theme; }

}  // namespace linkwright::ui
