#include "app/gui_options.h"

#include "kinematics/design/design.h"

#include <QCommandLineParser>
#include <QFileInfo>
#include <QStringList>

#include <charconv>
#include <cmath>

namespace linkwright::app {

namespace {

// A whole number in [low, high], or a message naming the option, the value and the range.
std::optional<int> wholeNumber(const std::string& option, const std::string& text, int low, int high,
                               std::string& error) {
  int value = 0;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc{} || ptr != text.data() + text.size() || value < low || value > high) {
    error = option + ": must be a whole number from " + std::to_string(low) + " to " + std::to_string(high) +
            " (got '" + text + "')";
    return std::nullopt;
  }
  return value;
}

// "WxH" with each side in [low, high], or nullopt.
std::optional<std::pair<int, int>> parseSize(const std::string& text, int low, int high) {
  int width = 0, height = 0;
  const char* end = text.data() + text.size();
  const auto w = std::from_chars(text.data(), end, width);
  const bool separated = w.ec == std::errc{} && w.ptr != end && (*w.ptr == 'x' || *w.ptr == 'X');
  if (!separated) return std::nullopt;
  const auto h = std::from_chars(w.ptr + 1, end, height);
  if (h.ec != std::errc{} || h.ptr != end || width < low || width > high || height < low || height > high)
    return std::nullopt;
  return std::pair{width, height};
}

struct AnimationOptionNames {
  const QCommandLineOption& animation;
  const QCommandLineOption& frames;
  const QCommandLineOption& frameDelay;
  const QCommandLineOption& frameRate;
  const QCommandLineOption& size;
};

// The timing options: a GIF's is the delay (it counts 1/100 s), a video's the frame rate.
bool parseAnimationTiming(const QCommandLineParser& parser, const AnimationOptionNames& n, bool gif, GuiOptions& o,
                          std::string& error) {
  if (parser.isSet(n.frameDelay) && !gif) {
    error = "--frame-delay is a GIF's; a video's timing is --frame-rate FPS";
    return false;
  }
  if (parser.isSet(n.frameRate) && gif) {
    error = "--frame-rate is a video's (.mp4, .webm); a GIF's timing is --frame-delay MS";
    return false;
  }
  // The same bounds as File ▸ Export ▸ Animation (ui/export/cycle_animation.h checks them again).
  if (parser.isSet(n.frameDelay)) {
    const auto ms = wholeNumber("--frame-delay", parser.value(n.frameDelay).toStdString(), 20, 5000, error);
    if (!ms) return false;
    o.frameDelayMs = *ms;
  }
  if (parser.isSet(n.frameRate)) {
    const std::string text = parser.value(n.frameRate).toStdString();
    double fps = 0.0;
    const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), fps);
    if (ec != std::errc{} || ptr != text.data() + text.size() || !(fps >= 1.0 && fps <= 120.0)) {
      error = "--frame-rate: must be a number of frames per second from 1 to 120 (got '" + text + "')";
      return false;
    }
    o.frameRate = fps;
  }
  return true;
}

bool parseAnimationOptions(const QCommandLineParser& parser, const AnimationOptionNames& n, GuiOptions& o,
                           std::string& error) {
  if (parser.isSet(n.animation)) {
    // A wrong suffix is bad input, said before the window is made (the export checks it too).
    const QString path = parser.value(n.animation);
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix != QLatin1String("gif") && suffix != QLatin1String("mp4") && suffix != QLatin1String("webm")) {
      error = "--animation: the file name must end in .gif, .mp4 or .webm, the formats it writes (got '" +
              path.toStdString() + "')";
      return false;
    }
    o.animation = path.toStdString();
  }
  if ((parser.isSet(n.frames) || parser.isSet(n.frameDelay) || parser.isSet(n.frameRate) || parser.isSet(n.size)) &&
      !o.animation) {
    error = "--frames, --frame-delay, --frame-rate and --animation-size need --animation FILE";
    return false;
  }
  if (!o.animation) return true;
  if (o.screenshot) {
    error = "give --screenshot or --animation, not both";
    return false;
  }
  if (parser.isSet(n.frames)) {
    const auto frames = wholeNumber("--frames", parser.value(n.frames).toStdString(), 2, 720, error);
    if (!frames) return false;
    o.frames = *frames;
  }
  if (parser.isSet(n.size)) {
    const std::string text = parser.value(n.size).toStdString();
    o.animationSize = parseSize(text, 16, 4096);
    if (!o.animationSize) {
      error = "--animation-size: '" + text + "' must be WIDTHxHEIGHT in pixels, each 16 to 4096 (e.g. 1280x720)";
      return false;
    }
  }
  return parseAnimationTiming(parser, n, QFileInfo(QString::fromStdString(*o.animation)).suffix().toLower() == "gif", o,
                              error);
}

