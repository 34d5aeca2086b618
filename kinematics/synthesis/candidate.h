#pragma once
// What every synthesis problem returns: candidate linkages, each a ready, editable Design
// (design/design.h) that the designer can adopt as its document, with the numbers a designer
// ranks candidates by (the problem's error, the Grashof class, the worst transmission angle)
// and the defects that would make it useless, each with a sentence saying why. A candidate
// with a defect is kept and marked, never dropped: the user decides.

#include "kinematics/analysis/grashof.h"
#include "kinematics/design/design.h"
#include "kinematics/design/synthesis_targets.h"
#include "kinematics/model/units.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace linkwright::kinematics {

enum class DefectKind {
  NotGrashof,    ///< the crank cannot turn fully although the task needs a motor-driven full turn
  Branch,        ///< required positions lie on different assembly branches (circuits)
  Order,         ///< the crank reaches the required positions in the wrong order
  Transmission,  ///< the transmission angle falls below the bound
  LinkLength,    ///< a link is longer than the bound, or longest/shortest exceeds the bound
};

/// One reason a candidate may be useless, with a sentence for the user.
struct Defect {
  DefectKind kind = DefectKind::NotGrashof;
  std::string message;  ///< e.g. "minimum transmission angle 31.2° is below 40°"
  bool operator==(const Defect&) const = default;
};

/// A synthesised linkage and how good it is.
struct SynthesisCandidate {
  Design design;       ///< the linkage, ready to analyse, edit and save
  double error = 0.0;  ///< the problem's own error (see each problem's header); 0 for an exact construction
  std::optional<GrashofReport> grashof;  ///< four-bars only
  /// The worst transmission angle over the motion the task needs (rad, in [0, π/2]):
  /// min over it of min(μ, π − μ), μ the angle between coupler and output link.
  double minTransmission = 0.0;
  std::vector<Defect> defects;  ///< empty: no defect found
  bool operator==(const SynthesisCandidate&) const = default;

  /// True if the candidate has a defect of this kind.
  bool has(DefectKind kind) const {
    for (const Defect& d : defects)
      if (d.kind == kind) return true;
    return false;
  }
};

/// "not-grashof", "branch", "order", "transmission", "link-length".
std::string_view toString(DefectKind kind);

}  // namespace linkwright::kinematics
