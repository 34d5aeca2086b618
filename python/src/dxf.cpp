// Linkage.dxf (kinematics/design/drawing_request.h): the links drawn at one input and written
// as a DXF file through the writer linkwright-cli dxf uses (kinematics/io/dxf_export.h), so the
// two files are the same bytes.

#include "python/src/bindings.h"
#include "python/src/convert.h"

#include "kinematics/design/drawing_request.h"
#include "kinematics/io/dxf_export.h"

#include <pybind11/stl.h>

#include <optional>
#include <string>

namespace linkwright::python {
namespace {

namespace k = kinematics;

py::dict dxf(const Linkage& linkage, const std::string& output, std::optional<double> at, std::optional<double> hole,
             std::optional<double> width) {
  const k::DrawingRequest request{at, {hole, width}, k::FrontEnd::Python};
  const k::DrawingRun run = valueOrThrow(k::runDrawing(linkage.mechanism, linkage.grid, linkage.source, request));
  if (auto e = k::io::writeDxf(run.drawing, output)) {
    PyErr_SetString(PyExc_OSError, e->message.c_str());
    throw py::error_already_set();
  }
  py::dict out;
  out["output"] = output;
  out["at"] = run.at;
  out["at_text"] = run.atText;
  out["hole"] = run.drawing.holeDiameter;
  out["width"] = run.drawing.plateWidth;
  py::list layers;
  for (const k::DrawingLayer& layer : run.drawing.layers) layers.append(layer.name);
  out["layers"] = layers;
  out["insunits"] = k::io::dxfInsUnits(run.drawing.lengthUnit);
  return out;
}

}  // namespace

void bindDxf(py::class_<Linkage>& linkage) {
  linkage.def("dxf", &dxf, py::arg("output"), py::kw_only(), py::arg("at") = py::none(), py::arg("hole") = py::none(),
              py::arg("width") = py::none(),
              "Writes the links as a DXF R2000 drawing at true size to `output`, as linkwright-cli dxf (the same "
              "bytes): at the input `at` (degrees for a crank, the length unit for a linear driver; default where "
              "the design starts), pivot holes `hole` across and plates `width` wide (the length unit; default a "
              "fifth of the shortest joint spacing, and twice the hole). Written whole or not at all (OSError, the "
              "old file kept). Returns a dict of output, at, at_text, hole, width, layers (their names) and insunits "
              "(the DXF unit code).");
}

}  // namespace linkwright::python
