#pragma once
// Which of many small boxes meet, without testing every pair: the boxes (a curve's pieces,
// each its chord's bounding box) are dropped into a uniform grid of buckets whose side is about
// twice a box's mean side, and only boxes sharing a bucket are compared; a pair is reported
// from the one bucket that holds the lower-left corner of where the two boxes overlap, so
// once. A curve cut into n pieces puts O(1) pieces into a bucket except where it passes close
// to itself, so the work is O(n log n) (the sort of the bucket entries). A box wider than
// kMaxBucketsPerBox buckets (a long chord among short ones) is compared with every box instead.

#include <Eigen/Geometry>

#include <cstddef>
#include <utility>
#include <vector>

namespace linkwright::kinematics {

/// Boxes that would span more buckets than this are compared with every box.
inline constexpr std::size_t kMaxBucketsPerBox = 64;

/// The pairs (i, j), i < j, of `boxes` that intersect (closed boxes: touching counts), sorted
/// by i then j. An empty box meets nothing.
std::vector<std::pair<std::size_t, std::size_t>> intersectingBoxPairs(const std::vector<Eigen::AlignedBox2d>& boxes);

}  // namespace linkwright::kinematics
