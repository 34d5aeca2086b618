// Tests kinematics/io/csv_writer.h: the exact header for each request, CRLF line ends, cells
// that read back to the sweep's doubles, rows left out where the linkage does not assemble,
// empty rate cells at a toggle, RFC 4180 quoting, and output independent of the locale.

#include "kinematics/io/csv_writer.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/sweep.h"

#include "tests/support/approx.h"

#include "tests/support/catch.h"

#include <bit>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <locale>
#include <sstream>
#include <string>
#include <vector>

using namespace linkwright::kinematics;
using linkwright::test::kThesis;

namespace {

const std::vector<std::string> kThesisHeader{"crank_angle_deg",
                                             "crank_omega_rad_s",
                                             "crank_alpha_rad_s2",
                                             "coupler_angle_deg",
                                             "coupler_omega_rad_s",
                                             "coupler_alpha_rad_s2",
                                             "rocker_angle_deg",
                                             "rocker_omega_rad_s",
                                             "rocker_alpha_rad_s2",
                                             "transmission_angle_deg",
                                             "B_x_mm",
                                             "B_y_mm",
                                             "B_vx_mm_s",
                                             "B_vy_mm_s",
                                             "B_ax_mm_s2",
                                             "B_ay_mm_s2",
                                             "C_x_mm",
                                             "C_y_mm",
                                             "C_vx_mm_s",
                                             "C_vy_mm_s",
                                             "C_ax_mm_s2",
                                             "C_ay_mm_s2"};

Mechanism fourBar(const FourBarLengths& lengths) {
  const auto m = makeFourBar(lengths, Branch::Open);
  REQUIRE(m.ok());
  return *m;
}

SweepResult run(const Mechanism& m, const SweepSpec& spec, const SolveRequest& request = {}) {
  auto r = sweep(m, spec, request);
  REQUIRE(r.ok());
  return *r;
}

std::string csv(const Mechanism& m, const SweepResult& r) {
  std::ostringstream out;
  io::writeSweepCsv(out, m, r);
  return out.str();
}

// Splits CRLF-terminated lines; fails on a bare LF or a missing final CRLF.
std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t lf = text.find('\n', start);
    REQUIRE(lf != std::string::npos);
    REQUIRE(lf > start);
    REQUIRE(text[lf - 1] == '\r');
    out.push_back(text.substr(start, lf - 1 - start));
    start = lf + 1;
  }
  return out;
}

std::vector<std::string> cells(const std::string& line) {
  std::vector<std::string> out(1);
  for (const char c : line) {
    if (c == ',') out.emplace_back();
    else out.back() += c;
  }
  return out;
}

double parse(const std::string& text) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  REQUIRE(end == text.c_str() + text.size());
  return value;
}

// The cell reads back to exactly `expected`; −0 is written as "0", so compare it as +0.
bool readsBackAs(const std::string& cell, double expected) {
  return std::bit_cast<std::uint64_t>(parse(cell)) == std::bit_cast<std::uint64_t>(expected == 0.0 ? 0.0 : expected);
}

struct CommaDecimal : std::numpunct<char> {
  char do_decimal_point() const override { return ','; }
};

}  // namespace

TEST_CASE("sweepCsvHeader names every column with its unit", "[csv_writer]") {
  const Mechanism m = fourBar(kThesis);
  CHECK(io::sweepCsvHeader(m, {}) == kThesisHeader);
  CHECK(io::sweepCsvHeader(m, {false, false}) == std::vector<std::string>{"crank_angle_deg", "coupler_angle_deg",
                                                                          "rocker_angle_deg", "transmission_angle_deg",
                                                                          "B_x_mm", "B_y_mm", "C_x_mm", "C_y_mm"});
  CHECK(io::sweepCsvHeader(m, {true, false}) ==
        std::vector<std::string>{"crank_angle_deg", "crank_omega_rad_s", "coupler_angle_deg", "coupler_omega_rad_s",
                                 "rocker_angle_deg", "rocker_omega_rad_s", "transmission_angle_deg", "B_x_mm", "B_y_mm",
                                 "B_vx_mm_s", "B_vy_mm_s", "C_x_mm", "C_y_mm", "C_vx_mm_s", "C_vy_mm_s"});
  const auto withPoint = makeFourBar(kThesis, Branch::Open, "in", CouplerPointSpec{10.0, 5.0});
  REQUIRE(withPoint.ok());
  const std::vector<std::string> header = io::sweepCsvHeader(*withPoint, {});
  REQUIRE(header.size() == kThesisHeader.size() + 6);
  CHECK(header[10] == "B_x_in");
  CHECK(header[21] == "C_ay_in_s2");
  CHECK(std::vector<std::string>(header.end() - 6, header.end()) ==
        std::vector<std::string>{"P_x_in", "P_y_in", "P_vx_in_s", "P_vy_in_s", "P_ax_in_s2", "P_ay_in_s2"});
}

