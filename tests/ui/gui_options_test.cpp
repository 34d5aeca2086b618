// The designer's command line (app/gui_options.h): every option, both value forms, and a
// message naming the option for each kind of mistake.

#include "app/gui_options.h"

#include "tests/support/catch.h"

#include <string>
#include <vector>

using namespace linkwright;

namespace {

struct Parsed {
  std::optional<app::GuiOptions> options;
  std::string error;
};

Parsed parse(const std::vector<std::string>& args) {
  Parsed p;
  p.options = app::parseGuiOptions(args, p.error);
  return p;
}

}  // namespace

TEST_CASE("the designer's options are read in both value forms", "[ui][options]") {
  const auto p = parse({"--example=shaper", "--screenshot", "shot.png", "--crank-angle", "-30.5", "--presentation",
                        "--high-contrast", "--forces", "--centres"});
  REQUIRE(p.options);
  CHECK(p.options->example == "shaper");
  CHECK(p.options->screenshot == "shot.png");
  CHECK(p.options->crankAngleDeg == -30.5);
  CHECK(p.options->presentation);
  CHECK(p.options->highContrast);
  CHECK(p.options->forces);
  CHECK(p.options->centres);
  CHECK_FALSE(p.options->file);
  CHECK_FALSE(parse({"--example=shaper"}).options->centres);
  CHECK_FALSE(parse({"--example=shaper"}).options->highContrast);

  const auto file = parse({"arm.linkwright", "--crank-angle=90"});
  REQUIRE(file.options);
  CHECK(file.options->file == "arm.linkwright");
  CHECK(file.options->crankAngleDeg == 90.0);

  const auto animation = parse({"--animation=cycle.gif", "--frames", "36", "--frame-delay=60"});
  REQUIRE(animation.options);
  CHECK(animation.options->animation == "cycle.gif");
  CHECK(animation.options->frames == 36);
  CHECK(animation.options->frameDelayMs == 60);
  CHECK(parse({"--animation", "a.gif"}).options->frames == 72);
  const auto video = parse({"--animation=cycle.MP4", "--frame-rate", "29.97", "--animation-size=1281x720"});
  REQUIRE(video.options);
  CHECK(video.options->animation == "cycle.MP4");
  CHECK(video.options->frameRate == 29.97);
  CHECK(video.options->animationSize == std::pair{1281, 720});
  CHECK(parse({"--animation", "a.webm"}).options->frameRate == 25.0);
  CHECK_FALSE(parse({"--animation", "a.webm"}).options->animationSize);

  const auto image = parse({"--image", "figure.pdf", "--image-of=plot2"});
  REQUIRE(image.options);
  CHECK(image.options->image == "figure.pdf");
  CHECK(image.options->imagePlot == 2);
  CHECK_FALSE(parse({"--image", "canvas.svg", "--image-of", "canvas"}).options->imagePlot);
  CHECK_FALSE(parse({}).options->image);

  CHECK(parse({"--plots=rocker_angle,velocity_ratio"}).options->plots == "rocker_angle,velocity_ratio");
  CHECK_FALSE(parse({}).options->plots);
  const auto inversions = parse({"--example", "ls3-engine", "--inversions-screenshot=inv.png"});
  REQUIRE(inversions.options);
  CHECK(inversions.options->inversionsScreenshot == "inv.png");
  CHECK_FALSE(inversions.options->screenshot);

  CHECK(parse({"--window-size=1366x768"}).options->windowSize == std::pair{1366, 768});
  CHECK_FALSE(parse({}).options->windowSize);

  CHECK(parse({"-h"}).options->help);
  CHECK(parse({"--version"}).options->version);
  CHECK_FALSE(parse({}).options->help);
}

