// A path search's blocks checked before they are merged (path_generation.h): a block may come
// back pickled from a Dask worker, from another search or edited, and merging it would index
// its minima's crank angles by this search's targets. Its fingerprint says which search it is
// a block of; its counts and minima are checked against that search's block, so nothing read
// from it is out of range or not finite.

#include "kinematics/synthesis/path_generation.h"

#include <bit>
#include <cmath>
#include <string>

namespace linkwright::kinematics {
namespace {

// FNV-1a over 64-bit words: fixed by its definition, so a block's fingerprint is the same on
// every worker.
class Fingerprint {
public:
  void add(std::uint64_t word) {
    for (int byte = 0; byte < 8; ++byte) {
      m_hash ^= (word >> (8 * byte)) & 0xffu;
      m_hash *= 0x100000001b3ull;
    }
  }
  void add(double value) { add(std::bit_cast<std::uint64_t>(value)); }
  void add(const std::string& text) {
    add(static_cast<std::uint64_t>(text.size()));
    for (const char c : text) add(static_cast<std::uint64_t>(static_cast<unsigned char>(c)));
  }
  std::uint64_t value() const { return m_hash; }

private:
  std::uint64_t m_hash = 0xcbf29ce484222325ull;
};

Error refused(const std::string& message) { return Error{ErrorCode::InvalidValue, "blocks", message}; }

bool finite(const PathMinimum& m) {
  bool ok = std::isfinite(m.o2.x()) && std::isfinite(m.o2.y()) && std::isfinite(m.beta) && std::isfinite(m.frame) &&
            std::isfinite(m.crank) && std::isfinite(m.coupler) && std::isfinite(m.rocker) && std::isfinite(m.along) &&
            std::isfinite(m.across) && std::isfinite(m.worst) && std::isfinite(m.seconds);
  for (const double a : m.crankAngles) ok = ok && std::isfinite(a);
  return ok;
}

// Why block `b` is not a block of this search, if it is not.
std::optional<std::string> notOurs(const PathStartBlock& b, const PathTarget& target, const PathOptions& options,
                                   std::uint64_t fingerprint) {
  if (b.search != fingerprint)
    return "it is a block of another search (other targets, timing or options), not of this one";
  const int first = b.block * kPathStartsPerBlock;
  const int size = std::min(kPathStartsPerBlock, options.starts - first);
  if (b.startsRun < 0 || b.startsRun > size)
    return "it says it ran " + std::to_string(b.startsRun) + " starts, but the block has 0 to " + std::to_string(size);
  if (b.startsNotAssembled < 0 || b.startsNotAssembled > b.startsRun)
    return "it says " + std::to_string(b.startsNotAssembled) + " starts did not assemble, but it ran " +
           std::to_string(b.startsRun);
  const std::size_t found = static_cast<std::size_t>(b.startsRun - b.startsNotAssembled);
  if (b.kept.size() > std::min(options.keep, found))
    return "it keeps " + std::to_string(b.kept.size()) + " minima, more than its " + std::to_string(found) +
           " assembled starts or the search's keep of " + std::to_string(options.keep);
  for (const PathMinimum& m : b.kept) {
    if (m.start < first || m.start >= first + b.startsRun)
      return "a minimum comes from start " + std::to_string(m.start) + ", not one of the block's starts " +
             std::to_string(first) + " to " + std::to_string(first + b.startsRun - 1);
    if (m.crankAngles.size() != target.points.size())
      return "the minimum from start " + std::to_string(m.start) + " has " + std::to_string(m.crankAngles.size()) +
             " crank angles, not one for each of the " + std::to_string(target.points.size()) + " targets";
    if (!finite(m)) return "the minimum from start " + std::to_string(m.start) + " holds a number that is not finite";
  }
  return std::nullopt;
}

}  // namespace

std::uint64_t pathSearchFingerprint(const PathTarget& target, const PathOptions& options) {
  Fingerprint f;
  f.add(static_cast<std::uint64_t>(target.points.size()));
  for (const Eigen::Vector2d& p : target.points) {
    f.add(p.x());
    f.add(p.y());
  }
  f.add(static_cast<std::uint64_t>(target.timing.size()));
  for (const double t : target.timing) f.add(t);
  f.add(static_cast<std::uint64_t>(target.timingReference));
  f.add(static_cast<std::uint64_t>(target.needsFullRotation));
  f.add(target.lengthUnit);
  f.add(static_cast<std::uint64_t>(options.starts));
  f.add(static_cast<std::uint64_t>(options.seed));
  f.add(static_cast<std::uint64_t>(options.keep));
  f.add(static_cast<std::uint64_t>(options.maxEvaluations));
  return f.value();
}

std::optional<Error> checkPathStartBlocks(const PathTarget& target, const PathOptions& options,
                                          const std::vector<PathStartBlock>& blocks) {
  const int count = pathStartBlockCount(options);
  const std::uint64_t fingerprint = pathSearchFingerprint(target, options);
  std::vector<bool> seen(static_cast<std::size_t>(count), false);
  for (const PathStartBlock& b : blocks) {
    if (b.block < 0 || b.block >= count)
      return refused("a block numbered " + std::to_string(b.block) + " is not one of this search's 0 to " +
                     std::to_string(count - 1));
    if (seen[static_cast<std::size_t>(b.block)]) return refused("block " + std::to_string(b.block) + " is given twice");
    seen[static_cast<std::size_t>(b.block)] = true;
    if (auto why = notOurs(b, target, options, fingerprint))
      return refused("block " + std::to_string(b.block) + " cannot be merged: " + *why);
  }
  return std::nullopt;
}

}  // namespace linkwright::kinematics
