// The closed-form synthesis problems of linkwright-cli synthesize (kinematics/synthesis/):
// a crank-rocker for a swing and time ratio, a slider-crank or a shaper for a stroke, a
// Freudenstein function generator, a motion generator through two or three coupler poses. Each returns its candidate as the path search's are
// described (synthesis.cpp): the design as a Linkage, its error, Grashof class, worst
// transmission angle and defects.

#include "python/src/bindings.h"
#include "python/src/convert.h"

#include "kinematics/model/units.h"
#include "kinematics/synthesis/function_generation.h"
#include "kinematics/synthesis/motion_generation.h"
#include "kinematics/synthesis/stroke_shaper.h"
#include "kinematics/synthesis/stroke_slider_crank.h"
#include "kinematics/synthesis/swing_crank_rocker.h"

#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace linkwright::python {
namespace {

namespace k = kinematics;

// The core's field names as the keywords spell them.
k::Error spelled(k::Error e) {
  for (const auto& [core, keyword] : {std::pair<std::string, std::string>{"timeRatio", "time_ratio"},
                                      {"guideHeight", "guide_height"},
                                      {"inputStart", "input_start_deg"},
                                      {"inputSpan", "input_span_deg"},
                                      {"outputStart", "output_start_deg"},
                                      {"outputSpan", "output_span_deg"},
                                      {"circlePoints.a", "circle_a"},
                                      {"circlePoints.b", "circle_b"}})
    if (e.field == core) {
      e.field = keyword;
      if (e.message.rfind(core, 0) == 0) e.message.replace(0, core.size(), keyword);
    }
  return e;
}

template <typename T>
T orRaise(k::Result<T> result) {
  if (!result) throw CoreError(spelled(result.error()));
  return std::move(result).value();
}

k::Error badValue(const std::string& field, const std::string& why) {
  return k::Error{k::ErrorCode::InvalidValue, field, field + " " + why};
}

}  // namespace

py::dict candidateDict(const k::SynthesisCandidate& c, const std::string& source) {
  py::dict d;
  d["linkage"] = designLinkage(c.design, source);
  d["error"] = number(c.error);
  d["grashof"] =
      c.grashof ? py::object(py::str(std::string(k::toString(c.grashof->category)))) : py::object(py::none());
  d["min_transmission_deg"] = degrees(c.minTransmission);
  py::list defects;
  for (const k::Defect& defect : c.defects) defects.append(defect.message);
  d["defects"] = defects;
  return d;
}

