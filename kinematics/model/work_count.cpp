#include "kinematics/model/work_count.h"

#include <atomic>

namespace linkwright::kinematics {
namespace {

std::atomic<std::uint64_t> recognitions{0}, designChecks{0}, sweeps{0}, sweptSamples{0};

}  // namespace

WorkCount workCount() {
  return {recognitions.load(std::memory_order_relaxed), designChecks.load(std::memory_order_relaxed),
          sweeps.load(std::memory_order_relaxed), sweptSamples.load(std::memory_order_relaxed)};
}

void countRecognition() { recognitions.fetch_add(1, std::memory_order_relaxed); }
void countDesignCheck() { designChecks.fetch_add(1, std::memory_order_relaxed); }
void countSweep(std::size_t samples) {
  sweeps.fetch_add(1, std::memory_order_relaxed);
  sweptSamples.fetch_add(samples, std::memory_order_relaxed);
}

}  // namespace linkwright::kinematics
