#include "kinematics/synthesis/defects.h"

#include "kinematics/analysis/assembly_range.h"
#include "kinematics/analysis/transmission.h"
#include "kinematics/model/number_text.h"
#include "kinematics/synthesis/message_text.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace linkwright::kinematics {
namespace {

using synthesis_text::degrees;

// Angles within this of a range's edge count as inside it: the synthesis puts required
// positions exactly on dead-centre edges only in degenerate cases, and round-off there is
// ~1e-15 rad.
constexpr double kAngleSlack = 1e-9;

// The assemblable interval holding `angle`, and `angle` unwrapped into it; nullopt if none.
std::optional<std::pair<AngleRange, double>> rangeHolding(const InputRange& range, double angle) {
  for (const AngleRange& r : range.ranges) {
    const double u = r.from + wrapPositive(angle - r.from + kAngleSlack) - kAngleSlack;
    if (u <= r.to + kAngleSlack) return std::pair{r, u};
  }
  return std::nullopt;
}

// True if every angle of the span can be assembled (one interval holds all of it).
bool spanAssembles(const FourBarLengths& l, const CrankSpan& span) {
  const InputRange range = fourBarInputRange(l);
  if (range.fullRotation) return true;
  const auto held = rangeHolding(range, std::min(span.from, span.to));
  return held && held->second + std::abs(span.to - span.from) <= held->first.to + kAngleSlack;
}

std::string branchName(Branch b) { return b == Branch::Open ? "open" : "crossed"; }

std::optional<Defect> branchDefect(const FourBarTask& task) {
  for (std::size_t k = 1; k < task.branches.size(); ++k)
    if (task.branches[k] != task.branches[0])
      return Defect{DefectKind::Branch, "position " + std::to_string(k + 1) + " is on the " +
                                            branchName(task.branches[k]) + " branch and position 1 on the " +
                                            branchName(task.branches[0]) +
                                            " branch: the linkage cannot move between them without being taken apart"};
  return std::nullopt;
}

// "1, 3, 2": the positions in the order the crank meets them turning counter-clockwise from
// the first.
std::string orderText(const std::vector<double>& along) {
  std::vector<std::size_t> order(along.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return along[a] < along[b]; });
  std::string text;
  for (std::size_t k : order) text += (text.empty() ? "" : ", ") + std::to_string(k + 1);
  return text;
}

bool monotonic(const std::vector<double>& u) {
  bool up = true, down = true;
  for (std::size_t k = 1; k < u.size(); ++k) {
    up = up && u[k] > u[k - 1];
    down = down && u[k] < u[k - 1];
  }
  return up || down;
}

// Order, and for a crank that cannot turn fully, whether all positions share one range.
std::optional<Defect> orderDefect(const FourBarTask& task, const GrashofReport& grashof) {
  const std::vector<double>& angles = task.crankAngles;
  if (angles.size() < 2) return std::nullopt;
  std::vector<double> along(angles.size());
  if (grashof.inputFullyRotates) {
    // Turning one way, the positions come in the order of their angle from the first.
    for (std::size_t k = 0; k < angles.size(); ++k) along[k] = wrapPositive(angles[k] - angles[0]);
    std::vector<double> tail(along.begin() + 1, along.end());
    if (monotonic(tail)) return std::nullopt;
    return Defect{DefectKind::Order,
                  "turning either way the crank reaches the positions out of order (counter-clockwise: " +
                      orderText(along) + ")"};
  }
  const InputRange range = fourBarInputRange(task.lengths);
  const auto first = rangeHolding(range, angles[0]);
  for (std::size_t k = 0; k < angles.size(); ++k) {
    const auto held = rangeHolding(range, angles[k]);
    if (!held || !first || held->first != first->first)
      return Defect{DefectKind::Branch, "position " + std::to_string(k + 1) + " (crank at " + degrees(angles[k]) +
                                            ") is not in the range of crank angles that holds position 1: the crank "
                                            "cannot move between them"};
    along[k] = held->second;
  }
  if (monotonic(along)) return std::nullopt;
  return Defect{DefectKind::Order, "the crank rocks within " + degrees(first->first.from) + " to " +
                                       degrees(first->first.to) + " and meets the positions in the order " +
                                       orderText(along)};
}

}  // namespace