// --image FILE [--image-of canvas|plotN].
bool parseImageOptions(const QCommandLineParser& parser, const QCommandLineOption& image,
                       const QCommandLineOption& imageOf, GuiOptions& o, std::string& error) {
  if (parser.isSet(imageOf) && !parser.isSet(image)) {
    error = "--image-of needs --image FILE";
    return false;
  }
  if (!parser.isSet(image)) return true;
  const QString path = parser.value(image);
  const QString suffix = QFileInfo(path).suffix().toLower();
  if (suffix != QLatin1String("png") && suffix != QLatin1String("svg") && suffix != QLatin1String("pdf")) {
    error = "--image: the file name must end in .png, .svg or .pdf (got '" + path.toStdString() + "')";
    return false;
  }
  if (o.screenshot || o.inversionsScreenshot || o.animation) {
    error = "give --image alone, without --screenshot, --inversions-screenshot or --animation";
    return false;
  }
  o.image = path.toStdString();
  if (!parser.isSet(imageOf)) return true;
  const std::string what = parser.value(imageOf).toStdString();
  if (what == "canvas") return true;
  int n = 0;
  const char* end = what.data() + what.size();
  const bool plot = what.rfind("plot", 0) == 0 && what.size() > 4;
  const auto parsed = plot ? std::from_chars(what.data() + 4, end, n) : std::from_chars_result{end, std::errc{}};
  if (!plot || parsed.ec != std::errc{} || parsed.ptr != end || n < 1 || n > 99) {
    error = "--image-of: '" + what + "' must be canvas or plotN, N counting the plots from 1 (plot1)";
    return false;
  }
  o.imagePlot = n;
  return true;
}

// "1366x768": within what a screen has (640×480 to 7680×4320).
bool parseWindowSize(const std::string& text, GuiOptions& o, std::string& error) {
  o.windowSize = parseSize(text, 480, 7680);
  if (!o.windowSize || o.windowSize->first < 640 || o.windowSize->second > 4320) {
    error = "--window-size: '" + text + "' must be WIDTHxHEIGHT in pixels, 640x480 to 7680x4320 (e.g. 1366x768)";
    return false;
  }
  return true;
}

}  // namespace

