#pragma once
// The GUI's command line: linkwright [FILE] [--example NAME] [--screenshot FILE.png]
// [--image FILE.{png,svg,pdf} [--image-of canvas|plotN]]
// [--animation FILE.{gif,mp4,webm} [--frames N] [--frame-delay MS | --frame-rate FPS]
// [--animation-size WxH]] [--inversions-screenshot FILE.png]
// [--presentation] [--high-contrast] [--forces] [--centres] [--crank-angle DEG] [--plots KEY,…]
// [--compare TABLE.csv [--compare-map MAP]] [--help] [--version].

#include <optional>
#include <string>
#include <vector>

namespace linkwright::app {

struct GuiOptions {
  std::optional<std::string> file;        ///< a document to open
  std::optional<std::string> example;     ///< a built-in example to start on
  std::optional<std::string> screenshot;  ///< render the window to this PNG and exit
  /// render View ▸ Inversions… of the linkage to this PNG and exit
  std::optional<std::string> inversionsScreenshot;
  std::optional<double> crankAngleDeg;               ///< crank angle to show (default 0°)
  std::optional<std::string> image;                  ///< write Export ▸ Image (.png, .svg, .pdf) here and exit
  std::optional<int> imagePlot;                      ///< --image-of plotN: that plot (1 is the first), not the canvas
  std::optional<std::string> animation;              ///< write one cycle here (.gif, .mp4, .webm) and exit
  int frames = 72;                                   ///< --frames: frames per cycle of the animation, 2 to 720
  int frameDelayMs = 40;                             ///< --frame-delay: a GIF's ms per frame, 20 to 5000
  double frameRate = 25.0;                           ///< --frame-rate: a video's frames per second, 1 to 120
  std::optional<std::pair<int, int>> animationSize;  ///< --animation-size: the frames' width and height, px
  std::optional<std::string> compare;                ///< a table from another tool: open File ▸ Compare… on it
  std::optional<std::string> compareMap;  ///< its column mapping (linkwright-cli compare's --map), compared at once
  std::optional<std::string> plots;       ///< --plots: the keys of the quantities to plot, comma-separated
  std::optional<std::pair<int, int>> windowSize;  ///< --window-size: the window's width and height, px
  bool presentation = false;
  bool highContrast = false;  ///< start in View ▸ High contrast
  bool forces = false;        ///< start on the Forces tab with force arrows shown
  bool centres = false;       ///< draw the instant centres and centrodes
  bool help = false;
  bool version = false;
};

/// Parses the arguments after the program name (with QCommandLineParser, so it needs no
/// QApplication: --help and --version work without a display); `error` gets a message
/// naming the option.
std::optional<GuiOptions> parseGuiOptions(const std::vector<std::string>& args, std::string& error);

/// The --help text, with exit codes.
std::string guiUsage();

}  // namespace linkwright::app
