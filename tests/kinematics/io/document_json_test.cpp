// Linkwright documents: save → open reproduces the design exactly, for four-bars and every
// other linkage; a version 1 or 2 file holding a four-bar by its lengths still reads, and
// re-saves in the linkage form; every malformed, invalid, foreign or newer file is refused
// with a message naming the member.

#include "kinematics/io/document_json.h"
#include "kinematics/design/examples.h"
#include "kinematics/model/attach_dyad.h"

#include <fstream>
#include <limits>
#include <sstream>

#include "tests/support/catch.h"

#include <string>

using namespace linkwright::kinematics;
using namespace linkwright::kinematics::io;

namespace {

// The four-bar tests/kinematics/io/documents/fourbar_v1.json holds.
Design sampleDesign() {
  Design d = fourBarDesign({60.0, 25.0, 70.0, 45.0}, Branch::Crossed, "mm", CouplerPointSpec{35.0, -20.25}).value();
  d.omega = 1.0471975511965976;  // 10 rpm: not a short decimal, so the round trip is tested
  d.alpha = 0.1;
  d.fromDeg = -30.0;
  d.toDeg = 330.0;
  d.samples = 1441;
  return d;
}

// The document read back (fails the test if it does not read).
Design designOf(const Result<Design>& read) {
  INFO((read.ok() ? std::string() : read.error().message));
  REQUIRE(read.ok());
  return *read;
}

std::string fileText(const std::string& path) {
  std::ifstream file(path);
  REQUIRE(file.good());
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

// sampleDesign in the older four-bar form, as Linkwright wrote it before the linkage form
// (version 1, or 2 as that writer saved it).
std::string fourBarFormText(int version) {
  return replaced(fileText(LINKWRIGHT_TEST_DOCUMENTS "/fourbar_v1.json"), "\"version\": 1",
                  "\"version\": " + std::to_string(version));
}

}  // namespace

TEST_CASE("a document round-trips every field exactly", "[io][document]") {
  const Design d = sampleDesign();
  const std::string text = writeDocument(d);
  const Design back = designOf(readDocument(text));
  CHECK(back == d);
  CHECK(back.kind == "four-bar");
  CHECK(writeDocument(back) == text);

  Design plain = d;
  plain.mechanism = makeFourBar({60.0, 25.0, 70.0, 45.0}, Branch::Crossed, "mm").value();
  CHECK(designOf(readDocument(writeDocument(plain))) == plain);
}

TEST_CASE("every built-in example round-trips", "[io][document]") {
  for (const Example& e : examples()) {
    CAPTURE(e.name);
    const Design d = designFromExample(e);
    REQUIRE_FALSE(checkDesign(d).has_value());
    const std::string text = writeDocument(d);
    const auto back = readDocument(text);
    INFO(text << (back.ok() ? std::string() : back.error().message));
    REQUIRE(back.ok());
    CHECK(*back == d);
    CHECK(writeDocument(*back) == text);
  }
}

TEST_CASE("a linkage with moving guides, two-slider pins and free points round-trips", "[io][document]") {
  // Every point type and both kinds of guide, so the format note is exercised in full.
  Mechanism m = makeFourBar({60.0, 25.0, 70.0, 45.0}, Branch::Open).value();
  m = addPointOnLink(m, "P", fourbar::kCoupler, 35.0, 20.0).value();
  m = attachDyad(m, RrpDyadSpec{"S", PointId{4}, 60.0, Guide{fourbar::kRocker, {1.5, -2.0}, 0.25}, Branch::Crossed})
          .value();
  m = attachDyad(m, PrpDyadSpec{"Q", Guide{std::nullopt, {30.0, 0.0}, 1.5707963267948966},
                                Guide{fourbar::kCoupler, {0.0, 10.0}, 0.0}})
          .value();
  m = attachDyad(m, RprDyadSpec{"T", fourbar::kO4, fourbar::kB, 80.0}).value();
  m.points.push_back({"F", FreePoint{Eigen::Vector2d(10.0, 90.0)}});
  m.constraints.push_back({fourbar::kB, PointId{m.points.size() - 1}, 75.0});
  m.constraints.push_back({fourbar::kC, PointId{m.points.size() - 1}, 60.5});
  Design d;
  d.kind = "test";
  d.mechanism = m;
  const std::string text = writeDocument(d);
  CAPTURE(text);
  const auto back = readDocument(text);
  INFO((back.ok() ? std::string() : back.error().message));
  REQUIRE(back.ok());
  CHECK(*back == d);
  CHECK_THAT(
      text,
      Catch::Contains("{\"name\": \"S\", \"type\": \"rrp\", \"first\": \"P\", \"length\": 60, \"branch\": \"crossed\", "
                      "\"guide\": {\"link\": \"rocker\", \"x\": 1.5, \"y\": -2, \"angle_rad\": 0.25}}"));
  CHECK_THAT(text, Catch::Contains("\"constraints\": [\n      {\"first\": \"B\", \"second\": \"F\", \"length\": 75}"));
}

TEST_CASE("a version 1 document still opens, as the same four-bar", "[io][document][migration]") {
  const std::string text = fileText(LINKWRIGHT_TEST_DOCUMENTS "/fourbar_v1.json");
  const Design d = designOf(readDocument(text));
  CHECK(d == sampleDesign());
  // Saved again it becomes a version 2 document in the linkage form, the same design.
  const std::string saved = writeDocument(d);
  CHECK(saved == writeDocument(sampleDesign()));
  CHECK_THAT(saved, Catch::StartsWith("{\n  \"format\": \"linkwright\",\n  \"version\": 2,"));
  CHECK(designOf(readDocument(saved)) == d);
}

TEST_CASE("a four-bar-form document of version 1 or 2 re-saves in the linkage form and reads back equal",
          "[io][document][migration]") {
  for (const int version : {1, 2}) {
    CAPTURE(version);
    const std::string old = fourBarFormText(version);
    const Design d = designOf(readDocument(old));
    CHECK(d == sampleDesign());
    // makeFourBar's mechanism: the ids and names O2, O4, B, C, P and crank, coupler, rocker.
    CHECK(d.kind == "four-bar");
    CHECK(d.mechanism ==
          makeFourBar({60.0, 25.0, 70.0, 45.0}, Branch::Crossed, "mm", CouplerPointSpec{35.0, -20.25}).value());
    const std::string saved = writeDocument(d);
    CHECK_THAT(saved, Catch::StartsWith("{\n  \"format\": \"linkwright\",\n  \"version\": 2,"));
    CHECK_THAT(saved, Catch::Contains("\"type\": \"linkage\",\n    \"kind\": \"four-bar\""));
    CHECK_THAT(saved, !Catch::Contains("\"lengths\"") && !Catch::Contains("\"type\": \"four-bar\""));
    const Design back = designOf(readDocument(saved));
    CHECK(back == d);
    CHECK(writeDocument(back) == saved);
  }
}

TEST_CASE("a four-bar-form document with dynamics (version 3) still reads", "[io][document][migration]") {
  // The older writer saved a four-bar with masses as version 3 in the four-bar form.
  const Design funsho = designForExample("funsho-fourbar").value();
  const std::string linkageText = writeDocument(funsho);
  const std::string dynamics = linkageText.substr(linkageText.find(",\n  \"dynamics\""));
  const std::string old =
      "{\n  \"format\": \"linkwright\",\n  \"version\": 3,\n  \"mechanism\": {\n"
      "    \"type\": \"four-bar\",\n    \"length_unit\": \"mm\",\n    \"branch\": \"open\",\n"
      "    \"lengths\": {\"frame\": 30, \"crank\": 10, \"coupler\": 35, \"rocker\": 20}\n  },\n"
      "  \"driver\": {\"omega_rad_s\": 100, \"alpha_rad_s2\": 0},\n"
      "  \"analysis\": {\"from_deg\": 0, \"to_deg\": 360, \"samples\": 721}" +
      dynamics;
  CAPTURE(old);
  const Design d = designOf(readDocument(old));
  CHECK(d == funsho);
  CHECK(writeDocument(d) == linkageText);
}

TEST_CASE("the document text is what the format note says", "[io][document]") {
  const std::string text = writeDocument(sampleDesign());
  CHECK_THAT(text, Catch::StartsWith("{\n  \"format\": \"linkwright\",\n  \"version\": 2,\n  \"mechanism\": {\n"
                                     "    \"type\": \"linkage\",\n    \"kind\": \"four-bar\",\n"
                                     "    \"length_unit\": \"mm\",\n    \"points\": ["));
  // The lengths are the points' definitions: C on (B, O4) with coupler 70 and rocker 45.
  CHECK_THAT(text, Catch::Contains("{\"name\": \"O4\", \"type\": \"ground\", \"x\": 60, \"y\": 0}"));
  CHECK_THAT(text, Catch::Contains("{\"name\": \"B\", \"type\": \"crank\", \"pivot\": \"O2\", \"length\": 25"));
  CHECK_THAT(text,
             Catch::Contains("\"first\": \"B\", \"first_length\": 70, \"second\": \"O4\", \"second_length\": 45"));
  CHECK_THAT(text, Catch::Contains("\"omega_rad_s\": 1.0471975511965976"));
}

TEST_CASE("a value that is still not finite is written as null, which the reader refuses", "[io][document][errors]") {
  // The last guard: a document never holds nan or inf, even from a design that skipped checks.
  auto d = sampleDesign();
  d.omega = std::numeric_limits<double>::infinity();
  const std::string text = writeDocument(d);
  CHECK_THAT(text, Catch::Contains("\"omega_rad_s\": null"));
  CHECK(text.find("inf") == std::string::npos);
  const auto back = readDocument(text);
  REQUIRE_FALSE(back.ok());
  CHECK(back.error().message == "driver.omega_rad_s must be a number");
}

TEST_CASE("bad documents are refused with the member named", "[io][document][errors]") {
  // The older four-bar form: its messages keep their paths ("mechanism.lengths.coupler").
  const std::string good = fourBarFormText(2);
  auto [text, expected] = GENERATE_COPY(table<std::string, std::string>({
      {"not json", "not valid JSON: line 1, column 2: syntax error while parsing value - invalid literal"},
      {"[1, 2]", "document must be a JSON object"},
      {replaced(good, "\"linkwright\"", "\"solvespace\""), "not a Linkwright document"},
      {replaced(good, "\"version\": 2", "\"version\": 8"),
       "this file is document version 8, written by a newer Linkwright; this one reads up to version 7"},
      {replaced(good, "\"version\": 2", "\"version\": 1.5"), "version must be a whole number"},
      {replaced(good, "\"version\": 2", "\"version\": \"1\""), "version must be a number"},
      {replaced(good, "\"four-bar\"", "\"six-bar\""),
       "mechanism.type must be \"four-bar\" or \"linkage\" in a version 2 document (got \"six-bar\")"},
      {replaced(good, "\"coupler\": 70", "\"coupler\": -70"),
       "mechanism.lengths.coupler length must be positive and finite (got -70)"},
      {replaced(good, "\"coupler\": 70", "\"coupler\": 0"), "mechanism.lengths.coupler length must be positive"},
      {replaced(good, "\"coupler\": 70, ", ""), "mechanism.lengths.coupler is missing"},
      {replaced(good, "\"frame\": 60", "\"frame\": \"60\""), "mechanism.lengths.frame must be a number"},
      {replaced(good, "\"crossed\"", "\"sideways\""), "mechanism.branch must be \"open\" or \"crossed\""},
      {replaced(good, "\"samples\": 1441", "\"samples\": 1"), "analysis.samples must be a whole number from 2"},
      {replaced(good, "\"samples\": 1441", "\"samples\": 12.5"), "analysis.samples must be a whole number from 2"},
      {replaced(good, "\"to_deg\": 330", "\"to_deg\": -90"), "analysis.to_deg must be greater than"},
      {replaced(good, "\"along\": 35", "\"along\": 1e999"), "not valid JSON"},
      {good.substr(0, good.size() / 2), "not valid JSON"},
  }));
  CAPTURE(text);
  const auto d = readDocument(text);
  REQUIRE_FALSE(d.ok());
  CHECK_THAT(d.error().message, Catch::Contains(expected));
}

TEST_CASE("a damaged four-bar saved in the linkage form is refused with the member named", "[io][document][errors]") {
  const std::string good = writeDocument(sampleDesign());
  auto [text, expected] = GENERATE_COPY(table<std::string, std::string>({
      {replaced(good, "\"linkwright\"", "\"solvespace\""), "not a Linkwright document"},
      {replaced(good, "\"version\": 2", "\"version\": 8"),
       "this file is document version 8, written by a newer Linkwright; this one reads up to version 7"},
      {replaced(good, "\"version\": 2", "\"version\": 1"),
       "must be \"four-bar\" in a version 1 document (got \"linkage\")"},
      {replaced(good, "\"first_length\": 70", "\"first_length\": -70"),
       "mechanism.points[3].first_length must be positive and finite (got -70)"},
      {replaced(good, "\"branch\": \"crossed\"", "\"branch\": \"sideways\""),
       "must be \"open\" or \"crossed\" (got \"sideways\")"},
      {replaced(good, "\"samples\": 1441", "\"samples\": 1"), "analysis.samples must be a whole number from 2"},
      {replaced(good, "\"to_deg\": 330", "\"to_deg\": -90"), "analysis.to_deg must be greater than"},
      {good.substr(0, good.size() / 2), "not valid JSON"},
  }));
  CAPTURE(text);
  const auto d = readDocument(text);
  REQUIRE_FALSE(d.ok());
  CHECK_THAT(d.error().message, Catch::Contains(expected));
}

TEST_CASE("unknown members are ignored, so minor additions stay readable", "[io][document]") {
  for (const std::string& good : {writeDocument(sampleDesign()), fourBarFormText(2)}) {
    const std::string text = replaced(good, "\"version\": 2,", "\"version\": 2,\n  \"comment\": {\"x\": [1]},");
    CHECK(designOf(readDocument(text)) == sampleDesign());
  }
}

TEST_CASE("bad linkage documents are refused with the member named", "[io][document][errors]") {
  const std::string good = writeDocument(designFromExample(*findExample("watt-ii")));
  auto [text, expected] = GENERATE_COPY(table<std::string, std::string>({
      {replaced(good, "\"version\": 2", "\"version\": 1"),
       "must be \"four-bar\" in a version 1 document (got \"linkage\")"},
      {replaced(good, "\"type\": \"rrr\"", "\"type\": \"rrrr\""),
       "mechanism.points[3].type must be one of ground, crank"},
      {replaced(good, "\"first\": \"B\", \"first_length\"", "\"first\": \"Z\", \"first_length\""),
       "mechanism.points[3].first names no point of this mechanism (got \"Z\")"},
      {replaced(good, "\"first_length\": 70", "\"first_length\": -70"),
       "mechanism.points[3].first_length must be positive and finite (got -70)"},
      {replaced(good, "\"link\": \"rocker\"", "\"link\": \"arm\""), "names no link of this mechanism (got \"arm\")"},
      {replaced(good, "{\"name\": \"O4\"", "{\"name\": \"O2\""), "mechanism.points[1].name repeats the name 'O2'"},
      {replaced(good, "\"links\": [", "\"links\": 3, \"x\": ["), "mechanism.links must be an array"},
      {replaced(good, "\"branch\": \"open\"", "\"branch\": \"up\""), "must be \"open\" or \"crossed\" (got \"up\")"},
  }));
  CAPTURE(text);
  const auto d = readDocument(text);
  REQUIRE_FALSE(d.ok());
  CHECK_THAT(d.error().message, Catch::Contains(expected));
}

TEST_CASE("a linear driver's document is version 5 and names its units in its keys", "[io][document][driven]") {
  const std::string arm = writeDocument(*designForExample("seed-arm"));
  CHECK_THAT(arm, Catch::Contains("\"version\": 5"));
  CHECK_THAT(arm, Catch::Contains(R"({"name": "tip", "type": "path", "path": {"shape": "polyline", "vertices": )"
                                  R"([{"x": 0.3, "y": 0}, {"x": 0, "y": 0.3}]}})"));
  CHECK_THAT(arm, Catch::Contains(R"("law": {"type": "constant", "start_m": 0, "velocity_m_s": 2})"));
  CHECK_THAT(arm, Catch::Contains(R"("analysis": {"from_m": 0, "to_m": 0.4242640687119285)"));
  const std::string boom = writeDocument(*designForExample("excavator-boom"));
  CHECK_THAT(boom, Catch::Contains(R"({"name": "C", "type": "actuator", "first": "O", "length": 1, "base": "A", )"
                                   R"("branch": "open"})"));
  // A crank's law keeps its radians, and its document stays version 4.
  Design timed = *designForExample("thesis-crank-rocker");
  timed.time = TimeBase{CycloidalRise{0.0, 1.0, 2.0}, 0.0, 2.0};
  CHECK_THAT(writeDocument(timed), Catch::Contains("\"version\": 4"));
  CHECK_THAT(writeDocument(timed), Catch::Contains(R"("start_rad": 0, "rise_rad": 1)"));
  // An arc path reads back exactly.
  Design arc = *designForExample("seed-arm");
  std::get<PathPoint>(arc.mechanism.points[1].definition).path = ArcPath{{0.1, 0.1}, 0.2, 0.3, -1.5};
  const auto back = readDocument(writeDocument(arc));
  REQUIRE(back.ok());
  CHECK(*back == arc);
}

TEST_CASE("bad driver documents are refused with the member named", "[io][document][driven][errors]") {
  const std::string arm = writeDocument(*designForExample("seed-arm"));
  const std::string boom = writeDocument(*designForExample("excavator-boom"));
  auto [text, expected] = GENERATE_COPY(table<std::string, std::string>({
      {replaced(arm, "\"shape\": \"polyline\"", "\"shape\": \"spiral\""),
       "mechanism.points[1].path.shape must be \"polyline\" or \"arc\" (got \"spiral\")"},
      {replaced(arm, "[{\"x\": 0.3, \"y\": 0}, {\"x\": 0, \"y\": 0.3}]", "[{\"x\": 0.3, \"y\": 0}]"),
       "mechanism.points[1].path.vertices needs at least two points (got 1)"},
      {replaced(arm, "[{\"x\": 0.3, \"y\": 0}, ", "[3, "), "mechanism.points[1].path.vertices[0] must be an object"},
      {replaced(arm, "\"velocity_m_s\": 2}", "\"velocity_rad_s\": 2}"), "driver.law.velocity_m_s"},
      {replaced(boom, "\"base\": \"A\"", "\"base\": \"O\""),
       "mechanism.points[2].base must differ from its first point"},
      {replaced(boom, "\"base\": \"A\"", "\"base\": \"Q\""),
       "mechanism.points[2].base names no point of this mechanism (got \"Q\")"},
      {replaced(boom, "\"rise_m\": 0.7", "\"rise_m\": 1e300"), "driver.law.rise_m"},
  }));
  CAPTURE(text);
  const auto d = readDocument(text);
  REQUIRE_FALSE(d.ok());
  CHECK_THAT(d.error().message, Catch::Contains(expected));
}

namespace {

// Every problem's targets filled with numbers that are not short decimals, some bounds unset.
SynthesisTargets sampleTargets() {
  SynthesisTargets t;
  t.problem = SynthesisProblem::Path;
  t.swing = {1.0471975511965976, 1.3, 50.0, SwingScale::Frame, "mm"};
  t.slider = {100.0, 1.25, SliderChoice::Offset, -12.5, "mm"};
  t.shaper = {300.0, 1.7, 50.0, 150.0, 321.0 / 7.0, "mm"};
  t.function = {"reciprocal", 1.0, 2.0, 0.1, 1.2, 2.0, -0.9, 80.0, {1.1, 1.5, 1.9}, 3};
  t.motion = {
      {{{0.0, 0.0}, 0.0}, {{10.0, 5.0}, 0.3}, {{20.0, 5.0}, 2.0 / 3.0}}, {{-5.0, -5.0}, {5.0, -7.0}}, 1.5, -2.5, true};
  t.path = {{{0, 0}, {10, 5}, {20, 5}, {30, 0}, {20, -1.0 / 3.0}},
            {0.1, 0.2, 0.3, 0.4, 0.5},
            TimingReference::Frame,
            true,
            "mm"};
  t.pathSearch = {250, 7};
  t.bounds = {0.5, 500.0, std::nullopt};
  return t;
}

}  // namespace

TEST_CASE("a design's synthesis targets are saved as version 6 and read back bit for bit",
          "[io][document][synthesis]") {
  Design d = sampleDesign();
  d.synthesis = sampleTargets();
  const std::string text = writeDocument(d);
  CHECK_THAT(text, Catch::Contains("\"version\": 6"));
  CHECK_THAT(text, Catch::Contains("\"synthesis\": {\"problem\": \"path\""));
  const Design back = designOf(readDocument(text));
  CHECK(back.synthesis == d.synthesis);
  CHECK(back == d);
  CHECK(writeDocument(back) == text);
  // Without targets nothing changes: the same version and text as before.
  CHECK_THAT(writeDocument(sampleDesign()), Catch::Contains("\"version\": 2"));
  CHECK_THAT(writeDocument(sampleDesign()), !Catch::Contains("synthesis"));
}

TEST_CASE("synthesis targets beyond the range of their field are refused with the member, value and range",
          "[io][document][synthesis][errors]") {
  // They were read unchecked: "swing_rad": 1e300 opened, and the designer's field showed 1e9°.
  Design d = sampleDesign();
  d.synthesis = sampleTargets();
  const std::string good = writeDocument(d);
  auto [text, expected] = GENERATE_COPY(table<std::string, std::string>({
      {replaced(good, "\"swing_rad\": 1.0471975511965976", "\"swing_rad\": 1e300"),
       "synthesis.swing.swing_rad must be finite and within ±1.7453e7 rad (1e9 degrees) (got 1e+300)"},
      {replaced(good, "\"time_ratio\": 1.3", "\"time_ratio\": -2e9"),
       "synthesis.swing.time_ratio must be finite and within ±1e9 (got -2e+09)"},
      {replaced(good, "\"length\": 50", "\"length\": 1e10"),
       "synthesis.swing.length must be finite and within ±1e9 mm (got 1e+10)"},
      {replaced(good, "\"value\": -12.5", "\"value\": 1e200"),
       "synthesis.slider.value must be finite and within ±1e9 mm"},
      {replaced(good, "\"link\": 150", "\"link\": 1e200"), "synthesis.shaper.link must be finite and within ±1e9 mm"},
      {replaced(good, "\"guide_height\": 45.857142857142854", "\"guide_height\": 1e200"),
       "synthesis.shaper.guide_height must be finite"},
      {replaced(good, "\"x1\": 2", "\"x1\": 1e300"),
       "synthesis.function.x1 must be finite and within ±1e9 (got 1e+300)"},
      {replaced(good, "\"output_span_rad\": -0.9", "\"output_span_rad\": 1e300"),
       "synthesis.function.output_span_rad must be finite"},
      {replaced(good, "\"points\": [1.1, 1.5, 1.9]", "\"points\": [1.1, 1e300, 1.9]"),
       "synthesis.function.points[1] must be finite and within ±1e9 (got 1e+300)"},
      {replaced(good, "\"frame\": 80", "\"frame\": 1e300"), "synthesis.function.frame must be finite"},
      {replaced(good, "\"x\": 10, \"y\": 5, \"angle_rad\": 0.3", "\"x\": 10, \"y\": 5, \"angle_rad\": 1e300"),
       "synthesis.motion.poses[1].angle_rad must be finite"},
      {replaced(good, "\"x\": 10, \"y\": 5", "\"x\": 10, \"y\": 5e9"),
       "synthesis.motion.poses[1].y must be finite and within ±1e9 mm (got 5e+09)"},
      {replaced(good, "\"circle_point_b\": [5, -7]", "\"circle_point_b\": [5, -7e99]"),
       "synthesis.motion.circle_point_b[1] must be finite and within ±1e9 mm (got -7e+99)"},
      {replaced(good, "\"centre_b\": -2.5", "\"centre_b\": -2.5e99"), "synthesis.motion.centre_b must be finite"},
      {replaced(good, "\"targets\": [[0, 0]", "\"targets\": [[0, 1e300]"),
       "synthesis.path.targets[0][1] must be finite and within ±1e9 mm (got 1e+300)"},
      {replaced(good, "\"timing_rad\": [0.1", "\"timing_rad\": [1e300"), "synthesis.path.timing_rad[0] must be finite"},
      {replaced(good, "\"timing_rad\": [0.1", "\"timing_rad\": [0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 0.1"),
       "synthesis.path.timing_rad must have at most 10 items (got 11)"},
      {replaced(good, "\"min_transmission_rad\": 0.5", "\"min_transmission_rad\": 1e300"),
       "synthesis.bounds.min_transmission_rad must be finite and within ±17453.29 rad (1e6 degrees) (got 1e+300)"},
      {replaced(good, "\"max_link\": 500", "\"max_link\": 0"),
       "synthesis.bounds.max_link (the longest link allowed) must be positive and finite (got 0)"},
      {replaced(good, "\"max_link\": 500", "\"max_link\": 500, \"max_ratio\": 0.5"),
       "synthesis.bounds.max_ratio must be between 1 and 1e6 (longest / shortest link; got 0.5)"},
  }));
  CAPTURE(text);
  REQUIRE(text != good);
  const auto read = readDocument(text);
  REQUIRE_FALSE(read.ok());
  CHECK_THAT(read.error().message, Catch::Contains(expected));
}

TEST_CASE("synthesis targets at the ends of their fields' ranges, and every problem's defaults, read back",
          "[io][document][synthesis]") {
  Design d = sampleDesign();
  SynthesisTargets t;  // the defaults: zero swing and strokes, no poses or targets, as the CLI saves them
  t.swing.length = -1e9;
  t.swing.swing = degToRad(-1e9);
  t.shaper.guideHeight = 1e9;
  t.bounds.minTransmission = degToRad(1e6);
  t.bounds.maxLinkRatio = 1e6;
  d.synthesis = t;
  const auto back = readDocument(writeDocument(d));
  INFO((back.ok() ? "" : back.error().message));
  REQUIRE(back.ok());
  CHECK(back->synthesis == d.synthesis);
}

TEST_CASE("bad synthesis targets are refused with the member named", "[io][document][synthesis][errors]") {
  Design d = sampleDesign();
  d.synthesis = sampleTargets();
  const std::string good = writeDocument(d);
  auto [text, expected] = GENERATE_COPY(table<std::string, std::string>({
      {replaced(good, "\"problem\": \"path\"", "\"problem\": \"cam\""),
       "synthesis.problem must be one of \"swing\", \"slider\", \"shaper\", \"function\", \"motion\", \"path\" "
       "(got \"cam\")"},
      {replaced(good, "\"time_ratio\": 1.3", "\"time_ratio\": \"fast\""),
       "synthesis.swing.time_ratio must be a number"},
      {replaced(good, "\"fixed\": \"frame\"", "\"fixed\": \"crank\""),
       "synthesis.swing.fixed must be one of \"rocker\", \"frame\" (got \"crank\")"},
      {replaced(good, "\"count\": 3", "\"count\": 2.5"), "synthesis.function.count must be a whole number from 3"},
      {replaced(good, "\"full_turn\": true,", "\"full_turn\": 1,"), "synthesis.path.full_turn must be true or false"},
      {replaced(good, "\"circle_point_a\": [-5, -5]", "\"circle_point_a\": [-5]"),
       "synthesis.motion.circle_point_a must be a pair of numbers [x, y]"},
      {replaced(good, "\"starts\": 250", "\"starts\": 0"), "synthesis.path.starts must be a whole number from 1"},
      {replaced(good, "\"targets\": [[0, 0]", "\"targets\": [[0, \"a\"]"),
       "synthesis.path.targets[0] must be a pair of numbers [x, y]"},
  }));
  CAPTURE(text);
  const auto read = readDocument(text);
  REQUIRE_FALSE(read.ok());
  CHECK_THAT(read.error().message, Catch::Contains(expected));
}
