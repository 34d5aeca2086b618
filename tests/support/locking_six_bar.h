#pragma once
// A Stephenson III six-bar whose dyad E passes its assembly limit for a fraction of a degree
// near a crank angle of 291.65°: in 5° steps every sample assembles, yet the linkage cannot
// turn from 290° to 295° (SweepResult::lockedBetween). Its four-bar is at a change point
// (6.757 + 14.196 = 11.774 + 9.179), so it also toggles at 180°. Found by the random-linkage
// soak (seed 7, linkage 612083), lengths rounded.

#include "kinematics/model/sixbar.h"

namespace linkwright::test {

inline kinematics::SixBarGeometry lockingSixBar() {
  kinematics::SixBarGeometry g;
  g.kind = kinematics::SixBarKind::StephensonIII;
  g.fourBar = {6.757, 14.196, 11.774, 9.179};
  g.first = {11.256, -4.718};
  g.groundPivot = {16.351, -8.521};
  g.link5 = 21.554;
  g.link6 = 20.573;
  return g;
}

}  // namespace linkwright::test