std::string guiUsage() {
  std::string names;
  for (const auto& e : kinematics::examples()) names += "\n                      " + e.name;
  return "Usage: linkwright [FILE] [OPTIONS]\n\n"
         "Linkwright: design and analyse planar linkages (four-bars, slider-cranks, quick\n"
         "returns, six-bars). Opens FILE, a Linkwright document of any kind (.linkwright, or\n"
         ".json as older versions saved it), or the thesis crank-rocker example, and\n"
         "animates it.\n\n"
         "Options:\n"
         "  --example NAME      start on a built-in example:" +
         names +
         "\n"
         "  --screenshot FILE   render the window to FILE (PNG) and exit, without animating\n"
         "  --inversions-screenshot FILE\n"
         "                      render View ▸ Inversions… (a four-bar's or slider-crank's four\n"
         "                      inversions side by side) to FILE (PNG) and exit\n"
         "  --crank-angle DEG   crank angle to show, degrees (default 0)\n"
         "  --image FILE        write File ▸ Export ▸ Image of the canvas to FILE and exit:\n"
         "                      .png (twice the screen's resolution), .svg or .pdf (vector:\n"
         "                      lines and text, one page the canvas's size)\n"
         "  --image-of WHAT     canvas (the default) or plotN, the N-th plot from the top\n"
         "                      (plot1), which must be shown (see --plots)\n"
         "  --animation FILE    write the canvas over one cycle (one turn from the crank\n"
         "                      angle shown; a crank that cannot turn fully goes there and\n"
         "                      back; a time base from start to end) and exit: an animated\n"
         "                      .gif, an .mp4 video (H.264; an odd side is made one pixel\n"
         "                      less, as H.264 needs even sides) or a .webm video (VP9)\n"
         "  --frames N          frames per cycle of the animation, 2 to 720 (default 72)\n"
         "  --frame-delay MS    a GIF's time per frame, ms, 20 to 5000, rounded to 10 ms\n"
         "                      (default 40: 25 frames per second)\n"
         "  --frame-rate FPS    a video's frames per second, 1 to 120, fractions too\n"
         "                      (29.97; default 25)\n"
         "  --animation-size WxH\n"
         "                      the animation's frames in pixels, each side 16 to 4096\n"
         "                      (default: the canvas's size), the canvas scaled into them\n"
         "  --plots KEY,...     plot exactly these quantities, named by the keys of the\n"
         "                      plots' checkboxes: rocker_angle, transmission_angle,\n"
         "                      rocker_omega, C_x, velocity_ratio, mechanical_advantage…\n"
         "                      (a key the linkage does not have is refused, listing its keys)\n"
         "  --window-size WxH   the window's size in pixels, e.g. 1366x768 (a teaching\n"
         "                      laptop), 640x480 to 7680x4320\n"
         "  --presentation      large fonts and lines, full screen, the big read-out\n"
         "  --high-contrast     black on white, darker link colours, thicker grid axes (a\n"
         "                      projector; View ▸ High contrast, F12)\n"
         "  --forces            open on the Forces tab, with force arrows on the canvas\n"
         "  --centres           draw the instant centres, Kennedy's lines and the centrodes\n"
         "                      (four-bars and slider-cranks; View ▸ Instant centres)\n"
         "  --compare TABLE     open File ▸ Compare… on TABLE, a table from another tool\n"
         "  --compare-map MAP   its column mapping, as linkwright-cli compare's --map; the\n"
         "                      comparison runs at once and its rows are drawn on the plots\n"
         "                      (and in the --screenshot)\n"
         "  --help, --version\n\n"
         "Exit codes: 0 success, 1 the screenshot, image or animation could not be\n"
         "written, 2 bad usage or a file that cannot be opened (the message says why).\n";
}

