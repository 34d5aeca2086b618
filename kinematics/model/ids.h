#pragma once
// Typed indices into a Mechanism's points and links. Values, not pointers: copies of a
// mechanism, undo snapshots and documents stay trivial, and a PointId cannot be passed where a
// LinkId is meant. (Equality only: <compare> would trip Qt 6.4's moc, which parses the
// headers the GUI includes.)

#include <cstddef>

namespace linkwright::kinematics {

/// Index of a point (joint or point of interest) in Mechanism::points.
struct PointId {
  std::size_t index = 0;
  bool operator==(const PointId&) const = default;
};

/// Index of a moving link in Mechanism::links.
struct LinkId {
  std::size_t index = 0;
  bool operator==(const LinkId&) const = default;
};

}  // namespace linkwright::kinematics
