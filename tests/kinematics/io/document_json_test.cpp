// Linkwright documents: save → open reproduces the design exactly; every malformed, invalid,
// foreign or newer file is refused with a message naming the member.

#include "kinematics/io/document_json.h"
#include "kinematics/model/examples.h"

#include <catch2/catch.hpp>

#include <string>

using namespace linkwright::kinematics;
using namespace linkwright::kinematics::io;

namespace {

FourBarDesign sampleDesign() {
  FourBarDesign d;
  d.lengths = {60.0, 25.0, 70.0, 45.0};
  d.lengthUnit = "mm";
  d.branch = Branch::Crossed;
  d.couplerPoint = CouplerPointSpec{35.0, -20.25};
  d.omega = 1.0471975511965976;  // 10 rpm: not a short decimal, so the round trip is tested
  d.alpha = 0.1;
  d.fromDeg = -30.0;
  d.toDeg = 330.0;
  d.samples = 1441;
  return d;
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

} // namespace

TEST_CASE("a document round-trips every field exactly", "[io][document]") {
  const FourBarDesign d = sampleDesign();
  const std::string text = writeDocument(d);
  const auto back = readDocument(text);
  REQUIRE(back.ok());
  CHECK(*back == d);
  CHECK(writeDocument(*back) == text);

  FourBarDesign plain = d;
  plain.couplerPoint.reset();
  const auto plainBack = readDocument(writeDocument(plain));
  REQUIRE(plainBack.ok());
  CHECK(*plainBack == plain);
}

TEST_CASE("every built-in example round-trips", "[io][document]") {
  for (const FourBarExample& e : fourBarExamples()) {
    CAPTURE(e.name);
    const FourBarDesign d = designFromExample(e);
    REQUIRE_FALSE(checkDesign(d).has_value());
    const auto back = readDocument(writeDocument(d));
    REQUIRE(back.ok());
    CHECK(*back == d);
  }
}

TEST_CASE("the document text is what the format note says", "[io][document]") {
  const std::string text = writeDocument(sampleDesign());
  CHECK_THAT(text, Catch::StartsWith("{\n  \"format\": \"linkwright\",\n  \"version\": 1,"));
  CHECK_THAT(text, Catch::Contains("\"lengths\": {\"frame\": 60, \"crank\": 25, \"coupler\": 70, \"rocker\": 45}"));
  CHECK_THAT(text, Catch::Contains("\"omega_rad_s\": 1.0471975511965976"));
}

TEST_CASE("bad documents are refused with the member named", "[io][document][errors]") {
  const std::string good = writeDocument(sampleDesign());
  auto [text, expected] = GENERATE_COPY(table<std::string, std::string>({
      {"not json", "not valid JSON: line 1, column 1"},
      {"[1, 2]", "document must be a JSON object"},
      {replaced(good, "\"linkwright\"", "\"solvespace\""), "not a Linkwright document"},
      {replaced(good, "\"version\": 1", "\"version\": 7"),
       "this file is document version 7, written by a newer Linkwright; this one reads up to version 1"},
      {replaced(good, "\"version\": 1", "\"version\": 1.5"), "version must be a whole number"},
      {replaced(good, "\"version\": 1", "\"version\": \"1\""), "version must be a number"},
      {replaced(good, "\"four-bar\"", "\"six-bar\""), "mechanism.type must be \"four-bar\" (got \"six-bar\")"},
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

TEST_CASE("unknown members are ignored, so minor additions stay readable", "[io][document]") {
  const std::string text = replaced(writeDocument(sampleDesign()), "\"version\": 1,", "\"version\": 1,\n  \"comment\": {\"x\": [1]},");
  const auto d = readDocument(text);
  REQUIRE(d.ok());
  CHECK(*d == sampleDesign());
}
