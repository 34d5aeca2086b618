#pragma once
// Four-bar path generation: a coupler point P through 4 to 10 target points, with or without
// prescribed crank angles (timing), by bounded least squares from many starts. There is no
// closed form past five points (Alt–Burmester: nine in general need polynomial continuation), so
// we minimise Σ|P(θ_i) − target_i|² over the linkage: ground pivot O2, frame angle β (O4 =
// O2 + d·(cos β, sin β)), the four lengths d, a (crank), b (coupler), c (rocker), the coupler
// point (along, across) on B→C, and the crank angles θ_i: one free angle per target without
// timing; with timing θ_i = θ0 + τ_i (θ0 free) or θ_i = β + τ_i (τ measured from the frame line,
// as the literature's benchmark problems state it). The point is
//   B = O2 + a·(cos θ, sin θ),  C = the RRR dyad (B, b; O4, c) on ONE branch (rrr_dyad.h),
//   P = B + along·u + across·perp(u),  u = (C − B)/b.
// The branch is chosen per start and kept. Where a target's crank angle cannot be assembled the
// dyad is clamped to its nearest limit (P stays continuous) and a residual proportional to the
// gap (|O4B| − (b + c), or |b − c| − |O4B|) pushes the optimiser back: a large, smooth penalty,
// never NaN. Every length is held in [scale·1e-2, scale·10] (scale: the diagonal of the targets'
// bounding box) by the smooth map l = lo·(hi/lo)^σ(u), σ the logistic function, and the coupler
// point within ±10·scale by a tanh, so no step can run away.
//
// The local solver is Eigen's Levenberg–Marquardt (unsupported/Eigen/LevenbergMarquardt, a port
// of MINPACK's lmder): it ships with Eigen, which the core already depends on (Debian's
// libeigen3-dev), so it adds no dependency; MINPACK's trust-region LM is the well-kept standard
// for small dense nonlinear least squares, and this problem has at most 19 unknowns and 30
// residuals. LM finds a local minimum only, so it runs from many deterministic pseudo-random
// starts (each start's std::mt19937 seeded by the caller's seed and the start's index, through
// std::seed_seq, whose mixing the standard fixes; the default seed is fixed, so results repeat
// on every machine and a start can be run alone).
// Each start draws a random linkage and spread of crank angles, then places it by the
// similarity transform (rotation, translation, scale; a reflection too, which swaps the branch,
// without timing) that best fits its points to the targets (Procrustes), so LM starts near.
//
// Every result is then checked independently: its Mechanism is solved with the pose solver at
// each found crank angle, and the reported distances are those, not the optimiser's residual.
// The defect check (defects.h) runs on the found crank angles: not Grashof when a full turn is
// asked for, branch (targets in different assembly ranges), order, transmission over the motion
// from the first target to the last, link lengths.

#include "kinematics/design/synthesis_targets.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/synthesis/candidate.h"

