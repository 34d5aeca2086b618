#pragma once
// Typed indices into a Mechanism's points and links. Values, not pointers: copies of a
// mechanism, undo snapshots and documents stay trivial, and a PointId cannot be passed where a
// LinkId is meant.

#include <compare>
#include <cstddef>

namespace linkwright::kinematics {

/// Index of a point (joint or point of interest) in Mechanism::points.
struct PointId {
  std::size_t index = 0;
  auto operator<=>(const PointId&) const = default;
};

/// Index of a moving link in Mechanism::links.
struct LinkId {
  std::size_t index = 0;
  auto operator<=>(const LinkId&) const = default;
};

} // namespace linkwright::kinematics