std::optional<GuiOptions> parseGuiOptions(const std::vector<std::string>& args, std::string& error) {
  // QCommandLineParser (Qt Core) does the splitting: --name=value and --name value, -h,
  // unknown options and missing values, with its own messages.
  QCommandLineParser parser;
  const QCommandLineOption help({"h", "help"}, {});
  const QCommandLineOption version("version", {});
  const QCommandLineOption presentation("presentation", {});
  const QCommandLineOption highContrast("high-contrast", {});
  const QCommandLineOption forces("forces", {});
  const QCommandLineOption centres("centres", {});
  const QCommandLineOption example("example", {}, "NAME");
  const QCommandLineOption screenshot("screenshot", {}, "FILE");
  const QCommandLineOption inversionsScreenshot("inversions-screenshot", {}, "FILE");
  const QCommandLineOption crankAngle("crank-angle", {}, "DEG");
  const QCommandLineOption animation("animation", {}, "FILE");
  const QCommandLineOption frames("frames", {}, "N");
  const QCommandLineOption frameDelay("frame-delay", {}, "MS");
  const QCommandLineOption frameRate("frame-rate", {}, "FPS");
  const QCommandLineOption animationSize("animation-size", {}, "WxH");
  const QCommandLineOption image("image", {}, "FILE");
  const QCommandLineOption imageOf("image-of", {}, "WHAT");
  const QCommandLineOption compare("compare", {}, "TABLE");
  const QCommandLineOption compareMap("compare-map", {}, "MAP");
  const QCommandLineOption plots("plots", {}, "KEYS");
  const QCommandLineOption windowSize("window-size", {}, "WxH");
  parser.addOptions({help,         version,    presentation,
                     highContrast, forces,     centres,
                     example,      screenshot, inversionsScreenshot,
                     crankAngle,   animation,  frames,
                     frameDelay,   frameRate,  animationSize,
                     image,        imageOf,    compare,
                     compareMap,   plots,      windowSize});
  parser.addPositionalArgument("file", {});
  QStringList arguments{"linkwright"};
  for (const std::string& a : args) arguments << QString::fromStdString(a);
  if (!parser.parse(arguments)) {
    error = parser.errorText().toStdString() + " (see linkwright --help)";
    return std::nullopt;
  }
  for (const auto& option : {example, screenshot, inversionsScreenshot, crankAngle, animation, frames, frameDelay,
                             frameRate, animationSize, image, imageOf, compare, compareMap, plots, windowSize})
    if (parser.values(option).size() > 1) {
      error = "--" + option.names().front().toStdString() + " is given more than once";
      return std::nullopt;
    }

  GuiOptions o;
  o.help = parser.isSet(help);
  o.version = parser.isSet(version);
  o.presentation = parser.isSet(presentation);
  o.highContrast = parser.isSet(highContrast);
  o.forces = parser.isSet(forces);
  o.centres = parser.isSet(centres);
  if (parser.isSet(example)) {
    const std::string name = parser.value(example).toStdString();
    if (!kinematics::designForExample(name)) {
      error = "--example: no example named '" + name + "' (see --help)";
      return std::nullopt;
    }
    o.example = name;
  }
  if (parser.isSet(compare)) o.compare = parser.value(compare).toStdString();
  if (parser.isSet(compareMap)) {
    if (!o.compare) {
      error = "--compare-map goes with --compare TABLE";
      return std::nullopt;
    }
    o.compareMap = parser.value(compareMap).toStdString();
  }
  if (parser.isSet(plots)) {
    o.plots = parser.value(plots).toStdString();
    if (o.plots->empty()) {
      error = "--plots: give at least one key (see --help)";
      return std::nullopt;
    }
  }
  if (parser.isSet(windowSize) && !parseWindowSize(parser.value(windowSize).toStdString(), o, error))
    return std::nullopt;
  if (parser.isSet(screenshot)) o.screenshot = parser.value(screenshot).toStdString();
  if (parser.isSet(inversionsScreenshot)) {
    if (o.screenshot) {
      error = "give --screenshot or --inversions-screenshot, not both";
      return std::nullopt;
    }
    o.inversionsScreenshot = parser.value(inversionsScreenshot).toStdString();
  }
  if (parser.isSet(crankAngle)) {
    // std::from_chars, not QString::toDouble: '.' is the decimal point whatever the locale.
    const std::string text = parser.value(crankAngle).toStdString();
    double deg = 0.0;
    const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), deg);
    if (ec != std::errc{} || ptr != text.data() + text.size() || !std::isfinite(deg)) {
      error = "--crank-angle: '" + text + "' is not a finite number";
      return std::nullopt;
    }
    o.crankAngleDeg = deg;
  }
  if (!parseAnimationOptions(parser, {animation, frames, frameDelay, frameRate, animationSize}, o, error))
    return std::nullopt;
  if (o.animation && o.inversionsScreenshot) {
    error = "give --animation or --inversions-screenshot, not both";
    return std::nullopt;
  }
  if (!parseImageOptions(parser, image, imageOf, o, error)) return std::nullopt;
  const QStringList files = parser.positionalArguments();
  if (files.size() > 1) {
    error = "only one file can be opened (got '" + files[0].toStdString() + "' and '" + files[1].toStdString() + "')";
    return std::nullopt;
  }
  if (!files.isEmpty()) o.file = files.front().toStdString();
  if (o.file && o.example) {
    error = "give a file or --example, not both";
    return std::nullopt;
  }
  return o;
}

}  // namespace linkwright::app
