#pragma once
// Extreme values of any quantity over a sweep, found precisely: the largest and smallest
// samples bracket each extremum, and a golden-section search on the exact pose solver refines
// it between the neighbouring samples, so the answer does not depend on the sampling step
// (a frame-based tool reads extremes off its frames; seed 003 reads them at one frame per
// degree). Used for a slider's peak velocity and acceleration, a coupler's peak ω and α, etc.

#include "kinematics/model/mechanism.h"
#include "kinematics/solve/pose.h"
#include "kinematics/solve/sweep.h"

#include <functional>
#include <optional>
#include <vector>

namespace linkwright::kinematics {

/// One extreme value and the input angle (rad) where it occurs; on a time base, the instant.
struct Extremum {
  double value = 0.0;
  double inputAngle = 0.0;
  bool refined = false;  ///< true if the search improved on the best sample
  double time = 0.0;     ///< s, on a time base (SweepSpec::time); else 0
  bool operator==(const Extremum&) const = default;
};

struct Extrema {
  Extremum minimum;
  Extremum maximum;
  bool operator==(const Extrema&) const = default;
};

/// Evaluates a quantity from a pose solved with velocities and accelerations at `inputAngle`.
using PoseQuantity = std::function<double(const Pose& pose, double inputAngle)>;

/// A quantity's lowest and highest samples gathered in sweep order, in constant memory: what
/// refineExtrema needs of a whole sweep (the best samples and whether their neighbours, and the
/// second and last-but-one samples, have a value), so a sweep in windows (sweepInWindows) of
/// 10⁷ samples is searched as one held whole.
class SampledExtrema {
public:
  /// Sample `index` of the sweep (the next one: samples come in order, each once) has `value`
  /// if `valid`.
  void add(std::size_t index, bool valid, double value);

  struct Best {
    std::size_t index = 0;
    double value = 0.0;
    bool validBefore = false;  ///< the sample before has a value
    bool validAfter = false;   ///< the sample after has a value
  };
  const std::optional<Best>& lowest() const { return m_lowest; }
  const std::optional<Best>& highest() const { return m_highest; }
  std::size_t samples() const { return m_samples; }
  bool secondValid() const { return m_secondValid; }          ///< sample 1 has a value
  bool lastButOneValid() const { return m_lastButOneValid; }  ///< sample n − 2 has a value

private:
  std::optional<Best> m_lowest, m_highest;
  std::size_t m_samples = 0;
  bool m_lastValid = false, m_lastButOneValid = false, m_secondValid = false;
};

/// Refines the extremes of the samples gathered in `sampled` (a sweep of `mechanism` over
/// `spec`) on poses solved between them, as below. Nullopt if no sample had a value.
std::optional<Extrema> refineExtrema(const Mechanism& mechanism, const SweepSpec& spec, const SampledExtrema& sampled,
                                     const PoseQuantity& quantity, double angleTolerance = 1e-10);

/// Refines the extremes of `quantity` over `sampled` (a sweep of `mechanism` over `spec`):
/// `values[j]` is the quantity at sample j and `valid[j]` says whether it exists there (rates
/// do not at a toggle). Nullopt if no sample is valid. The search stays between the valid
/// neighbours of the best sample, to `angleTolerance` rad; on a time base it searches in time,
/// the crank following the law, to `angleTolerance` s.
std::optional<Extrema> refineExtrema(const Mechanism& mechanism, const SweepSpec& spec,
                                     const std::vector<double>& values, const std::vector<bool>& valid,
                                     const PoseQuantity& quantity, double angleTolerance = 1e-10);

/// The minimum alone, refined as above: for a least distance or a worst angle, where the
/// largest value is not wanted, at half the solves.
std::optional<Extremum> refineMinimum(const Mechanism& mechanism, const SweepSpec& spec,
                                      const std::vector<double>& values, const std::vector<bool>& valid,
                                      const PoseQuantity& quantity, double angleTolerance = 1e-10);

}  // namespace linkwright::kinematics
