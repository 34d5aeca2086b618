#include "kinematics/analysis/point_tree.h"

#include <algorithm>
#include <limits>
#include <numeric>

namespace linkwright::kinematics {
namespace {
constexpr std::size_t kLeafPoints = 8;
}

PointTree::PointTree(const std::vector<Eigen::Vector2d>& points) : m_points(points), m_order(points.size()) {
  std::iota(m_order.begin(), m_order.end(), std::size_t{0});
  std::size_t nodes = 1;
  while (nodes * kLeafPoints < points.size()) nodes *= 2;
  m_nodes.resize(2 * nodes);
  if (!points.empty()) build(0, 0, points.size());
}

void PointTree::build(std::size_t node, std::size_t first, std::size_t count) {
  Node& n = m_nodes[node];
  n.first = first;
  n.count = count;
  if (count <= kLeafPoints || 2 * node + 2 >= m_nodes.size()) {
    n.axis = -1;  // a leaf
    return;
  }
  Eigen::Vector2d lo = m_points[m_order[first]], hi = lo;
  for (std::size_t k = first; k < first + count; ++k) {
    lo = lo.cwiseMin(m_points[m_order[k]]);
    hi = hi.cwiseMax(m_points[m_order[k]]);
  }
  const int axis = (hi - lo).x() >= (hi - lo).y() ? 0 : 1;
  const std::size_t half = count / 2;
  const auto begin = m_order.begin() + static_cast<std::ptrdiff_t>(first);
  std::nth_element(begin, begin + static_cast<std::ptrdiff_t>(half), begin + static_cast<std::ptrdiff_t>(count),
                   [&](std::size_t a, std::size_t b) { return m_points[a][axis] < m_points[b][axis]; });
  n.axis = axis;
  n.split = m_points[m_order[first + half]][axis];
  build(2 * node + 1, first, half);
  build(2 * node + 2, first + half, count - half);
}

void PointTree::search(std::size_t node, const Eigen::Vector2d& x, std::size_t& best, double& least) const {
  const Node& n = m_nodes[node];
  if (n.axis < 0) {
    for (std::size_t k = n.first; k < n.first + n.count; ++k) {
      const std::size_t i = m_order[k];
      const double d = (m_points[i] - x).squaredNorm();
      if (d < least || (d == least && i < best)) {
        least = d;
        best = i;
      }
    }
    return;
  }
  // Points left of the split have coordinate ≤ split, those right ≥ split.
  const double offset = x[n.axis] - n.split;
  const std::size_t nearSide = offset < 0.0 ? 2 * node + 1 : 2 * node + 2;
  const std::size_t farSide = offset < 0.0 ? 2 * node + 2 : 2 * node + 1;
  search(nearSide, x, best, least);
  if (offset * offset <= least) search(farSide, x, best, least);
}

std::size_t PointTree::nearest(const Eigen::Vector2d& x) const {
  if (m_points.empty()) return 0;
  std::size_t best = 0;
  double least = std::numeric_limits<double>::infinity();
  search(0, x, best, least);
  return best;
}

}  // namespace linkwright::kinematics
