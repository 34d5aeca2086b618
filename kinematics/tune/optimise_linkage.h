#pragma once
// Optimisation of a linkage the user already has: its dimensions (optimise_dimensions.h: the
// tolerance analyses' lengths and coordinates, each within a range, fixed pivots held) are
// changed to improve one objective (optimise_objective.h: peak |α| of a link, the worst
// transmission angle, the distance from a target path, the RMS driving torque) while the design
// keeps what it is:
//   - it assembles at every sample of its grid and never locks between two (sweep.h), with no
//     more singular samples than the start has;
//   - a recognised four-bar keeps its Grashof class and its assembly branch (grashof.h); every
//     other dyad keeps its branch by construction, since branches are not dimensions;
//   - every dimension stays in its range, and a fixed pivot's numbers are not touched.
// A candidate that breaks any of these is infeasible: the optimiser sees a barrier value
// above every feasible one, and it is never returned.
//
// The optimiser is NLopt's Nelder–Mead simplex with bound constraints (NLOPT_LN_NELDERMEAD,
// Debian's libnlopt-dev on Debian 12 and 13): derivative-free, which the objectives need since
// a peak or a worst case is not smooth where its maximising sample changes, and a barrier is
// not smooth at all; bounds are kept by the algorithm itself. Each variable is the dimension's
// place in its range, scaled to [0, 1], so one initial step (a tenth of each range) suits all.
// Nelder–Mead finds a local minimum, so it runs from several starts: the first is the design
// itself, the others are drawn by std::mt19937 seeded by the caller (uniform over the ranges,
// then about the best so far when a draw is infeasible). NLopt's own generator is seeded with
// the same seed, although Nelder–Mead draws nothing from it. So a seed gives the same result to
// the last bit. The evaluation budget is shared among the starts.
//
// The figures returned (objective before and after, the curves, the constraints' state) are
// measured again on the returned design, by the same code as any candidate.

#include "kinematics/analysis/grashof.h"
#include "kinematics/design/design.h"
#include "kinematics/model/result.h"
#include "kinematics/tune/optimise_dimensions.h"
#include "kinematics/tune/optimise_objective.h"

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace linkwright::kinematics {

/// The default seed: fixed, so a run repeats exactly.
inline constexpr std::uint32_t kDefaultOptimiseSeed = 46;
/// The default evaluation budget: a few seconds at most for a four-bar on a 721-sample grid.
inline constexpr int kDefaultOptimiseEvaluations = 1500;
/// The default number of starts, the design itself the first.
inline constexpr int kDefaultOptimiseStarts = 4;
/// The evaluation budgets accepted: enough for a simplex to move, and at most what finishes.
inline constexpr int kMinOptimiseEvaluations = 10;
inline constexpr int kMaxOptimiseEvaluations = 1000000;
/// The numbers of starts accepted.
inline constexpr int kMinOptimiseStarts = 1;
inline constexpr int kMaxOptimiseStarts = 1000;
/// The most samples a design's grid may have to be optimised: every candidate is swept over it
/// whole (about 360 bytes a sample for a four-bar), so 10⁷ samples took 3.6 GB.
inline constexpr std::size_t kMaxOptimiseSamples = 100'000;

/// How hard to search.
struct OptimiseOptions {
  std::uint32_t seed = kDefaultOptimiseSeed;  ///< std::mt19937's and NLopt's
  int evaluations =
      kDefaultOptimiseEvaluations;      ///< designs measured in all, in [10, 1000000] (kMin/kMaxOptimiseEvaluations)
  int starts = kDefaultOptimiseStarts;  ///< Nelder–Mead runs, in [1, 1000] (kMin/kMaxOptimiseStarts)
  bool recordEvaluations = false;       ///< keep every candidate's dimensions (tests)
  bool operator==(const OptimiseOptions&) const = default;
};

/// What to optimise and what to keep.
struct OptimiseRequest {
  OptimiseObjective objective;
  OptimiseConstraints constraints;
  OptimiseOptions options;
  bool operator==(const OptimiseRequest&) const = default;
};

/// What the returned design keeps, checked on it.
struct OptimiseConstraintState {
  std::optional<GrashofClass> grashofBefore;  ///< a four-bar's; none for other linkages
  std::optional<GrashofClass> grashofAfter;
  bool branchKept = true;    ///< a four-bar's assembly branch is the start's
  bool assembles = true;     ///< every sample assembled, no lock, no more singular samples
  bool withinRanges = true;  ///< every dimension within its range
  bool pivotsKept = true;    ///< every fixed pivot where it was
  bool operator==(const OptimiseConstraintState&) const = default;
};

/// The outcome.
struct LinkageOptimisation {
  Design design;  ///< the best design found; the start when nothing better was
  OptimiseObjective objective;
  double before = 0.0;                        ///< the start's objective (ObjectiveValue's unit)
  double after = 0.0;                         ///< the returned design's
  ObjectiveCurve curveBefore;                 ///< the objective's curve over the start's cycle
  ObjectiveCurve curveAfter;                  ///< … over the returned design's
  std::vector<OptimiseDimension> dimensions;  ///< with their ranges; values at the start
  std::vector<double> values;                 ///< each dimension's value in the returned design (length unit)
  OptimiseConstraintState constraints;
  int evaluations = 0;          ///< designs measured
  int feasibleEvaluations = 0;  ///< of those, the ones that kept every constraint
  int startsRun = 0;            ///< Nelder–Mead runs begun
  bool improved = false;        ///< the returned design is better than the start
  bool cancelled = false;       ///< *cancel was set: the best found before is returned
  /// Every candidate's dimension values in the order measured (options.recordEvaluations).
  std::vector<std::vector<double>> evaluated;
};

/// Progress after each design measured: (done, the budget).
using OptimiseProgress = std::function<void(int done, int total)>;

/// Optimises `design` as `request` asks. Error naming the field for a bad request (an invalid
/// design, checkObjective's, optimiseDimensions', "evaluations", "starts"), or when the start
/// itself cannot be measured: it does not assemble over its grid ("design", NotAssemblable),
/// a change-point four-bar (whose class no neighbour keeps), a link whose α is the same at
/// every sample ("objective.link"). `cancel` (may be null) is read before each measurement:
/// once true the search stops and returns the best so far, marked cancelled. `progress` (may be
/// empty) is called on the calling thread. Never throws.
Result<LinkageOptimisation> optimiseLinkage(const Design& design, const OptimiseRequest& request,
                                            const std::atomic<bool>* cancel = nullptr,
                                            const OptimiseProgress& progress = {});

}  // namespace linkwright::kinematics