TEST_CASE("writeSweepCsv: CRLF rows whose cells read back to the sweep's doubles", "[csv_writer]") {
  const Mechanism m = fourBar(kThesis);
  const SweepResult r = run(m, {0.0, 2.0 * kPi, 13, rpmToRadPerSec(10.0), 0.3});
  const std::string text = csv(m, r);
  const std::vector<std::string> rows = lines(text);
  REQUIRE(rows.size() == 14);
  CHECK(rows[0] ==
        "crank_angle_deg,crank_omega_rad_s,crank_alpha_rad_s2,coupler_angle_deg,coupler_omega_rad_s,"
        "coupler_alpha_rad_s2,rocker_angle_deg,rocker_omega_rad_s,rocker_alpha_rad_s2,"
        "transmission_angle_deg,B_x_mm,B_y_mm,B_vx_mm_s,B_vy_mm_s,B_ax_mm_s2,B_ay_mm_s2,C_x_mm,C_y_mm,"
        "C_vx_mm_s,C_vy_mm_s,C_ax_mm_s2,C_ay_mm_s2");
  const std::size_t crank = fourbar::kCrank.index, coupler = fourbar::kCoupler.index, rocker = fourbar::kRocker.index;
  for (std::size_t j = 0; j < r.size(); ++j) {
    CAPTURE(j, rows[j + 1]);
    const std::vector<std::string> c = cells(rows[j + 1]);
    REQUIRE(c.size() == kThesisHeader.size());
    // The grid column prints 12 significant digits ("30", not 29.999999999999996).
    CHECK(c[0] == std::to_string(30 * j));
    const std::vector<double> expected{
        r.linkOmega[crank][j],   r.linkAlpha[crank][j],   radToDeg(r.linkAngle[coupler][j]),
        r.linkOmega[coupler][j], r.linkAlpha[coupler][j], radToDeg(r.linkAngle[rocker][j]),
        r.linkOmega[rocker][j],  r.linkAlpha[rocker][j],  radToDeg(r.transmissionAngle[fourbar::kC.index][j])};
    for (std::size_t k = 0; k < expected.size(); ++k) CHECK(readsBackAs(c[k + 1], expected[k]));
    for (const std::size_t point : {fourbar::kB.index, fourbar::kC.index}) {
      const std::size_t first = point == fourbar::kB.index ? 10 : 16;
      const Eigen::Vector2d values[] = {r.position[point][j], r.velocity[point][j], r.acceleration[point][j]};
      for (std::size_t k = 0; k < 6; ++k) {
        CHECK(readsBackAs(c[first + k], values[k / 2][static_cast<Eigen::Index>(k % 2)]));
      }
    }
  }
}

TEST_CASE("writeSweepCsv: a positions-only sweep has no rate columns", "[csv_writer]") {
  const Mechanism m = fourBar(kThesis);
  const SweepResult r = run(m, {0.0, kPi, 7, 1.0, 0.0}, {false, false});
  const std::vector<std::string> rows = lines(csv(m, r));
  REQUIRE(rows.size() == 8);
  CHECK(rows[0] ==
        "crank_angle_deg,coupler_angle_deg,rocker_angle_deg,transmission_angle_deg,B_x_mm,B_y_mm,"
        "C_x_mm,C_y_mm");
  for (std::size_t j = 1; j < rows.size(); ++j) CHECK(cells(rows[j]).size() == 8);
}

TEST_CASE("writeSweepCsv leaves out samples that cannot be assembled", "[csv_writer]") {
  // Triple-rocker 60/50/35/40 assembles only for |θ| ≤ 85.46°.
  const Mechanism m = fourBar({60.0, 50.0, 35.0, 40.0});
  const SweepResult r = run(m, {0.0, 2.0 * kPi, 37, 1.0, 0.0});
  const std::vector<std::string> rows = lines(csv(m, r));
  std::vector<std::string> angles;
  for (std::size_t j = 1; j < rows.size(); ++j) angles.push_back(cells(rows[j])[0]);
  CHECK(angles == std::vector<std::string>{"0", "10", "20", "30", "40", "50", "60", "70", "80", "280", "290", "300",
                                           "310", "320", "330", "340", "350", "360"});
  CHECK(csv(m, r).find("nan") == std::string::npos);
}

