// linkwright.PathSearch (kinematics/synthesis/path_generation.h): the path generator's search
// whole, or block by block for linkwright.batch, whose Dask tasks run blocks anywhere and hand
// them back pickled; merge() makes them the whole search's answer. Each candidate comes with its
// design as a Linkage.

#include "python/src/bindings.h"
#include "python/src/convert.h"
#include "python/src/linkage.h"

#include "kinematics/model/units.h"
#include "kinematics/synthesis/path_generation.h"

#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

LINKWRIGHT_PYTHON_REFUSE_UNINITIALISED(linkwright::kinematics::PathStartBlock)

namespace linkwright::python {
namespace {

namespace k = kinematics;

// The core names the search's fields as the C++ does; the keywords are spelled here.
k::Error spelled(k::Error e) {
  if (e.field == "maxEvaluations") {
    e.field = "max_evaluations";
    e.message.replace(0, std::string("maxEvaluations").size(), "max_evaluations");
  }
  if (e.field.rfind("timing", 0) == 0) e.field = "timing_deg" + e.field.substr(6);
  return e;
}

template <typename T>
T orRaise(k::Result<T> result) {
  if (!result) throw CoreError(spelled(result.error()));
  return std::move(result).value();
}

// A search as the keywords gave it (kept as given, so a pickled search is the same search) and
// as the core takes it.
struct PathSearch {
  std::vector<std::pair<double, double>> points;
  std::optional<std::vector<double>> timingDeg;
  std::string timingFrom;
  bool fullRotation = false;
  std::string unit;
  int starts = 0;
  std::uint32_t seed = 0;
  int keep = 0;
  int maxEvaluations = 0;

  k::PathTarget target() const {
    k::PathTarget t;
    for (const auto& [x, y] : points) t.points.emplace_back(x, y);
    if (timingDeg)
      for (const double deg : *timingDeg) t.timing.push_back(k::degToRad(deg));
    t.timingReference = timingFrom == "frame" ? k::TimingReference::Frame : k::TimingReference::Start;
    t.needsFullRotation = fullRotation;
    t.lengthUnit = unit;
    return t;
  }
  k::PathOptions options() const { return {starts, seed, static_cast<std::size_t>(keep), maxEvaluations}; }
};

}  // namespace
}  // namespace linkwright::python

LINKWRIGHT_PYTHON_REFUSE_UNINITIALISED(linkwright::python::PathSearch)

