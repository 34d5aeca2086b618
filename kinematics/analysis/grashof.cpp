#include "kinematics/analysis/grashof.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace linkwright::kinematics {

GrashofReport classifyGrashof(const FourBarLengths& l, double tolerance) {
  const std::array<double, 4> lengths{l.frame, l.crank, l.coupler, l.rocker};
  const auto shortest = static_cast<std::size_t>(std::min_element(lengths.begin(), lengths.end()) - lengths.begin());
  const auto longest = static_cast<std::size_t>(std::max_element(lengths.begin(), lengths.end()) - lengths.begin());
  GrashofReport r;
  r.shortest = static_cast<LinkRole>(shortest);
  r.longest = static_cast<LinkRole>(longest);
  const double total = l.frame + l.crank + l.coupler + l.rocker;
  r.sPlusL = lengths[shortest] + lengths[longest];
  r.pPlusQ = total - r.sPlusL;
  const double margin = r.pPlusQ - r.sPlusL;
  if (std::abs(margin) <= tolerance * total) {
    r.category = GrashofClass::ChangePoint;
  } else if (margin < 0.0) {
    r.category = GrashofClass::TripleRocker;
  } else {
    switch (r.shortest) {
    case LinkRole::Frame: r.category = GrashofClass::DoubleCrank; break;
    case LinkRole::Coupler: r.category = GrashofClass::DoubleRocker; break;
    case LinkRole::Crank:
    case LinkRole::Rocker: r.category = GrashofClass::CrankRocker; break;
    }
  }
  // In a Grashof linkage the shortest link turns fully relative to both its neighbours; at a
  // change point this still holds, passing through the singular position. Equal shortest
  // links (a parallelogram's crank and rocker) all turn fully.
  const bool grashof = r.category != GrashofClass::TripleRocker;
  const auto isShortest = [&](double length) { return length - lengths[shortest] <= tolerance * total; };
  const bool frameShortest = isShortest(l.frame);
  r.inputFullyRotates = grashof && (frameShortest || isShortest(l.crank));
  r.outputFullyRotates = grashof && (frameShortest || isShortest(l.rocker));
  return r;
}

std::string_view toString(GrashofClass category) {
  switch (category) {
  case GrashofClass::CrankRocker: return "crank-rocker";
  case GrashofClass::DoubleCrank: return "double-crank";
  case GrashofClass::DoubleRocker: return "double-rocker";
  case GrashofClass::ChangePoint: return "change-point";
  case GrashofClass::TripleRocker: return "triple-rocker";
  }
  return "unknown";
}

std::string_view toString(LinkRole role) {
  switch (role) {
  case LinkRole::Frame: return "frame";
  case LinkRole::Crank: return "crank";
  case LinkRole::Coupler: return "coupler";
  case LinkRole::Rocker: return "rocker";
  }
  return "unknown";
}

}  // namespace linkwright::kinematics
