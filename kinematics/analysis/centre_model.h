#pragma once
// What instant centres need to know about a linkage, found once from its structure and used at
// every pose: its bodies (rigid_bodies.h: links and plates, slider blocks), numbered as the
// texts number them, and the joints that give the primary centres.
//
//   Numbering. Body 1 is the frame. The rigid bodies follow in the order they are defined, each
//   followed by the slider blocks pinned to it. A four-bar is 2 crank, 3 coupler, 4 rocker; a
//   slider-crank 2 crank, 3 rod, 4 slider; a crank-shaper 2 crank, 3 block, 4 slotted rocker,
//   5 link, 6 ram (Norton's numbering). Plots and read-outs number links by the same rule, so
//   "ω4" on a chart is the body 4 of "I14".
//   Names. The frame is "frame", a rigid body its first link's name, a block on the frame
//   "slider <pin>", a block on a moving body "block <pin>".
//   Primary joints. Every two bodies holding one point are pinned there; every block slides
//   on the body it turns with.
//   Ratio bodies. The input is the crank's body when the linkage is driven by a crank about a
//   frame pin; the output is the highest-numbered other body jointed to the frame.
//   Centrodes. They are traced for the first rigid body not jointed to the frame (a four-bar's
//   coupler, a shaper's link), whose frame is its first link (first point → second).

#include "kinematics/analysis/instant_centres.h"
#include "kinematics/model/mechanism.h"
#include "kinematics/model/result.h"
#include "kinematics/solve/rigid_bodies.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace linkwright::kinematics {

/// A joint between bodies i < j (body numbers) that fixes their centre.
struct CentreJoint {
  std::size_t i = 0;
  std::size_t j = 0;
  CentreRule rule = CentreRule::Pin;    ///< Pin or Slide
  PointId pin;                          ///< the pin, or the sliding block's pin
  std::optional<PrismaticJoint> slide;  ///< Slide: the block's joint, whose direction the pose gives
  bool operator==(const CentreJoint&) const = default;
};

struct CentreModel {
  std::vector<std::string> bodies;               ///< names by number − 1
  std::vector<BodyId> bodyIds;                   ///< by number − 1: the body in bodiesOf's model
  std::vector<std::size_t> linkNumbers;          ///< by LinkId: the number of the body it lies on
  std::vector<std::vector<PointId>> bodyJoints;  ///< by number − 1: its points other bodies hold too
  std::vector<CentreJoint> joints;
  RatioBodies ratio;
  std::optional<PrismaticJoint> outputGuide;  ///< a sliding output's block on the frame
  std::optional<LinkId> outputLink;           ///< a turning output's first link
  std::optional<PointId> anchor;              ///< the crank's pivot, else the frame's first pin
  std::size_t centrodeBody = 0;               ///< 0: no body qualifies
  PointId centrodeFirst, centrodeSecond;      ///< its frame: origin, and the x axis towards
  bool operator==(const CentreModel&) const = default;
};

/// The model of a mechanism. Errors: those of checkMechanism, and those of bodiesOf reworded
/// for instant centres (InvalidStructure).
Result<CentreModel> centreModel(const Mechanism& mechanism);

/// The textbook number of each link of `mechanism` (by LinkId): its body's number, or, for a
/// mechanism whose bodies are not found, its index + 2 (the crank is link 2).
std::vector<std::size_t> linkNumbers(const Mechanism& mechanism);

/// The centres at a pose of the mechanism `model` was made from (kennedy.h completes them).
InstantCentres instantCentres(const Mechanism& mechanism, const CentreModel& model, const Pose& pose);

/// The same into `out`, reusing its memory: what a sweep calls at every sample.
void instantCentresInto(const Mechanism& mechanism, const CentreModel& model, const Pose& pose, InstantCentres& out);

}  // namespace linkwright::kinematics
