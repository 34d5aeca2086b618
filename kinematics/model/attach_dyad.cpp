#include "kinematics/model/attach_dyad.h"

#include "kinematics/model/mechanism_check.h"

namespace linkwright::kinematics {
namespace {

Result<Mechanism> checked(Mechanism m) {
  if (auto e = checkMechanism(m)) return *e;
  return m;
}

PointId nextPoint(const Mechanism& m) { return PointId{m.points.size()}; }

// Textbook numbering: the frame is link 1, so the k-th moving link (from 0) is link k+2.
void addLink(Mechanism& m, PointId first, PointId second) {
  m.links.push_back({"link" + std::to_string(m.links.size() + 2), first, second});
}

struct Attacher {
  Mechanism& m;

  void operator()(const RrrDyadSpec& d) const {
    const PointId joint = nextPoint(m);
    m.points.push_back({d.joint, RrrPoint{d.first, d.firstLength, d.second, d.secondLength, d.branch}});
    addLink(m, d.first, joint);
    addLink(m, d.second, joint);
  }
  void operator()(const RrpDyadSpec& d) const {
    const PointId joint = nextPoint(m);
    m.points.push_back({d.joint, RrpPoint{d.first, d.length, d.guide, d.branch}});
    addLink(m, d.first, joint);
  }
  void operator()(const RprDyadSpec& d) const {
    const PointId joint = nextPoint(m);
    m.points.push_back({d.joint, RprPoint{d.pivot, d.through, d.length}});
    addLink(m, d.pivot, joint);
  }
  void operator()(const PrpDyadSpec& d) const { m.points.push_back({d.joint, PrpPoint{d.first, d.second}}); }
};

}  // namespace

Result<Mechanism> addPointOnLink(const Mechanism& mechanism, const std::string& name, LinkId link, double along,
                                 double across) {
  Mechanism m = mechanism;
  m.points.push_back({name, AttachedPoint{link, along, across}});
  return checked(std::move(m));
}

Result<Mechanism> addGroundPivot(const Mechanism& mechanism, const std::string& name, const Eigen::Vector2d& position) {
  Mechanism m = mechanism;
  m.points.push_back({name, GroundPoint{position}});
  return checked(std::move(m));
}

Result<Mechanism> attachDyad(const Mechanism& mechanism, const DyadSpec& dyad) {
  Mechanism m = mechanism;
  std::visit(Attacher{m}, dyad);
  return checked(std::move(m));
}

}  // namespace linkwright::kinematics
