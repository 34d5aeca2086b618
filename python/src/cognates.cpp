// Linkage.cognates (kinematics/explore/cognates.h): a four-bar's two Roberts–Chebyshev cognates,
// the core's JSON (linkwright-cli cognates --json's, to the bit) as a dict, each cognate also as
// a Linkage, and with `output` both written as documents where the CLI writes them.

#include "python/src/bindings.h"
#include "python/src/convert.h"

#include "kinematics/explore/cognates.h"
#include "kinematics/io/cognates_json.h"
#include "kinematics/io/document_json.h"

#include <pybind11/stl.h>

#include <array>
#include <optional>
#include <string>

namespace linkwright::python {
namespace {

namespace k = kinematics;

py::object cognates(const Linkage& linkage, std::optional<std::string> output,
                    std::optional<std::string> couplerPoint) {
  const k::Design design = linkageDesign(linkage);
  auto set = k::cognates(design, couplerPoint);
  if (!set) {
    k::Error e = set.error();
    if (e.field == "couplerPoint" && couplerPoint) e.message = "coupler_point: " + e.message;
    throw CoreError(e);
  }
  std::array<std::optional<std::string>, 2> files;
  if (output) {
    // Both documents, as the CLI writes them: a refusal above wrote nothing.
    files = {*output + "-1.linkwright", *output + "-2.linkwright"};
    for (std::size_t i = 0; i < 2; ++i)
      writeOrThrow(*files[i], k::io::writeDocument(set->cognates[i].design),
                   i == 1 ? " (" + *files[0] + " was written)" : std::string());
  }
  py::dict out = fromJson(k::io::cognatesJson(*set, design.mechanism.lengthUnit, files)).cast<py::dict>();
  py::list linkages = out["linkages"].cast<py::list>();
  linkages[0]["linkage"] = py::cast(linkage);
  for (std::size_t i = 0; i < 2; ++i)
    linkages[i + 1]["linkage"] =
        py::cast(designLinkage(set->cognates[i].design, "cognate " + std::to_string(i + 1) + " of " + linkage.source));
  return out;
}

}  // namespace

void bindCognates(py::class_<Linkage>& linkage) {
  linkage.def("cognates", &cognates, py::arg("output") = py::none(), py::kw_only(),
              py::arg("coupler_point") = py::none(),
              "A four-bar's two Roberts–Chebyshev cognates of the curve its coupler point traces, as "
              "linkwright-cli cognates --json: a dict of coupler_point, z, third_pivot, constructed_at_deg, "
              "length_unit and linkages (the original, cognate 1 and cognate 2: pivots, lengths, class, "
              "worst_transmission_deg, which original link each link turns with, the crank's speed ratio), each "
              "with its 'linkage' (a Linkage; the cognates with the grids their documents have). coupler_point "
              "names the point whose curve they trace (default: the first on the coupler; four_bar(coupler_point=) "
              "places one). With output=PREFIX, writes PREFIX-1.linkwright and PREFIX-2.linkwright, each atomically "
              "(a file that cannot be written raises OSError and keeps the old one); 'file' says where.");
}

}  // namespace linkwright::python
