#pragma once
// Turns the core's force columns (kinematics::ForceSweep) into plot points: what drives the
// linkage (a crank's torque, a linear driver's force along its input, a two-link arm's joint
// torques) and each joint's reaction magnitude against time or the input, and each pin joint's force vector
// as a polar locus. Samples whose forces were not solved (status not Ok: unassembled, a toggle,
// a singular force system) are left out and break the lines into runs, as series_data.h does
// for the kinematic curves.

#include "ui/plots/angle_unit.h"
#include "ui/plots/plot_x_axis.h"
#include "ui/plots/series_data.h"

#include "kinematics/dynamics/force_sweep.h"
#include "kinematics/solve/rigid_bodies.h"
#include "kinematics/solve/sweep.h"

#include <QColor>
#include <QString>

#include <vector>

namespace linkwright::ui {

/// One joint as the force plots name and colour it.
struct ForceJoint {
  QString name;            ///< the core's joint name: "A", "B", "C_coupler", …
  bool prismatic = false;  ///< a slider's guide (its reaction is the normal force N)
  std::size_t index = 0;   ///< into ForceSweep::revolute, or ::normal when prismatic
  QColor color;
  bool operator==(const ForceJoint&) const = default;
};

/// The joints of `bodies`: the revolute ones, then the prismatic ones.
std::vector<ForceJoint> forceJoints(const kinematics::BodyModel& bodies);

/// What the driver's chart shows: a crank's torque T (N·m); a serial arm's shoulder and elbow
/// torques (N·m), which is what its motors give; another linear driver's force along its input
/// (N: an actuator's axial force, a path drive's tangential force).
struct DriveChart {
  QString title;                ///< "Driving torque", "Joint torques", "Drive force"
  QString valueTitle;           ///< "torque [N·m]", "force [N]"
  std::vector<QString> curves;  ///< legend texts, one per curve
};
DriveChart driveChart(const kinematics::BodyModel& bodies);

/// x = time or the input (an angle in `unit`) as `x` says, y = the driver chart's curve
/// `curve` (driveChart), at the samples whose forces are Ok. `sweep` is the kinematic sweep
/// `forces` was solved on.
void buildDriveRuns(const kinematics::SweepResult& sweep, const kinematics::ForceSweep& forces, std::size_t curve,
                    AngleUnit unit, SeriesRuns& out, const XSource& x = {});

/// x as for buildDriveRuns, y = |F| of a pin joint or |N| of a slider's (N).
void buildJointForceRuns(const kinematics::SweepResult& sweep, const kinematics::ForceSweep& forces,
                         const ForceJoint& joint, AngleUnit unit, SeriesRuns& out, const XSource& x = {});

/// The shaking force on the frame (ForceSweep::shakingForce, N): its x and y components and its
/// magnitude.
enum class ShakingCurve { X, Y, Magnitude };

/// x as for buildDriveRuns, y = the shaking force's `curve` (N).
void buildShakingForceRuns(const kinematics::SweepResult& sweep, const kinematics::ForceSweep& forces,
                           ShakingCurve curve, AngleUnit unit, SeriesRuns& out, const XSource& x = {});

/// x as for buildDriveRuns, y = the shaking moment about BodyModel::momentPoint (N·m).
void buildShakingMomentRuns(const kinematics::SweepResult& sweep, const kinematics::ForceSweep& forces, AngleUnit unit,
                            SeriesRuns& out, const XSource& x = {});

/// The largest shaking force (N) and moment (N·m, by size) over the Ok samples, and where.
struct ShakingPeaks {
  double force = 0.0;
  std::size_t forceSample = 0;
  double moment = 0.0;  ///< signed, the one largest in size
  std::size_t momentSample = 0;
  bool any = false;  ///< false when no sample is Ok
};
ShakingPeaks shakingPeaks(const kinematics::ForceSweep& forces);

/// The polar diagram of the shaking force: x = Fx, y = Fy (N), one point per Ok sample.
void buildShakingPolarRuns(const kinematics::ForceSweep& forces, SeriesRuns& out);

/// The polar load diagram of revolute joint `revolute`: x = Fx, y = Fy (N, world frame; the
/// force on the joint's body from its hub), one point per Ok sample, in sweep order.
void buildPolarRuns(const kinematics::ForceSweep& forces, std::size_t revolute, SeriesRuns& out);

}  // namespace linkwright::ui