TEST_CASE("writeSweepCsv leaves the rate cells empty at a toggle", "[csv_writer]") {
  // Parallelogram 60/25/60/25: toggles at θ = 0, π, 2π (exact samples).
  const Mechanism m = fourBar({60.0, 25.0, 60.0, 25.0});
  const SweepResult r = run(m, {0.0, 2.0 * kPi, 5, 1.0, 0.0});
  const std::vector<std::string> rows = lines(csv(m, r));
  REQUIRE(rows.size() == 6);
  const std::vector<std::string> header = cells(rows[0]);
  for (std::size_t j = 1; j < rows.size(); ++j) {
    const bool singular = j % 2 == 1;  // samples 0, 2 and 4
    CAPTURE(rows[j]);
    const std::vector<std::string> c = cells(rows[j]);
    REQUIRE(c.size() == header.size());
    for (std::size_t k = 0; k < c.size(); ++k) {
      CAPTURE(header[k]);
      // Rates are the columns per second: rad_s, rad_s2, mm_s, mm_s2.
      const bool rate = header[k].ends_with("_s") || header[k].ends_with("_s2");
      CHECK(c[k].empty() == (singular && rate));
    }
  }
  CHECK(csv(m, r).find("nan") == std::string::npos);
}

TEST_CASE("writeSweepCsv writes a value that is still not finite as an empty cell", "[csv_writer]") {
  // The last guard: whatever let a non-finite number into a sweep, the CSV never says nan or inf.
  const Mechanism m = fourBar(kThesis);
  SweepResult r = run(m, {0.0, kPi, 3, 1.0, 0.0});
  r.linkOmega[fourbar::kCoupler.index][1] = std::numeric_limits<double>::quiet_NaN();
  r.acceleration[fourbar::kC.index][1].x() = -std::numeric_limits<double>::infinity();
  const std::string text = csv(m, r);
  CHECK(text.find("nan") == std::string::npos);
  CHECK(text.find("inf") == std::string::npos);
  const std::vector<std::string> header = cells(lines(text)[0]);
  const std::vector<std::string> row = cells(lines(text)[2]);
  REQUIRE(row.size() == header.size());
  for (std::size_t k = 0; k < row.size(); ++k) {
    CAPTURE(header[k]);
    CHECK(row[k].empty() == (header[k] == "coupler_omega_rad_s" || header[k] == "C_ax_mm_s2"));
  }
}

TEST_CASE("csvField quotes per RFC 4180 only where needed", "[csv_writer]") {
  CHECK(io::csvField("rocker_angle_deg") == "rocker_angle_deg");
  CHECK(io::csvField("a,b") == "\"a,b\"");
  CHECK(io::csvField("say \"hi\"") == "\"say \"\"hi\"\"\"");
  CHECK(io::csvField("two\nlines") == "\"two\nlines\"");
  CHECK(io::csvField("cr\r") == "\"cr\r\"");
  CHECK(io::csvField("") == "");

  Mechanism m = fourBar(kThesis);
  m.links[fourbar::kRocker.index].name = "out,put";
  const SweepResult r = run(m, {0.0, 1.0, 2, 1.0, 0.0}, {false, false});
  CHECK(lines(csv(m, r))[0] ==
        "crank_angle_deg,coupler_angle_deg,\"out,put_angle_deg\",transmission_angle_deg,"
        "B_x_mm,B_y_mm,C_x_mm,C_y_mm");
}

TEST_CASE("writeSweepCsv output does not depend on the locale", "[csv_writer]") {
  const Mechanism m = fourBar(kThesis);
  const SweepResult r = run(m, {0.0, 2.0 * kPi, 25, 1.5, -0.25});
  const std::string reference = csv(m, r);
  REQUIRE(reference.find('.') != std::string::npos);

  // No locale with a decimal comma is installed here, so make one: global and on the stream.
  const std::locale comma(std::locale::classic(), new CommaDecimal);
  const std::locale previous = std::locale::global(comma);
  std::ostringstream out;
  out.imbue(comma);
  out << 0.5;  // the facet is live: this writes "0,5"
  const std::string probe = out.str();
  out.str("");
  io::writeSweepCsv(out, m, r);
  const std::string localized = out.str();
  std::locale::global(previous);
  CHECK(probe == "0,5");
  CHECK(localized == reference);
}
