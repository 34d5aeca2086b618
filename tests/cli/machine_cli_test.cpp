// linkwright-cli machine: a turn's duty in SI units, its energy fluctuation against an
// independent integration of analyze --forces' torque column, and the refusals (no masses, a
// driver that is not a crank, options out of range) with exit code 2, naming the option.

#include "tests/cli/csv_column.h"
#include "tests/cli/run_cli.h"

#include "tests/support/scratch_dir.h"

#include "kinematics/design/design.h"
#include "kinematics/dynamics/machine_request.h"
#include "kinematics/io/document_json.h"
#include "kinematics/io/json.h"
#include "kinematics/io/safe_file.h"

#include "tests/support/catch.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace {

using namespace linkwright;
using test::runCliCommand;

// The T_drive_Nm column of analyze --forces over one turn at `stepDeg`.
std::vector<double> torqueColumn(double stepDeg) {
  const auto r =
      runCliCommand({"analyze", "--example", "funsho-fourbar", "--forces", "--step", std::to_string(stepDeg)});
  REQUIRE(r.code == 0);
  return test::csvColumn(r.out, "T_drive_Nm");
}

}  // namespace

TEST_CASE("machine --json gives the turn's duty in SI units", "[cli][machine]") {
  const auto r = runCliCommand({"machine", "--example", "funsho-fourbar", "--samples", "1441", "--cs", "0.05",
                                "--gear-ratio", "10", "--efficiency", "0.9", "--json"});
  INFO(r.err);
  REQUIRE(r.code == 0);
  const auto json = kinematics::io::parseJson(r.out).value();
  for (const char* key :
       {"energy_fluctuation_J", "flywheel_inertia_kg_m2", "textbook_flywheel_inertia_kg_m2", "rms_torque_Nm",
        "peak_torque_Nm", "mean_power_W", "peak_power_W", "shaking_force_peak_N", "shaking_moment_peak_Nm"}) {
    CAPTURE(key);
    REQUIRE(json.contains(key));
    CHECK(json[key].get<double>() >= 0.0);
  }
  CHECK(json["omega_rad_s"] == 100.0);
  CHECK(json["samples"] == 1441);
  CHECK(json["converged"] == true);
  CHECK(json["motor"]["speed_rad_s"].get<double>() == Approx(1000.0));
  // Each figure says its error, the motor's under "motor.".
  CHECK(json["accuracy"]["energy_fluctuation_J"].get<double>() < 1e-9);
  CHECK(json["accuracy"]["motor.rms_torque_Nm"].get<double>() < 1e-9);

  // An independent integration of analyze --forces' torque column at 0.25°, by Simpson's rule:
  // the surplus E(θ) = ∫(T̄ − T) dθ and its range ΔE; the RMS and the peak of the same column.
  const std::vector<double> t = torqueColumn(0.25);
  REQUIRE(t.size() == 1441);
  const double h = 0.25 * M_PI / 180.0;
  double mean = 0.0, square = 0.0, peak = 0.0;
  for (std::size_t i = 0; i + 2 < t.size(); i += 2) {
    mean += h / 3.0 * (t[i] + 4.0 * t[i + 1] + t[i + 2]);
    square += h / 3.0 * (t[i] * t[i] + 4.0 * t[i + 1] * t[i + 1] + t[i + 2] * t[i + 2]);
  }
  mean /= 2.0 * M_PI;
  square /= 2.0 * M_PI;
  double energy = 0.0, low = 0.0, high = 0.0;
  for (std::size_t i = 0; i + 2 < t.size(); i += 2) {
    // E at the odd sample by the half-interval Simpson weights, then at the next even one.
    const double mid = energy + h / 12.0 * (5.0 * (mean - t[i]) + 8.0 * (mean - t[i + 1]) - (mean - t[i + 2]));
    energy += h / 3.0 * ((mean - t[i]) + 4.0 * (mean - t[i + 1]) + (mean - t[i + 2]));
    low = std::min({low, mid, energy});
    high = std::max({high, mid, energy});
  }
  for (const double v : t) peak = std::max(peak, std::abs(v));
  // Simpson's E read at its samples (within (0.25°)² of its extremes) and the best sample fall
  // short of the refined figures, which are exact.
  CHECK(json["energy_fluctuation_J"].get<double>() == Approx(high - low).epsilon(1e-4));
  CHECK(json["energy_fluctuation_J"].get<double>() >= high - low);
  CHECK(json["rms_torque_Nm"].get<double>() == Approx(std::sqrt(square)).epsilon(1e-9));
  CHECK(json["peak_torque_Nm"].get<double>() == Approx(peak).epsilon(1e-5));
  CHECK(json["peak_torque_Nm"].get<double>() >= peak);
  // No loads and no gravity: the linkage gives back all it takes, and the mean is 0.
  CHECK(json["mean_torque_Nm"] == 0.0);
  CHECK(std::abs(mean) < 1e-9 * peak);
  // Virtual work and Newton–Euler agree to round-off of the peak torque.
  CHECK(json["virtual_work_difference_Nm"].get<double>() <= 1e-9 * json["peak_torque_Nm"].get<double>());
  // The flywheel that counts the linkage's own inertia is lighter than the textbook's.
  CHECK(json["flywheel_inertia_kg_m2"].get<double>() < json["textbook_flywheel_inertia_kg_m2"].get<double>());
  CHECK(json["textbook_flywheel_inertia_kg_m2"].get<double>() ==
        Approx(json["energy_fluctuation_J"].get<double>() / (0.05 * 100.0 * 100.0)));
  // The forward-dynamics check: the speed varies by the Cs asked, within 2 %.
  CHECK(json["cs_by_forward_dynamics"].get<double>() == Approx(0.05).epsilon(0.02));
}

