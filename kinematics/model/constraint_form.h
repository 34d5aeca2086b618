#pragma once
// The constraint form of a mechanism: free points (FreePoint) grouped as the pose solver meets
// them, the distance constraints each group closes on, and a converter that rewrites every RRR
// dyad joint as a free point held by its two link lengths, so that one linkage can be solved
// both in closed form and by Newton (newton_group.h) and the two compared.
//
// A group is a maximal run of consecutive free points in Mechanism::points; its constraints are
// those whose later point (the larger index) lies in it. Their other ends are earlier points,
// solved before the group, or points of the same group.

#include "kinematics/model/mechanism.h"

#include <Eigen/Core>

#include <cstddef>
#include <span>

namespace linkwright::kinematics {

/// The most free points one group may hold (a class-IV Assur group has four; checkMechanism
/// rejects more). It sizes Newton's stack workspace: 2·8 = 16 unknowns.
inline constexpr std::size_t kMaxFreeGroupPoints = 8;

/// True if point `id` is a FreePoint.
bool isFreePoint(const Mechanism& mechanism, PointId id);

/// One past the last point of the run of free points that starts at `first` (`first` itself
/// if that point is not free).
std::size_t freeGroupEnd(const Mechanism& mechanism, std::size_t first);

/// The point whose group a constraint closes: the later of its two (the larger index).
inline PointId constraintLaterPoint(const DistanceConstraint& c) {
  return c.first.index > c.second.index ? c.first : c.second;
}

/// The same linkage with every RRR point replaced by a FreePoint guessed at `positions[i]`
/// and two DistanceConstraints (first parent, point, firstLength), (second parent, point,
/// secondLength), appended after the mechanism's own constraints. Ground, crank, attached,
/// RPR and PRP points stay as they are, and so do RRP sliders: a point on a line is not a
/// distance. `positions` is a solved pose of `mechanism` (Pose::position): the guesses pick
/// the branch the closed form took there. Preconditions: checkMechanism(mechanism) passed and
/// positions.size() == mechanism.points.size().
Mechanism withNewtonPoints(const Mechanism& mechanism, std::span<const Eigen::Vector2d> positions);

}  // namespace linkwright::kinematics
