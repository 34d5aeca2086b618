#pragma once
// The nearest of many points to a query point, in O(log n) for points spread along a curve: a
// static k-d tree (each node splits its points at the median of its wider coordinate). What
// the symmetry test measures a mirrored curve against (curve_shape_fits.h), which compared
// every mirrored sample with every sample.

#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace linkwright::kinematics {

class PointTree {
public:
  /// The tree of `points` (copied). Empty is allowed.
  explicit PointTree(const std::vector<Eigen::Vector2d>& points);

  /// The index of a point nearest `x` (of the nearest, the lowest index); 0 when empty.
  std::size_t nearest(const Eigen::Vector2d& x) const;

private:
  struct Node {
    std::size_t first = 0, count = 0;  // the node's points: m_order[first, first + count)
    int axis = 0;                      // the coordinate it splits on
    double split = 0.0;                // its median point's coordinate
  };
  void build(std::size_t node, std::size_t first, std::size_t count);
  void search(std::size_t node, const Eigen::Vector2d& x, std::size_t& best, double& least) const;

  std::vector<Eigen::Vector2d> m_points;
  std::vector<std::size_t> m_order;  // indices into m_points, each node's a contiguous range
  std::vector<Node> m_nodes;         // heap order: node k's children are 2k + 1 and 2k + 2
};

}  // namespace linkwright::kinematics
