#pragma once
// Built-in examples taken from the seed documents, shared by the CLI and (later) the GUI.

#include "kinematics/model/fourbar.h"
#include "kinematics/model/slider_crank.h"

#include <optional>
#include <string>
#include <vector>

namespace linkwright::kinematics {

/// A four-bar from a seed, with the speed and the angle grid its published table uses.
struct FourBarExample {
  std::string name;         ///< CLI name, e.g. "thesis-crank-rocker"
  std::string description;  ///< one line: what it is and where it comes from
  FourBarLengths lengths;
  std::string lengthUnit;
  Branch branch = Branch::Open;
  double omega = 0.0;     ///< crank, rad/s
  double alpha = 0.0;     ///< crank, rad/s²
  double fromDeg = 0.0;   ///< default table start, degrees
  double toDeg = 360.0;   ///< default table end, degrees
  double stepDeg = 30.0;  ///< default table step, degrees
  std::optional<CouplerPointSpec> couplerPoint;  ///< a point the seed follows on the coupler
  bool operator==(const FourBarExample&) const = default;
};

/// A slider-crank from a seed, with its speed and default angle grid.
struct SliderCrankExample {
  std::string name;
  std::string description;
  SliderCrankGeometry geometry;
  std::string lengthUnit;
  double omega = 0.0;     ///< crank, rad/s
  double fromDeg = 0.0;
  double toDeg = 360.0;
  double stepDeg = 1.0;
  bool operator==(const SliderCrankExample&) const = default;
};

/// All built-in slider-crank examples.
std::vector<SliderCrankExample> sliderCrankExamples();

/// The slider-crank example named `name`, if there is one.
std::optional<SliderCrankExample> findSliderCrankExample(const std::string& name);

/// All built-in four-bar examples, in display order.
std::vector<FourBarExample> fourBarExamples();

/// The example named `name`, if there is one.
std::optional<FourBarExample> findFourBarExample(const std::string& name);

} // namespace linkwright::kinematics
