#pragma once
// The panel's calls into the core's synthesis (kinematics/synthesis/), one per problem, and
// the table rows made from their results. The requests are in the core's units (rad, the
// document's length unit); the forms convert at the edge. The closed-form problems run here,
// synchronously (well under a millisecond each); path generation runs in PathSearchWorker and only
// its result is turned into rows here.

#include "ui/synthesis/synthesis_outcome.h"

#include "kinematics/synthesis/function_generation.h"
#include "kinematics/synthesis/motion_generation.h"
#include "kinematics/synthesis/path_generation.h"
#include "kinematics/synthesis/stroke_shaper.h"
#include "kinematics/synthesis/stroke_slider_crank.h"
#include "kinematics/synthesis/swing_crank_rocker.h"

#include <cstddef>
#include <variant>
#include <vector>

namespace linkwright::ui {

/// A crank-rocker family for a swing and time ratio.
struct SwingRequest {
  kinematics::SwingTarget target;
  std::size_t count = 41;  ///< family members besides the best one
};

/// A function generator.
struct FunctionRequest {
  kinematics::FunctionTarget target;
  kinematics::FunctionOptions options;
};

/// Two or three coupler poses; the centres are used with two poses only.
struct MotionRequest {
  std::vector<kinematics::CouplerPose> poses;
  kinematics::CirclePoints circlePoints;
  double centreA = 0.0;  ///< length unit, along A's bisector
  double centreB = 0.0;  ///< length unit, along B's bisector
  kinematics::MotionOptions options;
};

/// A path to follow and how hard to search.
struct PathRequest {
  kinematics::PathTarget target;
  kinematics::PathOptions options;
};

using ClosedFormRequest =
    std::variant<SwingRequest, kinematics::StrokeTarget, kinematics::ShaperTarget, FunctionRequest, MotionRequest>;

/// Solves a closed-form problem; the core's Error (naming its field) if it refuses.
kinematics::Result<SynthesisOutcome> solveClosedForm(const ClosedFormRequest& request,
                                                     const kinematics::DefectBounds& bounds);

/// The rows of a path search's result, best first.
SynthesisOutcome pathOutcome(const kinematics::PathSynthesis& result, const kinematics::PathTarget& target);

}  // namespace linkwright::ui
