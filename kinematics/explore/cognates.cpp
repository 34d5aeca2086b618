#include "kinematics/explore/cognates.h"

#include "kinematics/design/fourbar_dimensions.h"
#include "kinematics/dynamics/crank_terms.h"
#include "kinematics/explore/cognate_cycle.h"
#include "kinematics/model/mechanism_check.h"
#include "kinematics/model/number_text.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace linkwright::kinematics {
namespace {

using Complex = std::complex<double>;

Complex complexOf(const Eigen::Vector2d& v) { return {v.x(), v.y()}; }
Eigen::Vector2d vectorOf(const Complex& c) { return {c.real(), c.imag()}; }
double angleOf(const Eigen::Vector2d& v) { return std::atan2(v.y(), v.x()); }

Error couplerPointError(std::string message) {
  return Error{ErrorCode::InvalidValue, "couplerPoint", std::move(message)};
}

// The point that is traced: the one named, or the first on the coupler. asFourBar has already
// made sure that every point fixed on a link is on the coupler.
Result<PointId> tracedPoint(const Mechanism& m, const FourBarStructure& f, const std::optional<std::string>& name) {
  std::string onCoupler;
  for (const Point& p : m.points)
    if (std::holds_alternative<AttachedPoint>(p.definition)) onCoupler += (onCoupler.empty() ? "" : ", ") + p.name;
  if (onCoupler.empty())
    return couplerPointError(
        "this four-bar has no point fixed on its coupler, and cognates are the linkages that "
        "trace such a point's curve: add a coupler point first");
  if (!name) return couplerPointOf(m, f)->id;
  const auto id = m.findPoint(*name);
  if (!id || !std::holds_alternative<AttachedPoint>(m.points[id->index].definition))
    return couplerPointError("couplerPoint must name a point fixed on the coupler (got \"" + *name +
                             "\"; the points on it: " + onCoupler + ")");
  return *id;
}

FourBarJoints jointsAt(const SweepResult& s, std::size_t j, const FourBarStructure& f, PointId p) {
  return {s.position[f.o2.index][j], s.position[f.o4.index][j], s.position[f.b.index][j], s.position[f.c.index][j],
          s.position[p.index][j]};
}

// The four-bar through `j` with its input at `input` (rad) there: the crank's phase puts B
// where it is, and of the two branches the one whose C lands nearest the constructed C.
Result<Mechanism> fourBarThrough(const FourBarJoints& j, double input, const std::string& unit,
                                 const std::string& which) {
  const Eigen::Vector2d crank = j.b - j.o2, coupler = j.c - j.b;
  const double couplerLength = coupler.norm();
  const Eigen::Vector2d along = coupler / couplerLength, across(-along.y(), along.x());
  Mechanism m;
  m.lengthUnit = unit;
  m.points = {
      {"O2", GroundPoint{j.o2}},
      {"O4", GroundPoint{j.o4}},
      {"B", CrankPoint{fourbar::kO2, crank.norm(), std::remainder(angleOf(crank) - input, 2.0 * kPi)}},
      {"C", RrrPoint{fourbar::kB, couplerLength, fourbar::kO4, (j.c - j.o4).norm(), Branch::Open}},
      {"P", AttachedPoint{fourbar::kCoupler, (j.p - j.b).dot(along), (j.p - j.b).dot(across)}},
  };
  m.links = {{"crank", fourbar::kO2, fourbar::kB},
             {"coupler", fourbar::kB, fourbar::kC},
             {"rocker", fourbar::kO4, fourbar::kC}};
  if (auto e = checkMechanism(m))
    return couplerPointError(which +
                             " would not be a linkage Linkwright can hold (the coupler point is too near B "
                             "or C): " +
                             e->message);
  SolveRequest positions;
  positions.velocities = positions.accelerations = positions.transmissionAngles = false;
  auto& jointC = std::get<RrrPoint>(m.points[fourbar::kC.index].definition);
  double bestMiss = std::numeric_limits<double>::infinity();
  Branch best = Branch::Open;
  for (const Branch branch : {Branch::Open, Branch::Crossed}) {
    jointC.branch = branch;
    const auto pose = solvePose(m, DriverState{input, 0.0, 0.0}, positions);
    if (!pose) continue;
    const double miss = (pose->position[fourbar::kC.index] - j.c).norm();
    if (miss < bestMiss) {
      bestMiss = miss;
      best = branch;
    }
  }
  jointC.branch = best;
  const double size = std::max({crank.norm(), couplerLength, jointC.secondLength, (j.o4 - j.o2).norm()});
  if (!(bestMiss <= 1e-6 * size))
    return Error{ErrorCode::NotAssemblable, "design",
                 which + " cannot be assembled where the construction puts its joints (at the original's input " +
                     formatShort(radToDeg(input)) + "°)"};
  return m;
}

CognateFourBar fourBarOf(Design design, std::array<OriginalLink, 3> turnsWith) {
  CognateFourBar r;
  r.fourBar = *asFourBar(design.mechanism);
  r.crankPivot = std::get<GroundPoint>(design.mechanism.points[r.fourBar.o2.index].definition).position;
  r.rockerPivot = std::get<GroundPoint>(design.mechanism.points[r.fourBar.o4.index].definition).position;
  r.grashof = classifyGrashof(r.fourBar.lengths);
  r.turnsWith = turnsWith;
  r.design = std::move(design);
  return r;
}

// A cognate's design with the grid `from` to `to` (rad), or the original's grid (and speed and
// time base) when its input is the original's.
Result<Design> cognateDesign(Mechanism m, const Design& original, const std::string& which,
                             std::optional<std::pair<double, double>> grid) {
  Design d;
  d.kind = "four-bar";
  d.mechanism = std::move(m);
  d.omega = original.omega;
  if (grid) {
    d.fromDeg = radToDeg(grid->first);
    d.toDeg = radToDeg(grid->second);
    d.samples = std::max<std::size_t>(2, samplesEveryHalfDegree(d.fromDeg, d.toDeg));
  } else {
    d.alpha = original.alpha;
    d.fromDeg = original.fromDeg;
    d.toDeg = original.toDeg;
    d.samples = original.samples;
    d.time = original.time;
  }
  if (auto e = checkDesign(d)) return couplerPointError(which + " is not a design Linkwright can hold: " + e->message);
  return d;
}

}  // namespace