TEST_CASE("machine prints its figures for reading, with a motor verdict", "[cli][machine]") {
  const auto r = runCliCommand({"machine", "--example", "funsho-fourbar", "--cs", "0.02", "--gear-ratio", "10",
                                "--rated-torque", "0.01", "--rated-speed", "12000"});
  INFO(r.err);
  REQUIRE(r.code == 0);
  // The core chooses the grid (not the example's 5° step) and says how exact the figures are.
  CHECK(r.out.find("one crank turn at 100 rad/s (954.92966 rpm), read at 361 samples; every figure within 1e-9 "
                   "relative") != std::string::npos);
  CHECK(r.out.find("  driving torque, mean                         0 N·m\n") != std::string::npos);
  CHECK(r.out.find("  flywheel for Cs 0.02 ") != std::string::npos);
  const std::string run =
      "flywheel check      a turn run in time with that flywheel and the mean torque: the speed "
      "varies by Cs ";
  const std::size_t at = r.out.find(run);
  REQUIRE(at != std::string::npos);
  CHECK(std::stod(r.out.substr(at + run.size())) == Approx(0.02).epsilon(0.02));
  CHECK(r.out.find("motor verdict       too weak: RMS torque") != std::string::npos);
  CHECK(r.out.find("nan") == std::string::npos);
}

