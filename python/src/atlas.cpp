// linkwright.Atlas (kinematics/explore/coupler_atlas.h): the coupler-curve atlas's grid, its
// cells computed and classified by the core, a page at a time (cells [first, first + count)),
// so linkwright.batch can compute pages as Dask tasks. A cell is a dict with linkwright-cli
// atlas --json's names, and its curve as NumPy arrays.

#include "python/src/bindings.h"
#include "python/src/convert.h"

#include "kinematics/explore/atlas_filter.h"
#include "kinematics/explore/coupler_atlas.h"
#include "kinematics/model/units.h"

#include <pybind11/stl.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

LINKWRIGHT_PYTHON_REFUSE_UNINITIALISED(linkwright::kinematics::AtlasAxes)

namespace linkwright::python {
namespace {

namespace k = kinematics;

py::tuple xy(const Eigen::Vector2d& p) { return py::make_tuple(number(p.x()), number(p.y())); }

py::object array(const std::vector<double>& values) { return maskedArray(values, {}); }

py::dict cellDict(std::size_t index, const k::AtlasCell& c) {
  const k::CurveFeatures& f = c.features;
  py::dict d;
  d["cell"] = index;
  d["coupler"] = number(c.key.lengths.coupler);
  d["rocker"] = number(c.key.lengths.rocker);
  d["frame"] = number(c.key.lengths.frame);
  d["along"] = number(c.key.point.along);
  d["across"] = number(c.key.point.across);
  d["branch"] = c.key.branch == k::Branch::Open ? "open" : "crossed";
  d["class"] = std::string(k::toString(c.grashof.category));
  d["crank"] = std::string(k::toString(c.motion));
  std::vector<double> x, y, crank;
  for (std::size_t i = 0; i < c.curve.point.size(); ++i) {
    x.push_back(c.curve.point[i].x());
    y.push_back(c.curve.point[i].y());
    crank.push_back(k::radToDeg(c.curve.crankAngle[i]));
  }
  d["x"] = array(x);
  d["y"] = array(y);
  d["crank_deg"] = array(crank);
  d["size"] = number(f.size);
  d["features"] = k::featureNames(f);
  py::list cusps, crunodes;
  for (const k::Cusp& p : f.cusps) {
    py::dict cusp;
    cusp["crank_deg"] = degrees(p.crankAngle);
    cusp["point"] = xy(p.point);
    cusp["speed"] = number(p.speed);
    cusps.append(cusp);
  }
  for (const k::Crunode& p : f.crunodes) {
    py::dict crunode;
    crunode["point"] = xy(p.point);
    crunode["crank_deg"] = py::make_tuple(degrees(p.crankAngles[0]), degrees(p.crankAngles[1]));
    crunodes.append(crunode);
  }
  d["cusps"] = cusps;
  d["crunodes"] = crunodes;
  d["symmetry"] = py::none();
  d["straight"] = py::none();
  d["circular"] = py::none();
  if (f.symmetry) {
    py::dict s;
    s["point"] = xy(f.symmetry->point);
    s["axis_deg"] = degrees(std::atan2(f.symmetry->direction.y(), f.symmetry->direction.x()));
    s["deviation"] = number(f.symmetry->deviation);
    d["symmetry"] = s;
  }
  if (f.straight) {
    py::dict s;
    s["from_deg"] = degrees(f.straight->fromAngle);
    s["to_deg"] = degrees(f.straight->toAngle);
    s["from"] = xy(f.straight->from);
    s["to"] = xy(f.straight->to);
    s["length"] = number(f.straight->length);
    s["deviation"] = number(f.straight->deviation);
    d["straight"] = s;
  }
  if (f.circular) {
    py::dict s;
    s["from_deg"] = degrees(f.circular->fromAngle);
    s["to_deg"] = degrees(f.circular->toAngle);
    s["centre"] = xy(f.circular->centre);
    s["radius"] = number(f.circular->radius);
    s["turn_deg"] = degrees(f.circular->turn);
    s["deviation"] = number(f.circular->deviation);
    d["circular"] = s;
  }
  return d;
}

k::AtlasAxes atlasAxes(std::vector<double> coupler, std::vector<double> rocker, std::vector<double> frame,
                       std::vector<double> along, std::vector<double> across, const std::string& branch,
                       long long samples) {
  if (branch != "open" && branch != "crossed")
    throw CoreError(k::Error{k::ErrorCode::InvalidValue, "branch",
                             "branch must be \"open\" or \"crossed\" (got \"" + branch + "\")"});
  if (samples < 0)  // before it becomes unsigned; the core checks the range
    throw CoreError(k::Error{k::ErrorCode::InvalidValue, "samples",
                             "samples must be between " + std::to_string(k::kMinAtlasSamples) + " and " +
                                 std::to_string(k::kMaxAtlasSamples) + " (got " + std::to_string(samples) + ")"});
  k::AtlasAxes axes{std::move(coupler),
                    std::move(rocker),
                    std::move(frame),
                    std::move(along),
                    std::move(across),
                    branch == "open" ? k::Branch::Open : k::Branch::Crossed,
                    static_cast<std::size_t>(samples)};
  if (auto e = k::checkAtlasAxes(axes)) throw CoreError(*e);
  return axes;
}

std::size_t checkedIndex(const k::AtlasAxes& axes, long long index, const char* field) {
  const auto cells = static_cast<long long>(k::atlasCellCount(axes));
  if (index < 0 || index >= cells)
    throw CoreError(k::Error{k::ErrorCode::InvalidValue, field,
                             std::string(field) + " must be between 0 and " + std::to_string(cells - 1) + " (got " +
                                 std::to_string(index) + ")"});
  return static_cast<std::size_t>(index);
}

py::list page(const k::AtlasAxes& axes, long long first, std::optional<long long> count,
              const std::optional<std::string>& filter) {
  const std::size_t from = checkedIndex(axes, first, "first");
  const std::size_t cells = k::atlasCellCount(axes);
  if (count && *count < 0)
    throw CoreError(
        k::Error{k::ErrorCode::InvalidValue, "count", "count must be at least 0 (got " + std::to_string(*count) + ")"});
  const std::size_t n = count ? static_cast<std::size_t>(*count) : cells - from;
  k::AtlasFilter wanted;
  if (filter) wanted = valueOrThrow(k::parseAtlasFilter(*filter));
  auto computed = [&] {
    py::gil_scoped_release unlocked;
    return k::computeAtlasPage(axes, from, n);
  }();
  const std::vector<k::AtlasCell> found = valueOrThrow(std::move(computed));
  py::list out;
  for (std::size_t i = 0; i < found.size(); ++i)
    if (k::matchesFilter(found[i], wanted)) out.append(cellDict(from + i, found[i]));
  return out;
}

}  // namespace

void bindAtlas(py::module_& module) {
  py::class_<k::AtlasAxes>(
      module, "Atlas",
      "The coupler-curve atlas's grid (linkwright-cli atlas): four-bars with crank 1 over coupler, rocker and frame "
      "ratios, and the coupler point's place along and across B->C in coupler lengths, each cell's curve the "
      "solver's coupler path, classified (cusps, crunodes, symmetric, straight, circular). Cells are numbered "
      "coupler slowest, across fastest. page() computes cells; picklable, for linkwright.batch.atlas.")
      .def(py::init(&atlasAxes), py::kw_only(), py::arg("coupler") = k::AtlasAxes{}.coupler,
           py::arg("rocker") = k::AtlasAxes{}.rocker, py::arg("frame") = k::AtlasAxes{}.frame,
           py::arg("along") = k::AtlasAxes{}.along, py::arg("across") = k::AtlasAxes{}.across,
           py::arg("branch") = "open", py::arg("samples") = static_cast<long long>(k::AtlasAxes{}.samples))
      .def_property_readonly("cells", &k::atlasCellCount, "How many cells the grid has.")
      .def(
          "page",
          [](const k::AtlasAxes& axes, long long first, std::optional<long long> count,
             const std::optional<std::string>& filter) { return page(axes, first, count, filter); },
          py::arg("first") = 0, py::arg("count") = py::none(), py::arg("filter") = py::none(),
          "Cells [first, first + count) (to the end if count is None), computed and classified, as dicts with "
          "linkwright-cli atlas --json's names (cell, coupler, rocker, frame, along, across, branch, class, crank, "
          "size, features, cusps, crunodes, symmetry, straight, circular) and the curve: x, y (crank lengths, O2 at "
          "the origin, O4 on +x) and crank_deg. filter='cusp,straight' keeps the cells that have all of those.")
      .def(
          "linkage",
          [](const k::AtlasAxes& axes, long long cell, double crank, const std::string& unit) {
            const k::AtlasCellKey key = k::atlasCellKey(axes, checkedIndex(axes, cell, "cell"));
            return designLinkage(valueOrThrow(k::atlasCellDesign(key, crank, unit)), "Atlas.linkage()");
          },
          py::arg("cell"), py::kw_only(), py::arg("crank") = 1.0, py::arg("unit") = "mm",
          "Cell `cell`'s four-bar as a Linkage, its crank `crank` long in `unit`, its grid its curve's crank range.")
      .def(py::pickle(
          [](const k::AtlasAxes& a) {
            return py::make_tuple(a.coupler, a.rocker, a.frame, a.along, a.across, a.branch == k::Branch::Open,
                                  a.samples);
          },
          [](const py::tuple& state) {
            return fromPickle("Atlas", "coupler, rocker, frame, along, across, open branch, samples", state, 7,
                              [](const py::tuple& t) {
                                return atlasAxes(t[0].cast<std::vector<double>>(), t[1].cast<std::vector<double>>(),
                                                 t[2].cast<std::vector<double>>(), t[3].cast<std::vector<double>>(),
                                                 t[4].cast<std::vector<double>>(),
                                                 t[5].cast<bool>() ? "open" : "crossed", t[6].cast<long long>());
                              });
          }));
}

}  // namespace linkwright::python
