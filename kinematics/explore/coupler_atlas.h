#pragma once
// A coupler-curve atlas in the spirit of Hrones and Nelson (Analysis of the Four-Bar Linkage,
// 1951): a grid of four-bars over link ratios, the crank being 1, and over the coupler point's
// place on the coupler, each cell's curve the solver's own coupler path (makeFourBar's point P,
// swept at ω = 1 rad/s so that its velocity is dP/dθ) and classified by
// coupler_curve_features.h. Cells are numbered coupler ratio slowest, then rocker, frame,
// along and across fastest, and each is computed alone from its key, so a viewer can compute
// the cells it shows in any order, in the background, stop when asked (std::atomic<bool>) and
// cache them by key.
//
// A crank that turns fully (Grashof crank-rocker or double-crank, or a change point) traces its
// branch's curve over one turn: `samples` crank angles 2πk/samples, swept. A crank that cannot
// turn fully rocks between the edges of its assembly range (assembly_range.h); at each edge the
// coupler and rocker fold into line and the linkage goes on in the other assembly branch, so
// the closed curve it traces is the branch's path across the range followed by the other
// branch's path back. It is sampled at θ = c − r cos u, c the range's middle and r its
// half-width, at u = 2π(k + ½)/samples (coupler_curve.h): the cell's branch for u < π, the other
// for u > π, each pose solved on its branch. Near an edge θ moves as u², and P as
// √(edge − θ), so P is as evenly spaced there as elsewhere and smooth in u through the edge;
// no sample falls on an edge, where rates do not exist. Of a range in two parts (a rocking
// crank of a Grashof linkage: two circuits) the first is traced.
// A cell that never assembles has no curve.

#include "kinematics/analysis/coupler_curve_features.h"
#include "kinematics/analysis/grashof.h"
#include "kinematics/design/design.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/request_field.h"
#include "kinematics/model/result.h"

#include <atomic>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace linkwright::kinematics {

inline constexpr std::size_t kMinAtlasSamples = 36;
inline constexpr std::size_t kMaxAtlasSamples = 100000;
inline constexpr std::size_t kMaxAtlasAxisValues = 64;  ///< values on one axis
/// Cells one run computes (runAtlas, computeAtlasPage): about 4 minutes on one core at 360
/// samples a curve (docs/atlas.md).
inline constexpr std::size_t kMaxAtlasRunCells = 100000;
inline constexpr double kMinAtlasRatio = 1e-3;      ///< of the crank
inline constexpr double kMaxAtlasRatio = 1e3;       ///< of the crank
inline constexpr double kMaxAtlasPosition = 100.0;  ///< |along|, |across|, coupler lengths
/// A rocking crank's design (atlasCellDesign) runs to within this of its range's edges (rad).
inline constexpr double kAtlasEdgeMargin = 1e-7;

/// The grid: link lengths over the crank's (dimensionless) and the coupler point's place in
/// coupler lengths, along B→C and 90° counter-clockwise across it.
struct AtlasAxes {
  std::vector<double> coupler{1.5, 2.0, 2.5, 3.0};     ///< coupler / crank (dimensionless)
  std::vector<double> rocker{1.5, 2.0, 2.5, 3.0};      ///< rocker / crank (dimensionless)
  std::vector<double> frame{2.0, 2.5, 3.0};            ///< frame / crank (dimensionless)
  std::vector<double> along{0.0, 0.5, 1.0, 1.5, 2.0};  ///< P along B→C, coupler lengths
  std::vector<double> across{0.0, 0.5, 1.0};           ///< P 90° CCW from B→C, coupler lengths
  Branch branch = Branch::Open;                        ///< the assembly branch every cell starts on
  std::size_t samples = 360;                           ///< solver samples per curve
  bool operator==(const AtlasAxes&) const = default;
};

/// Error naming the axis ("coupler", "rocker", "frame", "along", "across") and the value:
/// an axis empty or of more than kMaxAtlasAxisValues values, a ratio not in
/// [kMinAtlasRatio, kMaxAtlasRatio], a position not finite or beyond ±kMaxAtlasPosition;
/// samples ("samples") not in [kMinAtlasSamples, kMaxAtlasSamples].
std::optional<Error> checkAtlasAxes(const AtlasAxes& axes);