#include <Eigen/Core>

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace linkwright::kinematics {

/// The number of starts that takes 6 targets to within 1 % of their scale well inside the
/// issue's 2 s on its 2-core machine (tests/bench/synthesis_benchmark.cpp measures it).
inline constexpr int kDefaultPathStarts = PathSearch{}.starts;
/// The default seed: fixed, so a run repeats exactly.
inline constexpr std::uint32_t kDefaultPathSeed = PathSearch{}.seed;

/// How hard to search.
struct PathOptions {
  int starts = kDefaultPathStarts;        ///< LM runs from random starts, in [1, 100000]
  std::uint32_t seed = kDefaultPathSeed;  ///< with a start's index, seeds its std::mt19937
  std::size_t keep = 10;                  ///< distinct local minima kept, in [1, 1000]
  int maxEvaluations = 200;               ///< residual evaluations per LM run, in [10, 100000]
};

/// One synthesised path generator.
struct PathCandidate {
  /// design: the four-bar (points O2, O4, B, C, P; links crank, coupler, rocker; input: the
  /// crank's absolute angle, CCW from +x), graded over a full turn if its crank turns fully,
  /// else over its motion from the first target to the last; error: worstDistance;
  /// minTransmission over that motion from the first target to the last.
  SynthesisCandidate candidate;
  Eigen::Vector2d o2 = Eigen::Vector2d::Zero();  ///< crank pivot (length unit)
  Eigen::Vector2d o4 = Eigen::Vector2d::Zero();  ///< rocker pivot (length unit)
  FourBarLengths lengths;
  CouplerPointSpec couplerPoint;    ///< P on the coupler B→C (length unit)
  Branch branch = Branch::Open;     ///< the one branch every target is drawn on
  std::vector<double> crankAngles;  ///< the design's input at each target (rad, absolute, in (−π, π])
  std::vector<double> distances;    ///< |P − target| at each target, by the pose solver (length unit)
  double worstDistance = 0.0;       ///< the largest of distances (length unit)
  int start = 0;                    ///< which start found it (0-based)
  double secondsToFind = 0.0;       ///< wall time from the call's start to the end of that start (s)
};

/// The search's outcome.
struct PathSynthesis {
  /// Distinct local minima, best (smallest worstDistance) first, at most options.keep.
  std::vector<PathCandidate> candidates;
  double scale = 0.0;          ///< the diagonal of the targets' bounding box (length unit)
  int startsRun = 0;           ///< starts completed (fewer than asked when cancelled)
  int startsNotAssembled = 0;  ///< starts whose result could not be assembled at every target
  bool cancelled = false;      ///< *cancel was set: candidates hold what was found before
  double seconds = 0.0;        ///< wall time of the whole call (s)
};

/// Progress after each start: (starts done, starts in all).
using PathProgress = std::function<void(int done, int total)>;

// A search split into blocks. The starts run in blocks of kPathStartsPerBlock, each start from a
// generator seeded by (seed, start index) alone, each block keeping its own best distinct
// minima; the blocks' lists are then merged in block order. synthesisePath does exactly this,
// so blocks run anywhere (the Python module's linkwright.batch runs them as Dask tasks) and
// merged by pathSynthesisFromBlocks give its answer to the last bit.

/// Starts per block.
inline constexpr int kPathStartsPerBlock = 100;

/// One start's local minimum, in the search's normalised frame: the targets moved to their
/// bounding box's centre and divided by its diagonal (PathSynthesis::scale).
struct PathMinimum {
  Eigen::Vector2d o2 = Eigen::Vector2d::Zero();                  ///< crank pivot (normalised)
  double beta = 0.0;                                             ///< frame direction O2→O4 (rad, CCW from +x)
  double frame = 1.0, crank = 1.0, coupler = 1.0, rocker = 1.0;  ///< lengths (normalised)
  double along = 0.0, across = 0.0;                              ///< P on the coupler B→C (normalised)
  Branch branch = Branch::Open;
  std::vector<double> crankAngles;  ///< the crank's angle at each target (rad, absolute, in (−π, π])
  double worst = 0.0;               ///< the optimiser's largest distance to a target (normalised)
  int start = 0;                    ///< which start found it (0-based, over the whole search)
  double seconds = 0.0;             ///< wall time from its block's (or search's) start to its end (s)
};

/// A block's outcome.
struct PathStartBlock {
  int block = 0;                  ///< 0-based: starts block·kPathStartsPerBlock onwards
  std::uint64_t search = 0;       ///< pathSearchFingerprint of the search it is a block of
  int startsRun = 0;              ///< starts completed
  int startsNotAssembled = 0;     ///< starts whose minimum does not assemble at every target
  bool cancelled = false;         ///< stopped by the cancel flag before its last start
  std::vector<PathMinimum> kept;  ///< its best distinct minima, best first, at most options.keep
};

/// How many blocks options.starts makes.
int pathStartBlockCount(const PathOptions& options);

/// A fingerprint of the search (every target, timing and option, bit for bit; FNV-1a, so the
/// same on every machine): a block carries its search's, so a block of another search is
/// refused rather than merged (path_start_blocks.cpp).
std::uint64_t pathSearchFingerprint(const PathTarget& target, const PathOptions& options);

/// Whether `blocks` can be merged as blocks of this search: each one of its blocks, given once,
/// of this search's fingerprint, its counts within the block's size and its minima one crank
/// angle per target, from the block's own starts, finite (a block may arrive pickled from
/// anywhere). For a search synthesisePath accepts; Error (field "blocks") saying which block
/// and why.
std::optional<Error> checkPathStartBlocks(const PathTarget& target, const PathOptions& options,
                                          const std::vector<PathStartBlock>& blocks);

/// Runs block `block` of the search (errors as synthesisePath's, and "block" outside
/// [0, pathStartBlockCount)). `progress` gets the block's starts done and its size.
Result<PathStartBlock> runPathStartBlock(const PathTarget& target, const PathOptions& options, int block,
                                         const std::atomic<bool>* cancel = nullptr, const PathProgress& progress = {});

/// The search's outcome from its blocks, merged in block order (any order given); a missing
/// block counts as cancelled. Candidates measured and checked as synthesisePath's. Blocks that
/// are not this search's are refused (checkPathStartBlocks).
Result<PathSynthesis> pathSynthesisFromBlocks(const PathTarget& target, const PathOptions& options,
                                              const DefectBounds& bounds, std::vector<PathStartBlock> blocks);

/// Searches for four-bars whose coupler point passes through the targets. Error naming the
/// field ("points", "points[2].x", "points[3]", "timing", "timing[1]", "starts", "keep",
/// "maxEvaluations") for a bad request. `cancel` (may be null) is read between starts: once it
/// is true the search stops and returns what it has, marked cancelled. `progress` (may be
/// empty) is called on the calling thread after each start. Never throws.
Result<PathSynthesis> synthesisePath(const PathTarget& target, const PathOptions& options = {},
                                     const DefectBounds& bounds = {}, const std::atomic<bool>* cancel = nullptr,
                                     const PathProgress& progress = {});

}  // namespace linkwright::kinematics