TEST_CASE("mistakes on the designer's command line name the option", "[ui][options][errors]") {
  auto [args, message] = GENERATE(table<std::vector<std::string>, std::string>({
      {{"--bogus"}, "Unknown option 'bogus'"},
      {{"--example"}, "Missing value after '--example'"},
      {{"--example", "nope"}, "--example: no example named 'nope'"},
      {{"--crank-angle", "1,5"}, "--crank-angle: '1,5' is not a finite number"},
      {{"--crank-angle", "inf"}, "--crank-angle: 'inf' is not a finite number"},
      {{"--screenshot", "a.png", "--screenshot", "b.png"}, "--screenshot is given more than once"},
      {{"a.linkwright", "b.linkwright"}, "only one file can be opened (got 'a.linkwright' and 'b.linkwright')"},
      {{"a.linkwright", "--example", "shaper"}, "give a file or --example, not both"},
      {{"--animation", "a.gif", "--frames", "1"}, "--frames: must be a whole number from 2 to 720 (got '1')"},
      {{"--animation", "a.gif", "--frames", "36.5"}, "--frames: must be a whole number from 2 to 720 (got '36.5')"},
      {{"--animation", "a.gif", "--frame-delay", "6000"},
       "--frame-delay: must be a whole number from 20 to 5000 (got '6000')"},
      {{"--frame-delay", "40"}, "--frames, --frame-delay, --frame-rate and --animation-size need --animation FILE"},
      {{"--frame-rate", "30"}, "--frames, --frame-delay, --frame-rate and --animation-size need --animation FILE"},
      // It exited 1, as if the file could not be written.
      {{"--animation", "x.png"},
       "--animation: the file name must end in .gif, .mp4 or .webm, the formats it writes (got 'x.png')"},
      {{"--animation", "a.mp4", "--frame-rate", "0"},
       "--frame-rate: must be a number of frames per second from 1 to 120 (got '0')"},
      {{"--animation", "a.mp4", "--frame-rate", "121"}, "--frame-rate: must be a number of frames per second"},
      {{"--animation", "a.webm", "--frame-rate", "nan"}, "--frame-rate: must be a number of frames per second"},
      {{"--animation", "a.mp4", "--frame-delay", "40"},
       "--frame-delay is a GIF's; a video's timing is --frame-rate FPS"},
      {{"--animation", "a.gif", "--frame-rate", "30"},
       "--frame-rate is a video's (.mp4, .webm); a GIF's timing is --frame-delay MS"},
      {{"--animation", "a.mp4", "--animation-size", "0x720"},
       "--animation-size: '0x720' must be WIDTHxHEIGHT in pixels, each 16 to 4096"},
      {{"--animation", "a.mp4", "--animation-size", "8192x720"}, "--animation-size: '8192x720' must be"},
      {{"--image", "a.jpg"}, "--image: the file name must end in .png, .svg or .pdf (got 'a.jpg')"},
      {{"--image-of", "plot1"}, "--image-of needs --image FILE"},
      {{"--image", "a.pdf", "--image-of", "plot0"}, "--image-of: 'plot0' must be canvas or plotN"},
      {{"--image", "a.pdf", "--image-of", "chart"}, "--image-of: 'chart' must be canvas or plotN"},
      {{"--image", "a.pdf", "--screenshot", "a.png"},
       "give --image alone, without --screenshot, --inversions-screenshot or --animation"},
      {{"--animation", "gif"}, "--animation: the file name must end in .gif"},
      {{"--animation", "a.gif", "--screenshot", "a.png"}, "give --screenshot or --animation, not both"},
      {{"--plots="}, "--plots: give at least one key"},
      {{"--window-size", "1366"}, "--window-size: '1366' must be WIDTHxHEIGHT in pixels, 640x480 to 7680x4320"},
      {{"--window-size", "1366x76"}, "--window-size: '1366x76' must be WIDTHxHEIGHT"},
      {{"--window-size", "1366x768px"}, "--window-size: '1366x768px' must be"},
      {{"--window-size", "-1x768"}, "--window-size: '-1x768' must be"},
      {{"--inversions-screenshot", "i.png", "--screenshot", "a.png"},
       "give --screenshot or --inversions-screenshot, not both"},
      {{"--inversions-screenshot", "i.png", "--animation", "a.gif"},
       "give --animation or --inversions-screenshot, not both"},
  }));
  CAPTURE(args);
  const auto p = parse(args);
  CHECK_FALSE(p.options);
  CHECK_THAT(p.error, Catch::Contains(message));
}
