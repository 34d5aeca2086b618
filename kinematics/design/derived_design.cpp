#include "kinematics/design/derived_design.h"

#include "kinematics/analysis/assembly_range.h"

namespace linkwright::kinematics {

bool needsGridSweep(const Mechanism& mechanism) {
  const auto fourBar = asFourBar(mechanism, PointsOnLinks::AnyLink);
  return !fourBar || !fourBarInputRange(fourBar->lengths).fullRotation;
}

SolveRequest gridSweepRequest(const NewtonSettings& newton) { return {false, false, newton}; }

Result<DerivedDesign> deriveDesign(const Mechanism& mechanism, const SweepResult& gridSweep) {
  if (auto refusal = assemblesNowhere(mechanism, gridSweep)) return *refusal;
  return DerivedDesign{asFourBar(mechanism, PointsOnLinks::AnyLink), analyseDesign(mechanism, gridSweep)};
}

Result<DerivedDesign> deriveDesign(const Design& candidate, const SweepResult& gridSweep) {
  if (auto e = checkDesign(candidate)) return *e;
  return deriveDesign(candidate.mechanism, gridSweep);
}

Result<DerivedDesign> deriveDesign(const Design& candidate, const NewtonSettings& newton) {
  if (auto e = checkDesign(candidate)) return *e;
  if (!needsGridSweep(candidate.mechanism)) return deriveDesign(candidate.mechanism, SweepResult{});
  auto grid = sweep(candidate.mechanism, designSweepSpec(candidate), gridSweepRequest(newton));
  if (!grid) return grid.error();
  return deriveDesign(candidate.mechanism, *grid);
}

}  // namespace linkwright::kinematics