/// One cell: everything its curve depends on, and so what a cache keys it by.
struct AtlasCellKey {
  FourBarLengths lengths;        ///< crank 1, the others over it (dimensionless)
  CouplerPointSpec point;        ///< along and across B→C in coupler lengths
  Branch branch = Branch::Open;  ///< the branch it starts on
  std::size_t samples = 360;
  bool operator==(const AtlasCellKey&) const = default;
};

/// How the cell's crank moves.
enum class CrankMotion {
  FullTurn,        ///< it turns through 360°
  Rocks,           ///< it rocks between the edges of its assembly range (both branches traced)
  NeverAssembles,  ///< no crank angle assembles the linkage
};

/// "full turn", "rocks", "never assembles".
std::string_view toString(CrankMotion motion);

/// A classified cell.
struct AtlasCell {
  AtlasCellKey key;
  GrashofReport grashof;
  CrankMotion motion = CrankMotion::FullTurn;
  AngleRange range;    ///< rad: the crank angles traced (a full turn: 0 to 2π)
  CouplerCurve curve;  ///< P's path, in crank lengths, O2 at the origin, O4 on +x
  CurveFeatures features;
  bool operator==(const AtlasCell&) const = default;
};

/// A rocking crank's curve parameter u at sample k of `samples`: 2π(k + ½)/samples (rad).
double rockingParameter(std::size_t k, std::size_t samples);

/// The number of cells of the grid.
std::size_t atlasCellCount(const AtlasAxes& axes);

/// The key of cell `index` (< atlasCellCount).
AtlasCellKey atlasCellKey(const AtlasAxes& axes, std::size_t index);

/// The cell's four-bar as makeFourBar builds it (crank 1 in `lengthUnit`, scaled by `crank`),
/// its point P at the cell's place, on `branch`.
Result<Mechanism> atlasMechanism(const AtlasCellKey& key, Branch branch, double crank = 1.0,
                                 const std::string& lengthUnit = "mm");

/// The cell computed and classified. Fails with makeFourBar's error for lengths a linkage may
/// not have, or ErrorCode::Cancelled once `cancel` is true.
Result<AtlasCell> computeAtlasCell(const AtlasCellKey& key, const std::atomic<bool>* cancel = nullptr);

/// What a run does with each cell as it is classified: `index` is its number in the grid. The
/// cell is dropped when it returns; false stops the run.
using AtlasCellVisitor = std::function<bool(std::size_t index, const AtlasCell& cell)>;

/// Cells [first, first + count) of the grid (fewer at its end), each computed as
/// computeAtlasCell, handed to `visit` and dropped, in order; control.progress(done, total)
/// after each. Returns the cells visited. Errors: the axes' (checkAtlasAxes), more than
/// kMaxAtlasRunCells cells (field "count"), a cell's, or ErrorCode::Cancelled once
/// control.cancel is set.
Result<std::size_t> runAtlas(const AtlasAxes& axes, std::size_t first, std::size_t count, const AtlasCellVisitor& visit,
                             const RunControl& control = {});

/// Cells [first, first + count) of the grid, kept: runAtlas into a vector.
Result<std::vector<AtlasCell>> computeAtlasPage(const AtlasAxes& axes, std::size_t first, std::size_t count,
                                                const std::atomic<bool>* cancel = nullptr);

/// The cell's linkage as a design: the crank `crank` long (length unit) turning at `omega`
/// (rad/s; the designer passes the speed of the design the cell replaces), its grid a full
/// turn, or a rocking crank's traced range on the cell's branch, every 0.5°. Errors as
/// fourBarDesign and for a cell that never assembles (NotAssemblable, field "cell").
Result<Design> atlasCellDesign(const AtlasCellKey& key, double crank = 1.0, const std::string& lengthUnit = "mm",
                               double omega = 1.0);

}  // namespace linkwright::kinematics
