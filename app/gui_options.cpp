#include "app/gui_options.h"

#include "kinematics/model/mechanism_design.h"

#include <charconv>
#include <cmath>

namespace linkwright::app {

std::string guiUsage() {
  std::string names;
  for (const auto& e : kinematics::fourBarExamples()) names += "\n                      " + e.name;
  for (const auto& e : kinematics::mechanismExamples()) names += "\n                      " + e.name;
  return "Usage: linkwright [FILE] [OPTIONS]\n\n"
         "Linkwright: design and analyse planar linkages (four-bars, slider-cranks, quick\n"
         "returns, six-bars). Opens FILE, a Linkwright document of any kind (.linkwright, or\n"
         ".json as older versions saved it), or the thesis crank-rocker example, and\n"
         "animates it.\n\n"
         "Options:\n"
         "  --example NAME      start on a built-in example:" + names + "\n"
         "  --screenshot FILE   render the window to FILE (PNG) and exit, without animating\n"
         "  --crank-angle DEG   crank angle to show, degrees (default 0)\n"
         "  --presentation      large fonts and lines, full screen\n"
         "  --forces            open on the Forces tab, with force arrows on the canvas\n"
         "  --help, --version\n\n"
         "Exit codes: 0 success, 1 the screenshot could not be written, 2 bad usage or a file\n"
         "that cannot be opened (the message says why).\n";
}

std::optional<GuiOptions> parseGuiOptions(const std::vector<std::string>& args, std::string& error) {
  GuiOptions o;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&]() -> std::optional<std::string> {
      if (i + 1 >= args.size()) {
        error = a + " needs a value";
        return std::nullopt;
      }
      return args[++i];
    };
    if (a == "--help" || a == "-h") o.help = true;
    else if (a == "--version") o.version = true;
    else if (a == "--presentation") o.presentation = true;
    else if (a == "--forces") o.forces = true;
    else if (a == "--example" || a == "--screenshot" || a == "--crank-angle") {
      const auto v = value();
      if (!v) return std::nullopt;
      if (a == "--example") {
        if (!kinematics::designForExample(*v)) {
          error = "--example: no example named '" + *v + "' (see --help)";
          return std::nullopt;
        }
        o.example = *v;
      } else if (a == "--screenshot") {
        o.screenshot = *v;
      } else {
        double deg = 0.0;
        const auto [ptr, ec] = std::from_chars(v->data(), v->data() + v->size(), deg);
        if (ec != std::errc{} || ptr != v->data() + v->size() || !std::isfinite(deg)) {
          error = "--crank-angle: '" + *v + "' is not a finite number";
          return std::nullopt;
        }
        o.crankAngleDeg = deg;
      }
    } else if (!a.empty() && a[0] == '-') {
      error = "unknown option '" + a + "' (see linkwright --help)";
      return std::nullopt;
    } else if (o.file) {
      error = "only one file can be opened (got '" + *o.file + "' and '" + a + "')";
      return std::nullopt;
    } else {
      o.file = a;
    }
  }
  if (o.file && o.example) {
    error = "give a file or --example, not both";
    return std::nullopt;
  }
  return o;
}

} // namespace linkwright::app