std::optional<double> worstTransmissionOver(const FourBarLengths& l, const CrankSpan& span) {
  if (!spanAssembles(l, span)) return std::nullopt;
  return worstTransmissionBetween(l, span.from, span.to);
}

std::optional<double> worstTransmission(const FourBarLengths& l) {
  const auto range = fourBarTransmissionRange(l);
  if (!range) return std::nullopt;
  return kPi / 2.0 - range->worstDeviation;
}

std::optional<Defect> transmissionDefect(double minTransmission, const DefectBounds& bounds) {
  if (minTransmission >= bounds.minTransmission) return std::nullopt;
  return Defect{DefectKind::Transmission, "minimum transmission angle " + degrees(minTransmission) + " is below " +
                                              degrees(bounds.minTransmission)};
}

std::optional<Defect> linkLengthDefect(const std::vector<double>& lengths, const std::vector<std::string>& names,
                                       const DefectBounds& bounds) {
  if (lengths.empty()) return std::nullopt;
  const auto longest = static_cast<std::size_t>(std::max_element(lengths.begin(), lengths.end()) - lengths.begin());
  const auto shortest = static_cast<std::size_t>(std::min_element(lengths.begin(), lengths.end()) - lengths.begin());
  if (bounds.maxLinkLength && lengths[longest] > *bounds.maxLinkLength)
    return Defect{DefectKind::LinkLength, "the " + names[longest] + " (" + formatShort(lengths[longest]) +
                                              ") is longer than the bound " + formatShort(*bounds.maxLinkLength)};
  const double ratio = lengths[longest] / lengths[shortest];
  if (bounds.maxLinkRatio && ratio > *bounds.maxLinkRatio)
    return Defect{DefectKind::LinkLength, "the " + names[longest] + " is " + formatShort(ratio) + " times the " +
                                              names[shortest] + ", more than the bound " +
                                              formatShort(*bounds.maxLinkRatio)};
  return std::nullopt;
}

FourBarCheck checkFourBar(const FourBarTask& task, const DefectBounds& bounds) {
  const FourBarLengths& l = task.lengths;
  FourBarCheck check;
  check.grashof = classifyGrashof(l);
  if (task.needsFullRotation && !check.grashof.inputFullyRotates)
    check.defects.push_back({DefectKind::NotGrashof, "the crank cannot turn fully (" +
                                                         std::string(toString(check.grashof.category)) +
                                                         "), so a motor cannot drive it round"});
  if (auto d = branchDefect(task)) check.defects.push_back(*d);
  if (auto d = orderDefect(task, check.grashof)) check.defects.push_back(*d);
  std::optional<double> mu;
  if (task.workingRange) {
    mu = worstTransmissionOver(l, *task.workingRange);
    if (!mu)
      check.defects.push_back({DefectKind::Branch, "the crank cannot turn from " + degrees(task.workingRange->from) +
                                                       " to " + degrees(task.workingRange->to) +
                                                       ": the linkage cannot be assembled all the way"});
  } else {
    mu = worstTransmission(l);
  }
  check.minTransmission = mu.value_or(0.0);
  if (mu)
    if (auto d = transmissionDefect(*mu, bounds)) check.defects.push_back(*d);
  if (auto d =
          linkLengthDefect({l.frame, l.crank, l.coupler, l.rocker}, {"frame", "crank", "coupler", "rocker"}, bounds))
    check.defects.push_back(*d);
  return check;
}

double wrapPositive(double angle) {
  const double w = std::fmod(angle, 2.0 * kPi);
  return w < 0.0 ? w + 2.0 * kPi : w;
}

CrankSpan crankSpanThrough(const std::vector<double>& angles) {
  const double last = wrapPositive(angles.back() - angles.front());
  bool counterClockwise = last <= kPi;
  if (angles.size() > 2) counterClockwise = wrapPositive(angles[1] - angles.front()) < last;
  return {angles.front(), angles.front() + (counterClockwise ? last : last - 2.0 * kPi)};
}

}  // namespace linkwright::kinematics
