// The "dynamics" member of a document (dynamics_json.h): masses and loads round-trip exactly,
// a design with them is written as version 3 and one without as version 2, version 2 files
// still open, and bad values are refused naming the document member.

#include "kinematics/io/dynamics_json.h"
#include "kinematics/design/design.h"
#include "kinematics/design/examples.h"
#include "kinematics/io/document_json.h"

#include "tests/kinematics/dynamics/dynamics_cases.h"

#include "tests/support/catch.h"

#include <limits>
#include <string>

using namespace linkwright::kinematics;
using namespace linkwright::kinematics::io;

namespace {

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

}  // namespace

TEST_CASE("dynamics round-trip exactly in a document, for every kind of linkage", "[io][document][dynamics]") {
  for (const auto& c : linkwright::test::dynamicsCases()) {
    CAPTURE(c.name);
    Design d;
    d.kind = c.name;
    d.mechanism = c.mechanism;
    d.dynamics = c.dynamics;
    REQUIRE_FALSE(checkDesign(d).has_value());
    const std::string text = writeDocument(d);
    CHECK_THAT(text, Catch::Contains("\"version\": 3,"));
    const auto back = readDocument(text);
    INFO((back.ok() ? std::string() : back.error().message));
    REQUIRE(back.ok());
    CHECK(*back == d);
    CHECK(writeDocument(*back) == text);
  }
}

TEST_CASE("funsho-fourbar's document holds its masses in the documented form", "[io][document][dynamics]") {
  const auto design = designForExample("funsho-fourbar");
  REQUIRE(design.has_value());
  const std::string text = writeDocument(*design);
  CHECK_THAT(text, Catch::StartsWith("{\n  \"format\": \"linkwright\",\n  \"version\": 3,"));
  CHECK_THAT(
      text,
      Catch::EndsWith(
          "  \"analysis\": {\"from_deg\": 0, \"to_deg\": 360, \"samples\": 721},\n"
          "  \"dynamics\": {\n"
          "    \"links\": {\n"
          "      \"crank\": {\"mass_kg\": 0.2, \"centre\": {\"along\": 5, \"across\": 0}, \"inertia_kg_m2\": 1e-05},\n"
          "      \"coupler\": {\"mass_kg\": 0.6, \"centre\": {\"along\": 17.5, \"across\": 0}, \"inertia_kg_m2\": "
          "4e-04},\n"
          "      \"rocker\": {\"mass_kg\": 0.4, \"centre\": {\"along\": 10, \"across\": 0}, \"inertia_kg_m2\": 8e-05}\n"
          "    }\n"
          "  }\n"
          "}\n"));
  const auto back = readDocument(text);
  REQUIRE(back.ok());
  CHECK(*back == *design);
}

TEST_CASE("a design without dynamics is still a version 2 document, and version 2 reads",
          "[io][document][dynamics][migration]") {
  const auto design = designForExample("thesis-crank-rocker");
  REQUIRE(design.has_value());
  const std::string text = writeDocument(*design);
  CHECK_THAT(text, Catch::Contains("\"version\": 2,"));
  CHECK_THAT(text, !Catch::Contains("dynamics"));
  const auto back = readDocument(text);
  REQUIRE(back.ok());
  CHECK(back->dynamics.empty());
  CHECK(*back == *design);
}

TEST_CASE("defaults are left out and read back as defaults", "[io][document][dynamics]") {
  Design d;
  d.kind = "slider-crank";
  d.mechanism = makeSliderCrank(kLs3Engine).value();
  d.dynamics.links = {{"rod", 0.6, std::nullopt, std::nullopt}};
  d.dynamics.sliders = {{"C", 0, 0.5, 0.0}};
  const std::string text = writeDocument(d);
  CHECK_THAT(text, Catch::Contains("\"rod\": {\"mass_kg\": 0.6}"));
  CHECK_THAT(text, Catch::Contains("{\"point\": \"C\", \"mass_kg\": 0.5, \"inertia_kg_m2\": 0}"));
  CHECK_THAT(text, !Catch::Contains("gravity"));
  const auto back = readDocument(text);
  REQUIRE(back.ok());
  CHECK(*back == d);
}

