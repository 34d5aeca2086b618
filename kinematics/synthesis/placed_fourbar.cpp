#include "kinematics/synthesis/placed_fourbar.h"

namespace linkwright::kinematics {

Mechanism placedFourBar(const Eigen::Vector2d& o2, const Eigen::Vector2d& o4, const FourBarLengths& l, Branch branch,
                        const CouplerPointSpec& p, const std::string& lengthUnit) {
  Mechanism m;
  m.lengthUnit = lengthUnit;
  m.points = {
      {"O2", GroundPoint{o2}},
      {"O4", GroundPoint{o4}},
      {"B", CrankPoint{fourbar::kO2, l.crank, 0.0}},
      {"C", RrrPoint{fourbar::kB, l.coupler, fourbar::kO4, l.rocker, branch}},
      {"P", AttachedPoint{fourbar::kCoupler, p.along, p.across}},
  };
  m.links = {
      {"crank", fourbar::kO2, fourbar::kB},
      {"coupler", fourbar::kB, fourbar::kC},
      {"rocker", fourbar::kO4, fourbar::kC},
  };
  return m;
}

}  // namespace linkwright::kinematics
