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

bool parseAnimationOptions(const QCommandLineParser& parser, const QCommandLineOption& animation,
                           const QCommandLineOption& frames, const QCommandLineOption& frameDelay, GuiOptions& o,
                           std::string& error) {
  if (parser.isSet(animation)) {
    // A wrong suffix is bad input, said before the window is made (the export checks it too).
    const QString path = parser.value(animation);
    if (QFileInfo(path).suffix().toLower() != QLatin1String("gif")) {
      error =
          "--animation: the file name must end in .gif, the only format it writes (got '" + path.toStdString() + "')";
      return false;
    }
    o.animation = path.toStdString();
  }
  if ((parser.isSet(frames) || parser.isSet(frameDelay)) && !o.animation) {
    error = "--frames and --frame-delay need --animation FILE";
    return false;
  }
  if (o.animation && o.screenshot) {
    error = "give --screenshot or --animation, not both";
    return false;
  }
  // The same bounds as File ▸ Export ▸ Animation (ui/export/cycle_animation.h checks them again).
  if (parser.isSet(frames)) {
    const auto n = wholeNumber("--frames", parser.value(frames).toStdString(), 2, 720, error);
    if (!n) return false;
    o.frames = *n;
  }
  if (parser.isSet(frameDelay)) {
    const auto ms = wholeNumber("--frame-delay", parser.value(frameDelay).toStdString(), 20, 5000, error);
    if (!ms) return false;
    o.frameDelayMs = *ms;
  }
  return true;
}

// "1366x768": within what a screen has (640×480 to 7680×4320).
bool parseWindowSize(const std::string& text, GuiOptions& o, std::string& error) {
  int width = 0, height = 0;
  const char* end = text.data() + text.size();
  const auto w = std::from_chars(text.data(), end, width);
  const bool separated = w.ec == std::errc{} && w.ptr != end && (*w.ptr == 'x' || *w.ptr == 'X');
  const auto h =
      separated ? std::from_chars(w.ptr + 1, end, height) : std::from_chars_result{w.ptr, std::errc::invalid_argument};
  if (!separated || h.ec != std::errc{} || h.ptr != end || width < 640 || width > 7680 || height < 480 ||
      height > 4320) {
    error = "--window-size: '" + text + "' must be WIDTHxHEIGHT in pixels, 640x480 to 7680x4320 (e.g. 1366x768)";
    return false;
  }
  o.windowSize = std::pair{width, height};
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
         "  --animation FILE    write an animated GIF of the canvas over one cycle (one turn\n"
         "                      from the crank angle shown; a crank that cannot turn fully\n"
         "                      goes there and back; a time base from start to end), exit\n"
         "  --frames N          frames per cycle of the animation, 2 to 720 (default 72)\n"
         "  --frame-delay MS    time each frame shows, ms, 20 to 5000, rounded to 10 ms\n"
         "                      (default 40: 25 frames per second)\n"
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
         "Exit codes: 0 success, 1 the screenshot or animation could not be written, 2 bad\n"
         "usage or a file that cannot be opened (the message says why).\n";
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
  const QCommandLineOption compare("compare", {}, "TABLE");
  const QCommandLineOption compareMap("compare-map", {}, "MAP");
  const QCommandLineOption plots("plots", {}, "KEYS");
  const QCommandLineOption windowSize("window-size", {}, "WxH");
  parser.addOptions({help, version, presentation, highContrast, forces, centres, example, screenshot,
                     inversionsScreenshot, crankAngle, animation, frames, frameDelay, compare, compareMap, plots,
                     windowSize});
  parser.addPositionalArgument("file", {});
  QStringList arguments{"linkwright"};
  for (const std::string& a : args) arguments << QString::fromStdString(a);
  if (!parser.parse(arguments)) {
    error = parser.errorText().toStdString() + " (see linkwright --help)";
    return std::nullopt;
  }
  for (const auto& option : {example, screenshot, inversionsScreenshot, crankAngle, animation, frames, frameDelay,
                             compare, compareMap, plots, windowSize})
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
  if (!parseAnimationOptions(parser, animation, frames, frameDelay, o, error)) return std::nullopt;
  if (o.animation && o.inversionsScreenshot) {
    error = "give --animation or --inversions-screenshot, not both";
    return std::nullopt;
  }
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
