#include "kinematics/analysis/box_pairs.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace linkwright::kinematics {

std::vector<std::pair<std::size_t, std::size_t>> intersectingBoxPairs(const std::vector<Eigen::AlignedBox2d>& boxes) {
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  Eigen::AlignedBox2d all;
  double sides = 0.0;
  std::size_t counted = 0;
  for (const Eigen::AlignedBox2d& b : boxes) {
    if (b.isEmpty()) continue;
    all.extend(b);
    sides += b.sizes().maxCoeff();
    ++counted;
  }
  if (counted < 2) return pairs;
  // Buckets about twice a box's mean side; never so small that the whole extent needs more
  // than 2^30 of them across (their indices stay well inside 32 bits).
  const double extent = all.sizes().maxCoeff();
  double side = std::max(2.0 * sides / static_cast<double>(counted), extent * 1e-9);
  if (!(side > 0.0)) side = 1.0;
  const Eigen::Vector2d origin = all.min();
  const auto bucket = [&](double v, double o) { return static_cast<std::int64_t>(std::floor((v - o) / side)); };
  const auto key = [](std::int64_t ix, std::int64_t iy) {
    return (static_cast<std::uint64_t>(ix) << 32) | static_cast<std::uint64_t>(iy);
  };

  std::vector<std::pair<std::uint64_t, std::size_t>> entries;
  std::vector<std::size_t> wide;
  entries.reserve(2 * counted);
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const Eigen::AlignedBox2d& b = boxes[i];
    if (b.isEmpty()) continue;
    const std::int64_t x0 = bucket(b.min().x(), origin.x()), x1 = bucket(b.max().x(), origin.x());
    const std::int64_t y0 = bucket(b.min().y(), origin.y()), y1 = bucket(b.max().y(), origin.y());
    if (static_cast<double>(x1 - x0 + 1) * static_cast<double>(y1 - y0 + 1) > static_cast<double>(kMaxBucketsPerBox)) {
      wide.push_back(i);
      continue;
    }
    for (std::int64_t x = x0; x <= x1; ++x)
      for (std::int64_t y = y0; y <= y1; ++y) entries.push_back({key(x, y), i});
  }
  std::sort(entries.begin(), entries.end());
  for (std::size_t first = 0; first < entries.size();) {
    std::size_t end = first;
    while (end < entries.size() && entries[end].first == entries[first].first) ++end;
    for (std::size_t a = first; a < end; ++a)
      for (std::size_t b = a + 1; b < end; ++b) {
        const std::size_t i = entries[a].second, j = entries[b].second;
        if (!boxes[i].intersects(boxes[j])) continue;
        // Report the pair from the bucket holding the overlap's lower-left corner only.
        const Eigen::Vector2d corner = boxes[i].min().cwiseMax(boxes[j].min());
        if (key(bucket(corner.x(), origin.x()), bucket(corner.y(), origin.y())) != entries[first].first) continue;
        pairs.push_back({std::min(i, j), std::max(i, j)});
      }
    first = end;
  }
  for (const std::size_t w : wide)
    for (std::size_t j = 0; j < boxes.size(); ++j)
      if (j != w && !boxes[j].isEmpty() && boxes[w].intersects(boxes[j]))
        pairs.push_back({std::min(w, j), std::max(w, j)});
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

}  // namespace linkwright::kinematics
