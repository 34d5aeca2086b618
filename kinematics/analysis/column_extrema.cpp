#include "kinematics/analysis/column_extrema.h"

namespace linkwright::kinematics {

void ColumnExtremaScan::add(const SweepResult& r, std::size_t first) {
  for (std::size_t j = 0; j < r.size(); ++j) {
    const bool valid = m_column.isRate() ? r.ok(j) : r.assembled(j);
    const double value = valid ? m_column.value(r, j) : 0.0;
    if (valid) m_near = value;
    m_sampled.add(first + j, valid, value);
  }
}

std::optional<Extrema> ColumnExtremaScan::refine(const Mechanism& m, const SweepSpec& spec) const {
  const double near = m_near;
  return refineExtrema(m, spec, m_sampled,
                       [&](const Pose& pose, double angle) { return m_column.valueOf(pose, angle, near); });
}

std::optional<Extrema> columnExtrema(const Mechanism& m, const SweepSpec& spec, const SweepResult& r,
                                     const SweepColumn& column) {
  ColumnExtremaScan scan(column);
  scan.add(r, 0);
  return scan.refine(m, spec);
}

}  // namespace linkwright::kinematics
