#include "kinematics/solve/law_inverse.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace linkwright::kinematics {
namespace {

double instant(const TimeBase& time, std::size_t i, std::size_t intervals) {
  if (i == intervals) return time.toTime;
  return time.fromTime + (time.toTime - time.fromTime) * static_cast<double>(i) / static_cast<double>(intervals);
}

double positionAt(const TimeBase& time, double t) { return motionAt(time.law, t).position; }

// q − target brought to the period's nearest multiple (as it is without a period).
double offset(double q, double target, double period) {
  return period > 0.0 ? std::remainder(q - target, period) : q - target;
}

// The instant in [t0, t1] where the law reaches `target`, which lies between its positions at
// the two ends. Bisection halves the bracket until it no longer shrinks.
double refine(const TimeBase& time, double t0, double t1, double target) {
  double f0 = positionAt(time, t0) - target;
  if (f0 == 0.0) return t0;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (t0 + t1);
    if (mid <= t0 || mid >= t1) break;
    const double f = positionAt(time, mid) - target;
    if (f == 0.0) return mid;
    if ((f < 0.0) == (f0 < 0.0)) {
      t0 = mid;
      f0 = f;
    } else {
      t1 = mid;
    }
  }
  return 0.5 * (t0 + t1);
}

}  // namespace

std::vector<double> timesAtPosition(const TimeBase& time, double q, std::size_t most, double period,
                                    std::size_t intervals) {
  std::vector<double> times;
  if (most == 0 || intervals == 0 || !(time.toTime > time.fromTime)) return times;
  double q0 = positionAt(time, time.fromTime);
  // The start itself, if the law is there: intervals below take crossings after their start only.
  if (offset(q0, q, period) == 0.0) times.push_back(time.fromTime);
  for (std::size_t i = 0; i < intervals && times.size() < most; ++i) {
    const double t0 = instant(time, i, intervals);
    const double t1 = instant(time, i + 1, intervals);
    const double q1 = positionAt(time, t1);
    const double lo = std::min(q0, q1);
    const double hi = std::max(q0, q1);
    // Every copy of q in [lo, hi], one period apart (just q without a period), in time order.
    const double first = period > 0.0 ? std::ceil((lo - q) / period) : 0.0;
    const double last = period > 0.0 ? std::floor((hi - q) / period) : 0.0;
    std::vector<double> here;
    for (double n = first; n <= last && here.size() < most; ++n) {
      const double target = q + n * period;
      if (target < lo || target > hi || target == q0) continue;  // q0: the previous interval's end (or the start)
      here.push_back(refine(time, t0, t1, target));
    }
    std::sort(here.begin(), here.end());
    for (const double t : here)
      if (times.size() < most) times.push_back(t);
    q0 = q1;
  }
  return times;
}

double timeNearestPosition(const TimeBase& time, double q, double near, double period) {
  // Enough crossings to hold the one nearest `near` in any practical law; beyond, the first ones.
  constexpr std::size_t kMost = 4096;
  const std::vector<double> times = timesAtPosition(time, q, kMost, period);
  if (!times.empty())
    return *std::min_element(times.begin(), times.end(),
                             [near](double a, double b) { return std::abs(a - near) < std::abs(b - near); });
  double best = time.fromTime;
  double bestGap = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i <= kCrossingIntervals; ++i) {
    const double t = instant(time, i, kCrossingIntervals);
    const double gap = std::abs(offset(positionAt(time, t), q, period));
    if (gap < bestGap) {
      bestGap = gap;
      best = t;
    }
  }
  return best;
}

double lawTravel(const TimeBase& time, std::size_t intervals) {
  double travel = 0.0;
  double q0 = positionAt(time, time.fromTime);
  for (std::size_t i = 1; i <= intervals; ++i) {
    const double q1 = positionAt(time, instant(time, i, intervals));
    travel += std::abs(q1 - q0);
    q0 = q1;
  }
  return travel;
}

}  // namespace linkwright::kinematics
