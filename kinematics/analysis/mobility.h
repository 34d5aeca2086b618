#pragma once
// Mobility by Gruebler's (Kutzbach's) equation, thesis seed 000 eq. (1):
//   M = 3(N − 1) − 2·jp − jh,
// N links including the ground, jp full joints (revolute or prismatic), jh half joints.

#include "kinematics/model/mechanism.h"

namespace linkwright::kinematics {

struct MobilityReport {
  int links = 0;       ///< N, including the ground
  int fullJoints = 0;  ///< jp
  int halfJoints = 0;  ///< jh
  int mobility = 0;    ///< M
  bool operator==(const MobilityReport&) const = default;
};

/// Gruebler's equation for given counts.
int grueblerMobility(int links, int fullJoints, int halfJoints);

/// Counts the mechanism's bodies and joints from its structure: the ground, the crank (one
/// body, one pivot) and each RRR, RRP or RPR dyad (two bodies, three full joints). Points fixed on a link add
/// neither. Assumes checkMechanism passed.
MobilityReport mobility(const Mechanism& mechanism);

}  // namespace linkwright::kinematics