namespace linkwright::python {
namespace {

PathSearch pathSearch(std::vector<std::pair<double, double>> points, std::optional<std::vector<double>> timingDeg,
                      std::string timingFrom, bool fullRotation, std::string unit, int starts, std::uint32_t seed,
                      int keep, int maxEvaluations) {
  if (timingFrom != "start" && timingFrom != "frame")
    throw CoreError(k::Error{k::ErrorCode::InvalidValue, "timing_from",
                             "timing_from must be \"start\" or \"frame\" (got \"" + timingFrom + "\")"});
  if (keep < 1)  // before it becomes unsigned; the core checks the rest
    throw CoreError(k::Error{k::ErrorCode::InvalidValue, "keep",
                             "keep must be between 1 and 1000 (got " + std::to_string(keep) + ")"});
  PathSearch s{
      std::move(points), std::move(timingDeg), std::move(timingFrom), fullRotation, std::move(unit), starts, seed, keep,
      maxEvaluations};
  // Refused now, with the core's sentence, rather than in a task on a cluster.
  const k::PathTarget target = s.target();
  auto checked = k::runPathStartBlock(target, s.options(), -1);
  if (!checked && checked.error().field != "block") throw CoreError(spelled(checked.error()));
  return s;
}

py::tuple xy(const Eigen::Vector2d& p) { return py::make_tuple(number(p.x()), number(p.y())); }

py::dict candidateDict(const k::PathCandidate& c) {
  py::dict d;
  d["linkage"] = designLinkage(c.candidate.design, "synthesize_path()");
  d["o2"] = xy(c.o2);
  d["o4"] = xy(c.o4);
  d["frame"] = number(c.lengths.frame);
  d["crank"] = number(c.lengths.crank);
  d["coupler"] = number(c.lengths.coupler);
  d["rocker"] = number(c.lengths.rocker);
  d["coupler_point"] = py::make_tuple(number(c.couplerPoint.along), number(c.couplerPoint.across));
  d["branch"] = c.branch == k::Branch::Open ? "open" : "crossed";
  py::list angles, distances, defects;
  for (const double a : c.crankAngles) angles.append(degrees(a));
  for (const double x : c.distances) distances.append(number(x));
  for (const k::Defect& defect : c.candidate.defects) defects.append(defect.message);
  d["crank_angles_deg"] = angles;
  d["distances"] = distances;
  d["worst_distance"] = number(c.worstDistance);
  d["grashof"] = c.candidate.grashof ? py::object(py::str(std::string(k::toString(c.candidate.grashof->category))))
                                     : py::object(py::none());
  d["min_transmission_deg"] = degrees(c.candidate.minTransmission);
  d["defects"] = defects;
  d["start"] = c.start;
  return d;
}

py::dict synthesisDict(const k::PathSynthesis& s) {
  py::dict d;
  py::list candidates;
  for (const k::PathCandidate& c : s.candidates) candidates.append(candidateDict(c));
  d["candidates"] = candidates;
  d["scale"] = number(s.scale);
  d["starts_run"] = s.startsRun;
  d["starts_not_assembled"] = s.startsNotAssembled;
  d["cancelled"] = s.cancelled;
  return d;
}

// A block's state for pickle: plain numbers, which pickle keeps to the bit.
py::tuple blockState(const k::PathStartBlock& b) {
  py::list minima;
  for (const k::PathMinimum& m : b.kept)
    minima.append(py::make_tuple(m.o2.x(), m.o2.y(), m.beta, m.frame, m.crank, m.coupler, m.rocker, m.along, m.across,
                                 m.branch == k::Branch::Open ? 0 : 1, m.crankAngles, m.worst, m.start, m.seconds));
  return py::make_tuple(b.block, b.search, b.startsRun, b.startsNotAssembled, b.cancelled, minima);
}

k::PathStartBlock blockFromTuple(const py::tuple& t) {
  k::PathStartBlock b;
  b.block = t[0].cast<int>();
  b.search = t[1].cast<std::uint64_t>();
  b.startsRun = t[2].cast<int>();
  b.startsNotAssembled = t[3].cast<int>();
  b.cancelled = t[4].cast<bool>();
  for (const py::handle item : t[5].cast<py::list>()) {
    const auto m = item.cast<py::tuple>();
    if (m.size() != 14) throw py::cast_error("a minimum of 14 numbers");
    k::PathMinimum x;
    x.o2 = {m[0].cast<double>(), m[1].cast<double>()};
    x.beta = m[2].cast<double>();
    x.frame = m[3].cast<double>();
    x.crank = m[4].cast<double>();
    x.coupler = m[5].cast<double>();
    x.rocker = m[6].cast<double>();
    x.along = m[7].cast<double>();
    x.across = m[8].cast<double>();
    x.branch = m[9].cast<int>() == 0 ? k::Branch::Open : k::Branch::Crossed;
    x.crankAngles = m[10].cast<std::vector<double>>();
    x.worst = m[11].cast<double>();
    x.start = m[12].cast<int>();
    x.seconds = m[13].cast<double>();
    b.kept.push_back(std::move(x));
  }
  return b;
}

// A pickle that is not a block's state (another version's, or edited) is refused with a
// sentence; one that is a block's may still not be this search's, which merge() refuses.
k::PathStartBlock blockFromState(const py::tuple& t) {
  const CoreError notABlock(k::Error{k::ErrorCode::InvalidValue, "state",
                                     "linkwright.PathStartBlock: not a pickled block of this version "
                                     "(a tuple of block, search, starts run, starts not assembled, cancelled, "
                                     "minima)"});
  if (t.size() != 6) throw notABlock;
  try {
    return blockFromTuple(t);
  } catch (const py::cast_error&) {
    throw notABlock;
  }
}

}  // namespace

void bindSynthesis(py::module_& module) {
  py::class_<k::PathStartBlock>(module, "PathStartBlock",
                                "One block of a path synthesis's starts (path_start_block), to merge with "
                                "path_synthesis_from_blocks; picklable, so a Dask task can return it.")
      .def_property_readonly("block", [](const k::PathStartBlock& b) { return b.block; })
      .def_property_readonly("starts_run", [](const k::PathStartBlock& b) { return b.startsRun; })
      .def_property_readonly(
          "kept", [](const k::PathStartBlock& b) { return b.kept.size(); }, "How many distinct minima it kept.")
      .def(py::pickle([](const k::PathStartBlock& b) { return blockState(b); }, &blockFromState));

  module.attr("PATH_STARTS_PER_BLOCK") = k::kPathStartsPerBlock;
  py::class_<PathSearch>(
      module, "PathSearch",
      "A path synthesis, as linkwright-cli synthesize path: four-bars whose coupler point P passes through 4 to 10 "
      "points (x, y) in `unit`, by Levenberg-Marquardt from `starts` seeded starts, keeping the best `keep` distinct "
      "results, each measured with the pose solver. timing_deg gives the crank angle at each point (from the first "
      "point's angle with timing_from='start', from the frame line with 'frame'). run() searches; run_block() and "
      "merge() split it in blocks of PATH_STARTS_PER_BLOCK starts for linkwright.batch. Picklable.")
      .def(py::init(&pathSearch), py::arg("points"), py::kw_only(), py::arg("timing_deg") = py::none(),
           py::arg("timing_from") = "start", py::arg("full_rotation") = false, py::arg("unit") = "mm",
           py::arg("starts") = k::kDefaultPathStarts, py::arg("seed") = k::kDefaultPathSeed, py::arg("keep") = 10,
           py::arg("max_evaluations") = 200)
      .def_property_readonly(
          "blocks", [](const PathSearch& s) { return k::pathStartBlockCount(s.options()); },
          "How many blocks its starts make.")
      .def(
          "run",
          [](const PathSearch& s) {
            auto found = [&] {
              py::gil_scoped_release unlocked;
              return k::synthesisePath(s.target(), s.options());
            }();
            return synthesisDict(orRaise(std::move(found)));
          },
          "Runs the whole search. Returns a dict: candidates (best first, each a dict: linkage, o2, o4, frame, "
          "crank, coupler, rocker, coupler_point, branch, crank_angles_deg, distances, worst_distance, grashof, "
          "min_transmission_deg, defects, start), scale, starts_run, starts_not_assembled, cancelled.")
      .def(
          "run_block",
          [](const PathSearch& s, int block) {
            auto ran = [&] {
              py::gil_scoped_release unlocked;
              return k::runPathStartBlock(s.target(), s.options(), block);
            }();
            return orRaise(std::move(ran));
          },
          py::arg("block"),
          "Runs block `block` (0-based) of the search alone: its starts depend on the seed and their index only.")
      .def(
          "merge",
          [](const PathSearch& s, const std::vector<k::PathStartBlock>& blocks) {
            auto merged = [&] {
              py::gil_scoped_release unlocked;
              return k::pathSynthesisFromBlocks(s.target(), s.options(), {}, blocks);
            }();
            return synthesisDict(orRaise(std::move(merged)));
          },
          py::arg("blocks"),
          "run()'s answer from the search's blocks (run_block), merged in block order: the same to the last bit. "
          "A block missing makes the result cancelled.")
      .def(py::pickle(
          [](const PathSearch& s) {
            return py::make_tuple(s.points, s.timingDeg, s.timingFrom, s.fullRotation, s.unit, s.starts, s.seed, s.keep,
                                  s.maxEvaluations);
          },
          [](const py::tuple& state) {
            return fromPickle(
                "PathSearch", "points, timing, timing from, full rotation, unit, starts, seed, keep, evaluations",
                state, 9, [](const py::tuple& t) {
                  return pathSearch(t[0].cast<std::vector<std::pair<double, double>>>(),
                                    t[1].cast<std::optional<std::vector<double>>>(), t[2].cast<std::string>(),
                                    t[3].cast<bool>(), t[4].cast<std::string>(), t[5].cast<int>(),
                                    t[6].cast<std::uint32_t>(), t[7].cast<int>(), t[8].cast<int>());
                });
          }));
}

}  // namespace linkwright::python
