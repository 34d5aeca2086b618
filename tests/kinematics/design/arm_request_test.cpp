// The arm's run streams its rows: windows of bounded size, in order, the same rows and notes
// as the run that keeps them, and the counts its notes give gathered over every window.

#include "kinematics/design/arm_request.h"

#include "kinematics/io/arm_table.h"
#include "kinematics/solve/sweep.h"

#include "tests/support/catch.h"

#include <sstream>

namespace k = linkwright::kinematics;

TEST_CASE("the arm's rows stream in bounded windows, the same as the rows kept whole", "[arm]") {
  k::ArmRequest request;
  request.example = "seed-arm";
  request.toPoint = Eigen::Vector2d(0.9, 0.6);  // past the reach of the seed's 0.7 m arm
  request.samples = 20001;
  const auto kept = k::runArm(request);
  REQUIRE(kept);
  REQUIRE(kept->rows.size() == 20001);
  std::size_t windows = 0, largest = 0, rows = 0;
  double lastTime = -1.0;
  bool inOrder = true, allCounted = true;
  std::ostringstream streamed;
  k::io::ArmTableWriter writer(streamed, "m", false);
  const auto run = k::runArm(request, [&](const std::vector<k::ArmRow>& window, std::size_t rowsInAll) {
    ++windows;
    allCounted = allCounted && rowsInAll == 20001;
    largest = std::max(largest, window.size());
    for (const k::ArmRow& row : window) {
      inOrder = inOrder && row.time > lastTime && row.time == kept->rows[rows].time;
      lastTime = row.time;
      ++rows;
    }
    writer.write(window);
    return true;
  });
  REQUIRE(run);
  CHECK(run->rows.empty());
  CHECK(rows == 20001);
  CHECK(inOrder);
  CHECK(allCounted);
  CHECK(windows > 1);
  CHECK(largest <= k::kSweepWindow);
  CHECK(run->unreachable > 0);
  CHECK(run->unreachable == kept->unreachable);
  CHECK(run->unreachable < run->samples);
  CHECK(streamed.str() == k::io::armCsv(*kept));
  CHECK(k::armNotes(*run) == k::armNotes(*kept));
  CHECK(k::armNotes(*run).back().find(std::to_string(run->unreachable) + " of 20001 samples") != std::string::npos);
}

TEST_CASE("a sink that stops the arm's run cancels it", "[arm]") {
  k::ArmRequest request;
  request.example = "seed-arm";
  request.samples = 100000;
  std::size_t windows = 0;
  const auto run = k::runArm(request, [&](const std::vector<k::ArmRow>&, std::size_t) { return ++windows < 2; });
  REQUIRE_FALSE(run);
  CHECK(run.error().code == k::ErrorCode::Cancelled);
  CHECK(windows == 2);
}
