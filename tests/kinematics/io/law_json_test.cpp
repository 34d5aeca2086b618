// Tests a design on a time base in the document (io/law_json.h, document_json.h version 4):
// every kind of motion law round-trips bit for bit, a design without a law is still written
// as version 2, and a damaged law is refused with the member named.

#include "kinematics/design/design.h"
#include "kinematics/io/document_json.h"
#include "kinematics/model/units.h"

#include "tests/support/catch.h"

#include <string>

using namespace linkwright::kinematics;
using namespace linkwright::kinematics::io;

namespace {

Design timed(MotionLaw law, double from, double to) {
  Design d = *designForExample("thesis-crank-rocker");
  d.samples = 101;
  d.time = TimeBase{std::move(law), from, to};
  return d;
}

// The document of a ramp law with `member` replaced by `value` (a fragment of its JSON).
std::string damaged(const std::string& member, const std::string& value) {
  std::string text = writeDocument(timed(RampToSpeed{0.1, rpmToRadPerSec(10.0), 2.0}, 0.0, 3.0));
  const std::size_t at = text.find("\"" + member + "\": ");
  REQUIRE(at != std::string::npos);
  const std::size_t start = at + member.size() + 4;
  const std::size_t end = text.find_first_of(",}", start);
  return text.replace(start, end - start, value);
}

}  // namespace

TEST_CASE("every motion law round-trips through the document as version 4", "[io][document][law]") {
  const std::vector<Design> designs{
      timed(ConstantVelocity{0.25, 1.0471975511965976}, 0.0, 6.0),
      timed(RampToSpeed{0.1, rpmToRadPerSec(10.0), 2.0}, 0.0, 3.0),
      timed(CycloidalRise{0.0, degToRad(90.0), 0.5}, -0.1, 0.6),
      timed(PolynomialRise{1.0, -degToRad(45.0), 0.75}, 0.0, 0.75),
      timed(makeTableLaw({0.0, 0.3, 0.7, 1.2, 2.0}, {0.0, 0.1, 0.35, 0.9, 1.7}).value(), 0.0, 2.0),
  };
  for (const Design& d : designs) {
    const std::string text = writeDocument(d);
    CAPTURE(text);
    CHECK(text.find("\"version\": 4") != std::string::npos);
    const auto back = readDocument(text);
    REQUIRE(back);
    CHECK(*back == d);
  }
  // Without a law nothing changes: version 2, no time members.
  const std::string plain = writeDocument(*designForExample("thesis-crank-rocker"));
  CHECK(plain.find("\"version\": 2") != std::string::npos);
  CHECK(plain.find("law") == std::string::npos);
  CHECK(plain.find("time_s") == std::string::npos);
}

TEST_CASE("a damaged law is refused with the member named", "[io][document][law][errors]") {
  const auto message = [](const std::string& text) { return readDocument(text).error().message; };
  CHECK_THAT(message(damaged("ramp_time_s", "-2")), Catch::Contains("driver.law.ramp_time_s must be positive"));
  std::string jerk = writeDocument(timed(RampToSpeed{0.1, 1.0, 2.0}, 0.0, 3.0));
  jerk.replace(jerk.find("\"type\": \"ramp\""), std::string("\"type\": \"ramp\"").size(), "\"type\": \"jerk\"");
  CHECK_THAT(message(jerk), Catch::Contains("driver.law.type must be \"constant\""));
  CHECK_THAT(message(damaged("velocity_rad_s", "\"fast\"")), Catch::Contains("driver.law.velocity_rad_s"));
  CHECK_THAT(message(damaged("to_time_s", "-1")), Catch::Contains("analysis.to_time_s must not be before"));
  CHECK_THAT(message(damaged("velocity_rad_s", "2e6")), Catch::Contains("driver.law's peak velocity"));
  const Design table = timed(makeTableLaw({0.0, 0.3, 0.7, 1.2}, {0.0, 0.1, 0.35, 0.9}).value(), 0.0, 1.2);
  std::string text = writeDocument(table);
  const std::size_t rows = text.find("\"time_s\": [");
  REQUIRE(rows != std::string::npos);
  text.replace(rows, std::string("\"time_s\": [0, ").size(), "\"time_s\": [");
  // Lists of different lengths are not too few rows (it said "needs at least four rows").
  CHECK(message(text) ==
        "driver.law.angle_rad has 4 values but driver.law.time_s has 3: the two lists must have the "
        "same length, one value per time");
  const std::size_t angles = text.find("\"angle_rad\": [");
  REQUIRE(angles != std::string::npos);
  text.replace(angles, std::string("\"angle_rad\": [0, ").size(), "\"angle_rad\": [");
  CHECK_THAT(message(text), Catch::Contains("driver.law") && Catch::Contains("four rows"));
  // A law whose times leave its table.
  std::string outside = writeDocument(table);
  outside.replace(outside.find("\"to_time_s\": 1.2"), std::string("\"to_time_s\": 1.2").size(), "\"to_time_s\": 5");
  CHECK_THAT(message(outside), Catch::Contains("leave the law's table"));
}
