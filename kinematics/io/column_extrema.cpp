#include "kinematics/io/column_extrema.h"

namespace linkwright::kinematics::io {

std::optional<Extrema> columnExtrema(const Mechanism& m, const SweepSpec& spec, const SweepResult& r,
                                     const SweepColumn& column) {
  const auto valid = [&](std::size_t j) { return column.isRate() ? r.ok(j) : r.assembled(j); };
  std::vector<double> values(r.size(), 0.0);
  std::vector<bool> mask(r.size(), false);
  // The search's poses unwrap angles next to a value of the sweep's own continuous column.
  double near = 0.0;
  for (std::size_t j = 0; j < r.size(); ++j) {
    mask[j] = valid(j);
    if (!mask[j]) continue;
    values[j] = column.value(r, j);
    near = values[j];
  }
  return refineExtrema(m, spec, values, mask,
                       [&](const Pose& pose, double angle) { return column.valueOf(pose, angle, near); });
}

}  // namespace linkwright::kinematics::io