TEST_CASE("machine refuses what it cannot compute, naming the option", "[cli][machine]") {
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
      {{"machine", "--example", "thesis-crank-rocker"},
       "machine needs masses and loads, and the example thesis-crank-rocker has none"},
      {{"machine"}, "machine needs FILE.json or --example NAME: a linkage with its masses"},
      {{"machine", "--example", "funsho-fourbar", "--cs", "0"}, "--cs must be from 1e-5 to 0.9 (got 0)"},
      {{"machine", "--example", "funsho-fourbar", "--efficiency", "1.2"},
       "--efficiency must be from 0.01 to 1 (got 1.2)"},
      {{"machine", "--example", "funsho-fourbar", "--efficiency", "5e-324"},
       "--efficiency must be from 0.01 to 1 (got 5e-324)"},
      {{"machine", "--example", "funsho-fourbar", "--gear-ratio", "-3"},
       "--gear-ratio must be from 1e-6 to 1e6 (got -3)"},
      {{"machine", "--example", "funsho-fourbar", "--rated-speed", "0"},
       "--rated-speed must be above 0 and at most 1e7 rpm (got 0 rpm)"},
      {{"machine", "--example", "funsho-fourbar", "--rated-torque", "1e306"},
       "--rated-torque must be above 0 and at most 1e9 N·m (got 1e+306 N·m)"},
      {{"machine", "--example", "funsho-fourbar", "--samples", "3"},
       "--samples must be a whole number from 4 to 100000 (got 3)"},
      {{"machine", "--example", "funsho-fourbar", "--samples", "10000000"},
       "--samples must be a whole number from 4 to 100000 (got 10000000)"},
      {{"machine", "--example", "funsho-fourbar", "--samples", "x"}, "--samples: 'x' is not a whole number"},
      {{"machine", "--example", "funsho-fourbar", "--omega", "0"},
       "--omega must be from -900000 to 900000 rad/s, not 0 (got 0 rad/s)"},
      {{"machine", "--example", "funsho-fourbar", "--rpm", "10", "--omega", "1"},
       "--rpm and --omega are one speed: give one of them"},
      {{"machine", "--example", "funsho-fourbar", "--tolerance", "1"},
       "--tolerance must be from 1e-12 to 0.01 (got 1)"},
      {{"machine", "--example", "seed-arm"}, "a flywheel, a motor and a turn's torque need a crank"},
      {{"machine", "--example", "excavator-boom", "--rpm", "10"},
       "a flywheel, a motor and a turn's torque need a crank: this linkage is driven by its actuator"},
      {{"machine", "--example", "funsho-fourbar", "--forces"}, "unknown option '--forces' for 'machine'"},
  };
  for (const auto& [args, message] : cases) {
    CAPTURE(args);
    const auto r = runCliCommand(args);
    CHECK(r.code == 2);
    CHECK(r.out.empty());
    CHECK(r.err.find(message) != std::string::npos);
    CHECK(r.err.find("nan") == std::string::npos);
  }
}

TEST_CASE("machine on a document reads the turn at the core's grid, whatever the document's grid", "[cli][machine]") {
  // A design saved with a grid of 2 samples, or of 10⁷: machine never works its turn out of
  // them (it once blamed "--samples (got 2)", which was never given).
  const auto dir = test::scratchDir("machine-grid");
  kinematics::Design design = *kinematics::designForExample("funsho-fourbar");
  std::string reference;
  for (const std::size_t samples : {std::size_t{2}, std::size_t{10'000'000}, std::size_t{721}}) {
    CAPTURE(samples);
    design.samples = samples;
    const std::string path = (dir / ("grid-" + std::to_string(samples) + ".linkwright")).string();
    REQUIRE_FALSE(kinematics::io::writeFileSafely(path, kinematics::io::writeDocument(design)));
    const auto r = runCliCommand({"machine", path, "--cs", "0.05", "--json"});
    INFO(r.err);
    REQUIRE(r.code == 0);
    auto json = kinematics::io::parseJson(r.out).value();
    CHECK(json["samples"] == 361);
    CHECK(json["converged"] == true);
    json.erase("samples");
    if (reference.empty()) reference = json.dump();
    CHECK(json.dump() == reference);
  }
  std::filesystem::remove_all(dir);
}

TEST_CASE("machine's help lists every field of the core's request with its range and default", "[cli][machine]") {
  const auto r = runCliCommand({"machine", "--help"});
  REQUIRE(r.code == 0);
  for (const auto& field : kinematics::machineFields()) {
    CAPTURE(field.key);
    CHECK(r.out.find("  " + kinematics::fieldName(field, kinematics::FrontEnd::Cli) + " ") != std::string::npos);
    // The help may wrap: compare with the spaces folded.
    std::string folded, expected = kinematics::helpText(field);
    for (std::size_t i = 0; i < r.out.size(); ++i) {
      if (r.out[i] == '\n' || r.out[i] == ' ') {
        if (!folded.empty() && folded.back() != ' ') folded += ' ';
      } else folded += r.out[i];
    }
    CHECK(folded.find(expected) != std::string::npos);
  }
}
