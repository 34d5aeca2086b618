#pragma once
// How much of the core's heavier work has been done, counted where it is done, so that a test
// can hold one edit of the designer (or one request) to its budget: the linkage recognised
// (asFourBar), a design checked (checkDesign), a sweep run and its samples. Process-wide relaxed
// atomic counters: a few nanoseconds each, ordering nothing.

#include <cstddef>
#include <cstdint>

namespace linkwright::kinematics {

struct WorkCount {
  std::uint64_t recognitions = 0;  ///< asFourBar calls
  std::uint64_t designChecks = 0;  ///< checkDesign calls
  std::uint64_t sweeps = 0;        ///< sweeps run (whole or in windows)
  std::uint64_t sweptSamples = 0;  ///< their samples
  WorkCount operator-(const WorkCount& since) const {
    return {recognitions - since.recognitions, designChecks - since.designChecks, sweeps - since.sweeps,
            sweptSamples - since.sweptSamples};
  }
};

/// The work counted so far in this process.
WorkCount workCount();

/// Where the work is done, to count it.
void countRecognition();
void countDesignCheck();
void countSweep(std::size_t samples);

}  // namespace linkwright::kinematics