TEST_CASE("bad dynamics are refused naming the document member", "[io][document][dynamics][errors]") {
  const std::string good = writeDocument(*designForExample("funsho-fourbar"));
  auto [text, expected] = GENERATE_COPY(table<std::string, std::string>({
      {replaced(good, "\"mass_kg\": 0.6", "\"mass_kg\": -0.6"),
       "dynamics.links.coupler.mass_kg must be between 0 and 1e9 kg (got -0.6)"},
      {replaced(good, "\"mass_kg\": 0.6", "\"mass_kg\": \"heavy\""), "dynamics.links.coupler.mass_kg must be a number"},
      {replaced(good, "\"mass_kg\": 0.6, ", ""), "dynamics.links.coupler.mass_kg is missing"},
      {replaced(good, "\"inertia_kg_m2\": 8e-05", "\"inertia_kg_m2\": -8e-05"),
       "dynamics.links.rocker.inertia_kg_m2 must be between 0 and 1e27 kg·m² (got -8e-05)"},
      {replaced(good, "\"coupler\": {", "\"bar\": {"),
       "dynamics.links.bar names no link of this mechanism (got \"bar\")"},
      {replaced(good, "\"links\": {", "\"links\": ["), "not valid JSON"},
      {replaced(good, "\"links\": {\n", "\"sliders\": [{\"point\": \"C\", \"mass_kg\": 1}],\n    \"links\": {\n"),
       "dynamics.sliders[0].point must name a slider's point (an rrp, rpr or prp point; got \"C\")"},
      {replaced(good, "\"links\": {\n", "\"torques\": [{\"link\": \"rocker\"}],\n    \"links\": {\n"),
       "dynamics.torques[0].torque_N_m is missing"},
      {replaced(
           good, "\"links\": {\n",
           "\"forces\": [{\"link\": \"coupler\", \"point\": \"O4\", \"x_N\": 1, \"y_N\": 0}],\n    \"links\": {\n"),
       "dynamics.forces[0].point must lie on the body of link coupler (got \"O4\")"},
      {replaced(good, "\"links\": {\n", "\"gravity_m_s2\": {\"x\": 0},\n    \"links\": {\n"),
       "dynamics.gravity_m_s2.y is missing"},
  }));
  const auto read = readDocument(text);
  REQUIRE_FALSE(read.ok());
  CHECK_THAT(read.error().message, Catch::StartsWith(expected));
}

TEST_CASE("checkDocumentDynamics maps every checkDynamics field to its member", "[io][dynamics]") {
  const Mechanism yoke = linkwright::test::prpYoke();
  LinkageDynamics d;
  d.loads.forces = {{"", "C", 3, Eigen::Vector2d(1.0, 0.0)}};
  auto e = checkDocumentDynamics(yoke, d);
  REQUIRE(e.has_value());
  CHECK(e->field == "dynamics.forces[0].guide");
  CHECK(e->message == "dynamics.forces[0].guide must be 0 or 1 for C (got 3)");
  d.loads.forces = {{"", "Q", 0, Eigen::Vector2d(1.0, 0.0)}};
  e = checkDocumentDynamics(yoke, d);
  REQUIRE(e.has_value());
  CHECK(e->message == "dynamics.forces[0].slider names no point of this mechanism (got \"Q\")");
  d.loads.forces = {{"crank", "B", 0, Eigen::Vector2d(0.0, std::numeric_limits<double>::infinity())}};
  e = checkDocumentDynamics(yoke, d);
  REQUIRE(e.has_value());
  CHECK(e->message == "dynamics.forces[0].y_N must be finite and within ±1e24 N (got undefined)");
}

TEST_CASE("springs round-trip as version 7, and a bad one is refused naming its member", "[io][document][springs]") {
  Design d = *designForExample("funsho-fourbar");
  d.mechanism.points.push_back({"S", GroundPoint{Eigen::Vector2d(-10.0, 25.0)}});
  d.dynamics.loads.springs = {{"lift", {"rocker", "C"}, {"", "S"}, 2400.0, 12.5, -3.0},
                              {"", {"crank", "B"}, {"coupler", "C"}, 0.5, 0.0, 0.0}};
  REQUIRE_FALSE(checkDesign(d).has_value());
  const std::string text = writeDocument(d);
  CHECK_THAT(text, Catch::Contains("\"version\": 7,"));
  CHECK_THAT(text, Catch::Contains("\"springs\": [\n      {\"name\": \"lift\", \"first\": {\"link\": \"rocker\", "
                                   "\"point\": \"C\"}, \"second\": {\"point\": \"S\"}, \"stiffness_N_m\": 2400, "
                                   "\"free_length\": 12.5, \"preload_N\": -3}"));
  const auto back = readDocument(text);
  INFO((back.ok() ? std::string() : back.error().message));
  REQUIRE(back.ok());
  CHECK(*back == d);
  CHECK(writeDocument(*back) == text);
  const auto bad = readDocument(replaced(text, "\"stiffness_N_m\": 2400", "\"stiffness_N_m\": -5"));
  REQUIRE_FALSE(bad.ok());
  CHECK(bad.error().message == "dynamics.springs[0].stiffness_N_m must be between 0 and 1e15 N/m (got -5)");
  const auto ground = readDocument(replaced(text, "\"second\": {\"point\": \"S\"}", "\"second\": {\"point\": \"C\"}"));
  REQUIRE_FALSE(ground.ok());
  CHECK(ground.error().message ==
        "dynamics.springs[0].second.point must be a ground point for an end on the frame (got \"C\")");
}