void bindProblems(py::module_& module) {
  module.def(
      "synthesize_motion",
      [](const std::vector<std::tuple<double, double, double>>& poses, std::pair<double, double> circleA,
         std::pair<double, double> circleB, std::optional<double> centreA, std::optional<double> centreB,
         bool fullRotation, const std::string& unit) {
        std::vector<k::CouplerPose> coupler;
        for (const auto& [x, y, deg] : poses) coupler.push_back({{x, y}, k::degToRad(deg)});
        const k::CirclePoints circle{{circleA.first, circleA.second}, {circleB.first, circleB.second}};
        const k::MotionOptions options{fullRotation, unit};
        if (coupler.size() != 2 && coupler.size() != 3)
          throw CoreError(badValue("poses", "must number 2 or 3 (got " + std::to_string(coupler.size()) + ")"));
        if (coupler.size() == 3 && (centreA || centreB))
          throw CoreError(badValue(centreA ? "centre_a" : "centre_b",
                                   "applies to two poses only: three poses fix the centre points"));
        const k::MotionSynthesis s =
            orRaise(coupler.size() == 3 ? k::synthesiseMotion3(coupler, circle, {}, options)
                                        : k::synthesiseMotion2(coupler, circle, centreA.value_or(0.0),
                                                               centreB.value_or(0.0), {}, options));
        py::dict d = candidateDict(s.candidate, "synthesize_motion()");
        d["o2"] = py::make_tuple(number(s.o2.x()), number(s.o2.y()));
        d["o4"] = py::make_tuple(number(s.o4.x()), number(s.o4.y()));
        d["frame"] = number(s.lengths.frame);
        d["crank"] = number(s.lengths.crank);
        d["coupler"] = number(s.lengths.coupler);
        d["rocker"] = number(s.lengths.rocker);
        d["branch"] = s.branch == k::Branch::Open ? "open" : "crossed";
        py::list angles;
        for (const double a : s.crankAngles) angles.append(degrees(a));
        d["crank_angles_deg"] = angles;
        return d;
      },
      py::arg("poses"), py::kw_only(), py::arg("circle_a"), py::arg("circle_b"), py::arg("centre_a") = py::none(),
      py::arg("centre_b") = py::none(), py::arg("full_rotation") = false, py::arg("unit") = "mm",
      "A four-bar whose coupler passes through 2 or 3 poses (x, y, angle_deg: its point P and its angle, CCW "
      "from +x), as linkwright-cli synthesize motion: circle points circle_a and circle_b are where the crank's "
      "and the rocker's moving pivots sit at pose 1; with two poses centre_a and centre_b place each centre point "
      "on its bisector (signed distance). Returns a dict: linkage, o2, o4, frame, crank, coupler, rocker, branch, "
      "crank_angles_deg (at each pose), error (0: exact), grashof, min_transmission_deg, defects.");
  module.def(
      "synthesize_crank_rocker",
      [](double swingDeg, double timeRatio, double length, const std::string& scale, const std::string& unit) {
        if (scale != "rocker" && scale != "frame")
          throw CoreError(badValue("scale", "must be \"rocker\" or \"frame\" (got \"" + scale + "\")"));
        const k::SwingTarget target{k::degToRad(swingDeg), timeRatio, length,
                                    scale == "rocker" ? k::SwingScale::Rocker : k::SwingScale::Frame, unit};
        auto found = [&] {
          py::gil_scoped_release unlocked;
          return k::synthesiseCrankRocker(target);
        }();
        if (!found && found.error().field == "swing")  // the keyword is in degrees
          found = k::Error{found.error().code, "swing_deg", found.error().message};
        const k::SwingSynthesis s = orRaise(std::move(found));
        py::dict d = candidateDict(s.best.candidate, "synthesize_crank_rocker()");
        d["frame"] = number(s.best.lengths.frame);
        d["crank"] = number(s.best.lengths.crank);
        d["coupler"] = number(s.best.lengths.coupler);
        d["rocker"] = number(s.best.lengths.rocker);
        d["family"] = s.family.size();
        return d;
      },
      py::arg("swing_deg"), py::kw_only(), py::arg("time_ratio") = 1.0, py::arg("length") = 1.0,
      py::arg("scale") = "rocker", py::arg("unit") = "mm",
      "A crank-rocker whose rocker swings swing_deg with slow/quick time ratio time_ratio, as linkwright-cli "
      "synthesize swing: the one with the best worst transmission angle among the family, scaled so that the "
      "rocker (scale='rocker') or the frame ('frame') is `length`. Returns a dict: linkage, frame, crank, coupler, "
      "rocker, error (0: exact), grashof, min_transmission_deg, defects, family (how many it chose among).");
  module.def(
      "synthesize_slider_crank",
      [](double stroke, double timeRatio, std::optional<double> rod, std::optional<double> offset,
         const std::string& unit) {
        if (rod.has_value() == offset.has_value())
          throw CoreError(badValue(
              "rod", "or offset must be given, one of them (got " + std::string(rod ? "both" : "neither") + ")"));
        const k::StrokeTarget target{stroke, timeRatio, rod ? k::SliderChoice::Rod : k::SliderChoice::Offset,
                                     rod ? *rod : *offset, unit};
        auto found = k::synthesiseSliderCrank(target);
        if (!found && found.error().field == "value")
          found = k::Error{found.error().code, rod ? "rod" : "offset", found.error().message};
        const k::SliderCrankSynthesis s = orRaise(std::move(found));
        py::dict d = candidateDict(s.candidate, "synthesize_slider_crank()");
        d["near_end"] = number(s.nearEnd);
        d["far_end"] = number(s.farEnd);
        d["extended_crank_deg"] = degrees(s.extendedCrankAngle);
        d["folded_crank_deg"] = degrees(s.foldedCrankAngle);
        return d;
      },
      py::arg("stroke"), py::kw_only(), py::arg("time_ratio") = 1.0, py::arg("rod") = py::none(),
      py::arg("offset") = py::none(), py::arg("unit") = "mm",
      "A slider-crank whose slider travels `stroke` with time ratio time_ratio, given its rod length or its "
      "offset (one of them), as linkwright-cli synthesize slider. Returns a dict: linkage, near_end, far_end, "
      "extended_crank_deg, folded_crank_deg, error, min_transmission_deg, defects.");
  module.def(
      "synthesize_shaper",
      [](double stroke, double timeRatio, double crank, double link, std::optional<double> guideHeight,
         const std::string& unit) {
        const k::ShaperTarget target{stroke, timeRatio, crank, link, guideHeight, unit};
        const k::ShaperSynthesis s = orRaise(k::synthesiseShaper(target));
        return candidateDict(s.candidate, "synthesize_shaper()");
      },
      py::arg("stroke"), py::kw_only(), py::arg("time_ratio") = 1.5, py::arg("crank"), py::arg("link"),
      py::arg("guide_height") = py::none(), py::arg("unit") = "mm",
      "A crank-shaper whose ram travels `stroke` with time ratio time_ratio, crank and link given, as "
      "linkwright-cli synthesize shaper. Returns a dict: linkage, error, min_transmission_deg, defects.");
  module.def(
      "synthesize_function",
      [](const std::string& function, double x0, double x1, double inputStartDeg, double inputSpanDeg,
         double outputStartDeg, double outputSpanDeg, double frame, std::optional<std::vector<double>> points,
         int count, const std::string& unit) {
        if (count < 0)  // before it becomes unsigned; the core checks the range
          throw CoreError(badValue("count", "must be between 3 and 1000 (got " + std::to_string(count) + ")"));
        k::FunctionSpec spec{function,
                             x0,
                             x1,
                             k::degToRad(inputStartDeg),
                             k::degToRad(inputSpanDeg),
                             k::degToRad(outputStartDeg),
                             k::degToRad(outputSpanDeg),
                             frame,
                             points.value_or(std::vector<double>{}),
                             static_cast<std::size_t>(count)};
        const k::FunctionSynthesis s = orRaise(k::synthesiseFunction(spec, unit));
        py::dict d = candidateDict(s.candidate, "synthesize_function()");
        d["points"] = s.points;
        d["frame"] = number(s.linkage.lengths.frame);
        d["crank"] = number(s.linkage.lengths.crank);
        d["coupler"] = number(s.linkage.lengths.coupler);
        d["rocker"] = number(s.linkage.lengths.rocker);
        d["max_error_deg"] = degrees(s.error.maxAbs);
        return d;
      },
      py::arg("function"), py::kw_only(), py::arg("x0"), py::arg("x1"), py::arg("input_start_deg"),
      py::arg("input_span_deg"), py::arg("output_start_deg"), py::arg("output_span_deg"), py::arg("frame") = 100.0,
      py::arg("points") = py::none(), py::arg("count") = 3, py::arg("unit") = "mm",
      "A Freudenstein function generator: the rocker's angle follows y = function(x) for x in [x0, x1] mapped "
      "to the crank's and rocker's angles (frame-relative, degrees), exact at `points` (else `count` Chebyshev "
      "points), as linkwright-cli synthesize function. Returns a dict: linkage, points, frame, crank, coupler, "
      "rocker, max_error_deg (the structural error over the range), grashof, min_transmission_deg, defects.");
}

}  // namespace linkwright::python