std::complex<double> couplerRatio(const FourBarJoints& j) {
  return (complexOf(j.p) - complexOf(j.b)) / (complexOf(j.c) - complexOf(j.b));
}

CognateJoints cognateJoints(const FourBarJoints& j) {
  const Complex o2 = complexOf(j.o2), o4 = complexOf(j.o4), b = complexOf(j.b), c = complexOf(j.c);
  const Complex z = couplerRatio(j);
  const Complex o6 = o2 + z * (o4 - o2);
  CognateJoints r;
  r.thirdPivot = vectorOf(o6);
  r.first = {j.o2, r.thirdPivot, vectorOf(o2 + z * (c - b)), vectorOf(o6 + z * (c - o4)), j.p};
  r.second = {r.thirdPivot, j.o4, vectorOf(o6 + (1.0 - z) * (b - o2)), vectorOf(o4 + (z - 1.0) * (c - b)), j.p};
  return r;
}

std::string_view toString(OriginalLink link) {
  switch (link) {
  case OriginalLink::Crank: return "crank";
  case OriginalLink::Coupler: return "coupler";
  case OriginalLink::Rocker: return "rocker";
  }
  return "unknown";
}

Result<CognateSet> cognates(const Design& original, const std::optional<std::string>& couplerPoint) {
  if (auto e = checkDesign(original)) return *e;
  const Mechanism& m = original.mechanism;
  const auto fourBar = asFourBar(m);
  if (!fourBar)
    return Error{ErrorCode::InvalidStructure, "mechanism",
                 "cognates are for a four-bar (a crank, a coupler and a rocker on two ground pivots, with points "
                 "fixed on the coupler), and this " +
                     original.kind + " is not one"};
  const auto traced = tracedPoint(m, *fourBar, couplerPoint);
  if (!traced) return traced.error();

  // The cycle: the original's grid or time base, at a resolution the figures can trust.
  SweepSpec cycle = designSweepSpec(original);
  cycle.samples = std::clamp<std::size_t>(cycle.samples, 721, kMaxTurnSamples);
  if (!cycle.time) {
    cycle.omega = 1.0;  // the speed ratios are geometric: any ω will do, and 0 would give none
    cycle.alpha = 0.0;
  }
  SolveRequest request;
  request.accelerations = request.transmissionAngles = false;
  const auto swept = sweep(m, cycle, request);
  if (!swept) return swept.error();
  if (!swept->assembled(0))
    return Error{ErrorCode::NotAssemblable, "design",
                 "the four-bar cannot be assembled at the start of its grid, where its cognates are constructed: " +
                     swept->firstFailure.value_or("")};

  CognateSet set;
  set.couplerPoint = m.points[traced->index].name;
  set.constructedAt = swept->inputAngle[0];
  const FourBarJoints at = jointsAt(*swept, 0, *fourBar, *traced);
  set.z = couplerRatio(at);
  const double tiny = 1e-9;
  if (std::abs(set.z) <= tiny)
    return couplerPointError("the coupler point " + set.couplerPoint +
                             " is at B, the crank–coupler joint, where cognate 1 shrinks to a point (its links would "
                             "have zero length): choose a point away from B and C");
  if (std::abs(1.0 - set.z) <= tiny)
    return couplerPointError("the coupler point " + set.couplerPoint +
                             " is at C, the coupler–rocker joint, where cognate 2 shrinks to a point (its links would "
                             "have zero length): choose a point away from B and C");
  const CognateJoints built = cognateJoints(at);
  set.thirdPivot = built.thirdPivot;
  const std::string& unit = m.lengthUnit;
  auto first = fourBarThrough(built.first, set.constructedAt, unit, "cognate 1");
  if (!first) return first.error();
  auto second = fourBarThrough(built.second, set.constructedAt, unit, "cognate 2");
  if (!second) return second.error();

  const CognateCycle motion = cognateCycle(*swept, *fourBar, *traced);
  // Cognate 1's input over the cycle: its crank's angle less its phase, q0 at sample 0.
  const CrankRun& run = motion.runs[1].front();
  std::pair<double, double> grid{set.constructedAt + run.least - run.start,
                                 set.constructedAt + run.greatest - run.start};
  if (run.greatest - run.least >= 2.0 * kPi * (1.0 - 1e-9)) grid = {set.constructedAt, set.constructedAt + 2.0 * kPi};
  if (!(grid.second - grid.first > 1e-9))
    return couplerPointError(
        "cognate 1's crank turns with the original's coupler, which does not turn in the cycle "
        "(it moves parallel to itself, as a parallelogram's does): cognate 1 cannot be driven");
  auto firstDesign = cognateDesign(std::move(first).value(), original, "cognate 1", grid);
  if (!firstDesign) return firstDesign.error();
  auto secondDesign = cognateDesign(std::move(second).value(), original, "cognate 2", std::nullopt);
  if (!secondDesign) return secondDesign.error();

  using L = OriginalLink;
  set.original = fourBarOf(original, {L::Crank, L::Coupler, L::Rocker});
  set.cognates[0] = fourBarOf(std::move(firstDesign).value(), {L::Coupler, L::Crank, L::Rocker});
  set.cognates[1] = fourBarOf(std::move(secondDesign).value(), {L::Crank, L::Rocker, L::Coupler});
  const std::array<CognateFourBar*, 3> bars{&set.original, &set.cognates[0], &set.cognates[1]};
  for (std::size_t k = 0; k < 3; ++k) {
    bars[k]->worstTransmission = worstTransmissionOverRuns(bars[k]->fourBar.lengths, motion.runs[k]);
    if (bars[k]->turnsWith[0] == L::Coupler) {
      bars[k]->crankSpeedRatioMin = motion.couplerSpeedRatioMin;
      bars[k]->crankSpeedRatioMax = motion.couplerSpeedRatioMax;
    }
  }
  return set;
}

}  // namespace linkwright::kinematics
