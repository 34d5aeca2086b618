#include "kinematics/analysis/mobility.h"

namespace linkwright::kinematics {

int grueblerMobility(int links, int fullJoints, int halfJoints) {
  return 3 * (links - 1) - 2 * fullJoints - halfJoints;
}

MobilityReport mobility(const Mechanism& m) {
  MobilityReport r;
  r.links = 1;  // the ground
  for (const Point& p : m.points) {
    if (std::holds_alternative<CrankPoint>(p.definition)) {
      r.links += 1;
      r.fullJoints += 1;
    } else if (std::holds_alternative<RrrPoint>(p.definition) || std::holds_alternative<RrpPoint>(p.definition) ||
               std::holds_alternative<RprPoint>(p.definition) || std::holds_alternative<PrpPoint>(p.definition)) {
      // Two links and three joints: pin, pin, pin (RRR); pin, pin, slider (RRP); pin, slider,
      // pin (RPR: the block on the pin and the slotted link); slider, pin, slider (PRP).
      r.links += 2;
      r.fullJoints += 3;
    }
  }
  r.mobility = grueblerMobility(r.links, r.fullJoints, r.halfJoints);
  return r;
}

} // namespace linkwright::kinematics
