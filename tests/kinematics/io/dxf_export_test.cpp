// Tests kinematics/io/dxf_export.h by reading its files back with dxflib's own reader: every
// layer, hole, outline vertex and bulge comes back as the same double (17 significant digits,
// large or small, which dxflib's own "%.16f" would not keep below 1); $INSUNITS follows the unit; a file that cannot be written leaves nothing behind and
// an existing file untouched. (tests/cli/dxf_readback.py reads the CLI's files with ezdxf.)

#include "kinematics/io/dxf_export.h"

#include "kinematics/design/examples.h"
#include "kinematics/solve/pose_solver.h"
#include "tests/support/catch.h"
#include "tests/support/scratch_dir.h"

#include <dl_creationadapter.h>
#include <dl_dxf.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

using namespace linkwright::kinematics;
using namespace linkwright::kinematics::io;
namespace fs = std::filesystem;
using linkwright::test::scratchDir;

namespace {

// What dxflib's reader finds, per layer.
struct ReadBack : DL_CreationAdapter {
  std::map<std::string, std::vector<DL_CircleData>> circles;
  std::map<std::string, std::vector<std::vector<DL_VertexData>>> polylines;
  std::map<std::string, int> lines;
  std::vector<std::string> layers;
  int insUnits = -1;

  void addLayer(const DL_LayerData& d) override { layers.push_back(d.name); }
  void addCircle(const DL_CircleData& d) override { circles[getAttributes().getLayer()].push_back(d); }
  void addLine(const DL_LineData&) override { ++lines[getAttributes().getLayer()]; }
  void addPolyline(const DL_PolylineData&) override { polylines[getAttributes().getLayer()].emplace_back(); }
  void addVertex(const DL_VertexData& d) override { polylines[getAttributes().getLayer()].back().push_back(d); }
  void setVariableInt(const std::string& key, int value, int) override {
    if (key == "$INSUNITS") insUnits = value;
  }
};

ReadBack readBack(const fs::path& file) {
  ReadBack r;
  DL_Dxf dxf;
  REQUIRE(dxf.in(file.string(), &r));
  return r;
}

LinkDrawing oneHole(const Eigen::Vector2d& centre, const std::string& unit) {
  LinkDrawing drawing{unit, 2.0, 4.0, {}};
  drawing.layers.push_back({"GROUND", {}, {{PointId{0}, centre, 2.0}}, {}});
  drawing.layers.push_back({"crank", {roundedHull({centre, centre + Eigen::Vector2d(10.0, 0.0)}, 2.0)}, {}, {}});
  return drawing;
}

}  // namespace

TEST_CASE("a DXF file reads back with every layer, hole and outline", "[dxf_export]") {
  const fs::path dir = scratchDir("dxf-test");
  const Example e = *findExample("stephenson-iii-triad");
  const auto pose = solvePose(e.mechanism, {0.3, 0.0, 0.0}, SolveRequest{false, false});
  REQUIRE(pose.ok());
  const auto drawing = linkDrawing(e.mechanism, *pose, {});
  REQUIRE(drawing.ok());
  const fs::path file = dir / "six.dxf";
  REQUIRE_FALSE(exportLinkDrawingDxf(e.mechanism, *pose, {}, file.string()).has_value());
  const ReadBack r = readBack(file);
  CHECK(r.insUnits == 4);  // mm
  for (const DrawingLayer& layer : drawing->layers) {
    INFO(layer.name);
    CHECK(std::count(r.layers.begin(), r.layers.end(), layer.name) == 1);
    const auto& circles = r.circles.at(layer.name);
    REQUIRE(circles.size() == layer.holes.size());
    for (std::size_t i = 0; i < circles.size(); ++i) {
      CHECK(circles[i].cx == layer.holes[i].centre.x());
      CHECK(circles[i].cy == layer.holes[i].centre.y());
      CHECK(circles[i].radius == layer.holes[i].diameter / 2.0);
    }
    const std::size_t outlines = r.polylines.count(layer.name) ? r.polylines.at(layer.name).size() : 0;
    REQUIRE(outlines == layer.outlines.size());
    for (std::size_t o = 0; o < outlines; ++o) {
      const auto& vertices = r.polylines.at(layer.name)[o];
      REQUIRE(vertices.size() == layer.outlines[o].size());
      for (std::size_t v = 0; v < vertices.size(); ++v) {
        CHECK(vertices[v].x == layer.outlines[o][v].point.x());
        CHECK(vertices[v].y == layer.outlines[o][v].point.y());
        CHECK(vertices[v].bulge == layer.outlines[o][v].bulge);
      }
    }
  }
  CHECK(r.lines.at("GROUND") == 2 * static_cast<int>(drawing->layers.front().holes.size()));
  fs::remove_all(dir);
}

TEST_CASE("coordinates keep 17 significant digits through a DXF file", "[dxf_export]") {
  const fs::path dir = scratchDir("dxf-test");
  const Eigen::Vector2d big(123456789.01234567, -98765.432109876543);
  const Eigen::Vector2d small(0.012345678901234567, -3.3333333333333333e-5);  // "%.16f" loses these
  for (const Eigen::Vector2d& centre : {big, small}) {
    REQUIRE_FALSE(writeDxf(oneHole(centre, "m"), (dir / "p.dxf").string()).has_value());
    const ReadBack r = readBack(dir / "p.dxf");
    const DL_CircleData& c = r.circles.at("GROUND").at(0);
    CHECK(c.cx == centre.x());
    CHECK(c.cy == centre.y());
    CHECK(r.insUnits == 6);  // m
  }
  fs::remove_all(dir);
}

TEST_CASE("$INSUNITS names the length unit, 0 when DXF has no code for it", "[dxf_export]") {
  CHECK(dxfInsUnits("in") == 1);
  CHECK(dxfInsUnits("ft") == 2);
  CHECK(dxfInsUnits("mm") == 4);
  CHECK(dxfInsUnits("cm") == 5);
  CHECK(dxfInsUnits("m") == 6);
  CHECK(dxfInsUnits("furlong") == 0);
  CHECK(dxfInsUnits("MM") == 0);  // unit labels are case-sensitive everywhere else too
}

TEST_CASE("a DXF file that cannot be written leaves nothing behind", "[dxf_export]") {
  const fs::path dir = scratchDir("dxf-test");
  const auto missing = writeDxf(oneHole({1.0, 2.0}, "mm"), (dir / "no-such-dir" / "x.dxf").string());
  REQUIRE(missing.has_value());
  CHECK(missing->field == "output");
  CHECK_THAT(missing->message, Catch::Contains("no-such-dir/x.dxf"));
  CHECK_FALSE(fs::exists(dir / "no-such-dir"));
  // A refused drawing leaves an existing file as it was.
  const fs::path kept = dir / "kept.dxf";
  std::ofstream(kept) << "old";
  const Example e = *findExample("thesis-crank-rocker");
  const auto pose = solvePose(e.mechanism, {0.0, 0.0, 0.0}, SolveRequest{false, false});
  REQUIRE(pose.ok());
  const auto refused = exportLinkDrawingDxf(e.mechanism, *pose, {-1.0, std::nullopt}, kept.string());
  REQUIRE(refused.has_value());
  CHECK(refused->field == "holeDiameter");
  std::stringstream text;
  text << std::ifstream(kept).rdbuf();
  CHECK(text.str() == "old");
  CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator{}) == 1);
  fs::remove_all(dir);
}
