// Linkage.polygons and Linkage.inversions (kinematics/analysis/vector_polygon.h,
// inversions.h): the classroom's velocity and acceleration polygons at crank angles, and a
// four-bar's or slider-crank's inversions, each the core's JSON (linkwright-cli polygon --json's
// and inversions --json's, to the bit) as Python objects.

#include "python/src/bindings.h"
#include "python/src/convert.h"

#include "kinematics/analysis/inversions.h"
#include "kinematics/analysis/vector_polygon.h"
#include "kinematics/design/sweep_grid.h"
#include "kinematics/io/inversions_json.h"
#include "kinematics/io/polygon_json.h"
#include "kinematics/model/number_text.h"

#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <vector>

namespace linkwright::python {
namespace {

namespace k = kinematics;

// The keywords polygon takes, as the core's grid fields are spelled in its refusals.
const k::GridFieldNames& polygonNames() {
  static const k::GridFieldNames names{"rpm", "omega", "alpha", "", "", "", "", "", "", "", "", "", "", "", ""};
  return names;
}

py::object polygonsAt(const Linkage& linkage, double deg, std::optional<double> rpm, std::optional<double> omega,
                      std::optional<double> alpha) {
  const auto driver = valueOrThrow(k::crankStateAt(deg, {rpm, omega, alpha}, linkage.grid, polygonNames(), "at"));
  const auto polygons = k::polygonsAt(linkage.mechanism, driver);
  if (!polygons) {
    k::Error e = polygons.error();
    e.message = "crank angle " + k::formatShort(deg) + "°: " + e.message;  // as the CLI says which --at
    throw CoreError(e);
  }
  return fromJson(k::io::polygonsJson(deg, driver, *polygons));
}

py::object polygons(const Linkage& linkage, const py::object& at, std::optional<double> rpm,
                    std::optional<double> omega, std::optional<double> alpha) {
  if (auto e = k::checkPolygonInput(linkage.mechanism, linkage.source)) throw CoreError(*e);
  if (py::isinstance<py::float_>(at) || py::isinstance<py::int_>(at))
    return polygonsAt(linkage, at.cast<double>(), rpm, omega, alpha);
  py::list all;
  for (const double deg : at.cast<std::vector<double>>()) all.append(polygonsAt(linkage, deg, rpm, omega, alpha));
  return all;
}

py::object inversions(const Linkage& linkage) {
  const auto all = valueOrThrow(k::linkageInversions(linkage.mechanism, linkage.source, linkage.kind));
  return fromJson(k::io::inversionsJson(all, linkage.mechanism.lengthUnit));
}

}  // namespace

void bindClassroom(py::class_<Linkage>& linkage) {
  linkage.def("polygons", &polygons, py::arg("at"), py::kw_only(), py::arg("rpm") = py::none(),
              py::arg("omega") = py::none(), py::arg("alpha") = py::none(),
              "The velocity and acceleration polygons at crank angle `at` (degrees; a list of angles gives a list), "
              "as linkwright-cli polygon --json: a dict of crank_angle_deg, omega_rad_s, alpha_rad_s2 and the "
              "'velocity' and 'acceleration' polygons (unit, box, equations, vectors in drawing order with from, "
              "to and magnitude, images). The crank's speed is rpm (rev/min) or omega (rad/s), its acceleration "
              "alpha (rad/s²); what is not given is the linkage's own. Crank-driven linkages only; a pose that "
              "cannot be assembled, or a toggle, is refused.");
  linkage.def("inversions", &inversions,
              "The four inversions of a four-bar or a slider-crank driven by its crank, as linkwright-cli "
              "inversions --json: a dict of linkage ('four-bar' or 'slider-crank'), length_unit and inversions, "
              "each with the link grounded, the one driven, its class and which links turn fully.");
}

}  // namespace linkwright::python
