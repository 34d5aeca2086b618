// Linkage.balance (kinematics/design/balance_request.h): counterweights for the shaking force,
// or the spring that makes the RMS driving torque least, as the core's one request; its answer
// the core's JSON (linkwright-cli balance --json's, to the bit) as a dict, the balanced design
// as a Linkage, a spring's torque over the turn as arrays, and with `output` the design written
// where the CLI writes it.

#include "python/src/bindings.h"
#include "python/src/convert.h"

#include "kinematics/design/balance_request.h"
#include "kinematics/io/balance_json.h"
#include "kinematics/io/document_json.h"
#include "kinematics/model/units.h"

#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace linkwright::python {
namespace {

namespace k = kinematics;

py::dict balance(const Linkage& linkage, std::optional<std::string> output, std::optional<double> fraction,
                 std::optional<double> radius, std::optional<std::pair<std::string, std::string>> spring,
                 std::optional<std::string> springSearch) {
  const k::BalanceRequest request{fraction, radius, std::move(spring), std::move(springSearch), k::FrontEnd::Python};
  const k::Design design = linkageDesign(linkage);
  k::BalanceRun run = [&] {
    py::gil_scoped_release unlocked;
    return valueOrThrow(k::runBalance(design, request));
  }();
  if (output) writeOrThrow(*output, k::io::writeDocument(run.balanced));
  py::dict out = fromJson(k::io::balanceJson(run, output ? k::io::JsonValue(*output) : k::io::JsonValue(nullptr)))
                     .cast<py::dict>();
  out["linkage"] = py::cast(designLinkage(run.balanced, "the balance of " + linkage.source));
  if (run.spring) {
    std::vector<double> deg = run.spring->angle;
    for (double& v : deg) v = k::radToDeg(v);
    out["angle_deg"] = array(deg);
    out["torque_before_Nm"] = array(run.spring->torqueBefore);
    out["torque_after_Nm"] = array(run.spring->torqueAfter);
  }
  return out;
}

}  // namespace

void bindBalance(py::class_<Linkage>& linkage) {
  linkage.def("balance", &balance, py::arg("output") = py::none(), py::kw_only(), py::arg("fraction") = py::none(),
              py::arg("radius") = py::none(), py::arg("spring") = py::none(), py::arg("spring_search") = py::none(),
              "The design balanced, as linkwright-cli balance --json: counterweights that balance the shaking "
              "force of a four-bar or slider-crank with masses (fraction: a slider-crank's share of the "
              "reciprocating mass balanced, 0 to 1, default 0.5; radius: each counterweight's distance from its "
              "pivot in lengths of its link, 0.1 to 10, default 1), with one turn's figures before and after; or "
              "spring=(A, B), the spring between two points (each 'LINK:POINT', or a ground point's name alone) "
              "that makes the RMS driving torque least; or spring_search=LINK, that spring from a point searched on "
              "LINK to one searched on the frame. The dict's 'linkage' is the balanced design (a Linkage); a "
              "spring's angle_deg, torque_before_Nm and torque_after_Nm are arrays over the turn. With output=PATH "
              "the design is written there as a document, atomically (OSError if it cannot be, the old file kept).");
}

}  // namespace linkwright::python
