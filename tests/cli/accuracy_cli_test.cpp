// linkwright-cli accuracy: the measured speed-accuracy table and its plot.

#include "app/cli/svg_plot.h"
#include "tests/cli/run_cli.h"

#include "tests/support/catch.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

namespace {

int run(const std::vector<std::string>& args, std::string& out, std::string& err) {
  const auto r = linkwright::test::runCliCommand(args);
  out = r.out;
  err = r.err;
  return r.code;
}

}  // namespace

TEST_CASE("accuracy tabulates the trade for one example and draws it", "[cli][accuracy]") {
  const std::string svg = (std::filesystem::temp_directory_path() / "linkwright_accuracy_test.svg").string();
  std::string out, err;
  REQUIRE(run({"accuracy", "--example", "ls3-engine", "--svg", svg}, out, err) == 0);
  std::istringstream lines(out);
  std::string line;
  std::getline(lines, line);
  CHECK(line ==
        "example,method,samples_per_rev,time_us,omega_rel_error,alpha_rel_error,speed_rel_error,"
        "acceleration_rel_error,angle_error_deg,reference\r");
  int rows = 0, refined = 0;
  while (std::getline(lines, line)) {
    ++rows;
    if (line.find(",refined,") == std::string::npos) continue;
    ++refined;
    // Refined peaks agree with the 7200-sample reference to round-off, from any grid.
    std::istringstream cells(line);
    std::vector<std::string> c;
    for (std::string cell; std::getline(cells, cell, ',');) c.push_back(cell);
    for (int i = 4; i <= 7; ++i) CHECK(std::stod(c[static_cast<std::size_t>(i)]) < 1e-12);
  }
  CHECK(rows == 4 * 3 + 1 + 6);  // 4 grids × 3 methods, closed form, 6 Newton tolerances
  CHECK(refined == 4);
  std::ifstream file(svg);
  std::stringstream text;
  text << file.rdbuf();
  CHECK_THAT(text.str(), Catch::StartsWith("<svg"));
  CHECK_THAT(text.str(), Catch::Contains("refined (Linkwright)"));
  std::filesystem::remove(svg);
}

TEST_CASE("accuracy names what it cannot measure", "[cli][accuracy][errors]") {
  std::string out, err;
  CHECK(run({"accuracy", "--example", "nope"}, out, err) == 2);
  CHECK_THAT(err, Catch::Contains("no example named 'nope'"));
  CHECK(run({"accuracy", "--samples", "3"}, out, err) == 2);
  CHECK_THAT(err, Catch::Contains("unknown option '--samples' for 'accuracy'"));
}

TEST_CASE("the SVG plot leaves out points that are not positive and finite", "[cli][accuracy][errors]") {
  // The last guard of accuracy --svg: an infinite error would otherwise become no coordinate.
  const double inf = std::numeric_limits<double>::infinity();
  const std::string svg = linkwright::cli::logLogPlotSvg(
      "t", "x", "y",
      {{"s", "#000", false, {{10.0, 1e-3}, {100.0, inf}, {inf, 1e-4}, {1000.0, std::nan("")}, {1e4, 1e-6}}}});
  CHECK(svg.find("undefined") == std::string::npos);
  CHECK(svg.find("inf") == std::string::npos);
  CHECK(svg.find("nan") == std::string::npos);
  std::size_t circles = 0;
  for (std::size_t at = svg.find("<circle"); at != std::string::npos; at = svg.find("<circle", at + 1)) ++circles;
  CHECK(circles == 2);
}
