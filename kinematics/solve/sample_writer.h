#pragma once
// Copies solved poses, one or a block of them, into a sweep's columns (sweep.h). The columns a
// request selected are found once per sweep and kept as raw pointers, so a sample costs one
// copy per stored quantity: a four-bar's full sample is 21 values, and looking each column up through the
// result's nested vectors every time cost as much as solving the dyad.
//
// A ground pivot's columns are the same at every sample (its position where the linkage
// assembles, zero velocity and acceleration), so they are filled once, by finish().
//
// Link angles are unwrapped on the way in: each stored angle is the previous stored angle
// plus the wrapped difference, so a column is continuous through ±180°. The previous angle is
// kept by the writer, not read back from the column, so a sweep in windows (sweepInWindows)
// that reuses its columns for the next window goes on unwrapping from where it was.

#include "kinematics/model/mechanism.h"
#include "kinematics/solve/pose.h"
#include "kinematics/solve/sweep.h"

#include <Eigen/Core>

#include <span>
#include <vector>

namespace linkwright::kinematics {

class SampleWriter {
public:
  /// Binds to `out`'s columns as allocated: call after they are sized, and do not resize them
  /// while the writer is used.
  SampleWriter(const Mechanism& mechanism, SweepResult& out);

  /// Writes samples j, j+1, … from `poses`, rates as they are: a singular pose's must be
  /// cleared first (clearRates), since the solver leaves those it could not compute as they
  /// were. A block is written column by column: each column's pointer is loaded once.
  void write(std::size_t j, std::span<const Pose> poses);
  void write(std::size_t j, const Pose& pose) { write(j, {&pose, 1}); }

  /// A sample that could not be assembled: 0 in every column (its positions are not valid).
  void writeNothing(std::size_t j);

  /// Fills the ground pivots' columns, once every sample's report is in `out`: zero at the
  /// samples given to writeNothing, the pivot's place at the others.
  void finish(const Mechanism& mechanism, SweepResult& out);

private:
  struct PointSlot {
    std::size_t point;
    Eigen::Vector2d* position;
    Eigen::Vector2d* velocity;      // null: not requested
    Eigen::Vector2d* acceleration;  // null: not requested
    double* transmission;           // null: not requested, or not a dyad
  };
  struct LinkSlot {
    std::size_t link;
    double* angle;
    double* omega;  // null: not requested
    double* alpha;  // null: not requested
  };

  std::vector<PointSlot> m_points;  // moving points
  std::vector<PointSlot> m_ground;  // ground pivots
  std::vector<LinkSlot> m_links;
  std::vector<double> m_lastAngle;  // per link slot, the last angle written: later ones continue from it
  bool m_haveAngle = false;
  bool m_wroteNothing = false;  // some sample did not assemble: finish() zeroes its pivots
};

/// Zeroes every velocity and acceleration of `pose`: a singular pose's rate columns read 0.
void clearRates(Pose& pose);

}  // namespace linkwright::kinematics
