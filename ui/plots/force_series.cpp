#include "ui/plots/force_series.h"

#include "ui/colors.h"

#include <QObject>

#include <algorithm>
#include <array>
#include <cmath>

namespace linkwright::ui {

namespace k = kinematics;

namespace {

// Fills `out` with (x(j), y(j)) for the runs of samples where `ok(j)` and y(j) is finite (the
// last guard: a value that is still not finite is left out, never drawn); reuses its lists.
template <typename Ok, typename X, typename Y>
void buildRuns(std::size_t samples, Ok okSample, X x, Y y, SeriesRuns& out) {
  const auto ok = [&](std::size_t j) { return okSample(j) && std::isfinite(y(j)); };
  qsizetype runCount = 0;
  bool first = true;
  out.minY = 0.0;
  out.maxY = 0.0;
  std::size_t j = 0;
  while (j < samples) {
    if (!ok(j)) {
      ++j;
      continue;
    }
    std::size_t end = j;
    while (end < samples && ok(end)) ++end;
    if (runCount == out.runs.size()) out.runs.emplace_back();
    QList<QPointF>& run = out.runs[runCount++];
    run.clear();
    run.reserve(static_cast<qsizetype>(end - j));
    for (; j < end; ++j) {
      const double value = y(j);
      run.append(QPointF(x(j), value));
      out.minY = first ? value : std::min(out.minY, value);
      out.maxY = first ? value : std::max(out.maxY, value);
      first = false;
    }
  }
  out.runs.resize(runCount);
}

// The force columns belong to this sweep (same sample count), else nothing is plotted.
std::size_t samplesOf(const k::SweepResult& sweep, const k::ForceSweep& forces) {
  return sweep.size() == forces.size() ? forces.size() : 0;
}

}  // namespace

std::vector<ForceJoint> forceJoints(const k::BodyModel& bodies) {
  std::vector<ForceJoint> joints;
  for (std::size_t i = 0; i < bodies.revolutes.size(); ++i)
    joints.push_back({QString::fromStdString(bodies.revolutes[i].name), false, i, QColor()});
  for (std::size_t i = 0; i < bodies.prismatics.size(); ++i)
    joints.push_back({QString::fromStdString(bodies.prismatics[i].name), true, i, QColor()});
  for (std::size_t i = 0; i < joints.size(); ++i) joints[i].color = jointForceColor(i);
  return joints;
}

DriveChart driveChart(const k::BodyModel& bodies) {
  if (bodies.arm)
    return {QObject::tr("Joint torques"),
            QObject::tr("torque [N·m]"),
            {QObject::tr("τ %1").arg(QString::fromStdString(bodies.arm->pivotName)),
             QObject::tr("τ %1").arg(QString::fromStdString(bodies.arm->elbowName))}};
  if (bodies.drive.kind == k::DriveKind::Crank)
    return {QObject::tr("Driving torque"), QObject::tr("torque [N·m]"), {QObject::tr("T₂")}};
  const QString name =
      bodies.drive.kind == k::DriveKind::Actuator ? QObject::tr("actuator") : QString::fromStdString(bodies.drive.name);
  return {QObject::tr("Drive force"), QObject::tr("force [N]"), {QObject::tr("%1 along its input").arg(name)}};
}

void buildDriveRuns(const k::SweepResult& sweep, const k::ForceSweep& forces, std::size_t curve, AngleUnit unit,
                    SeriesRuns& out, const XSource& x) {
  const k::BodyModel& bodies = forces.bodies;
  const auto value = [&](std::size_t j) {
    if (bodies.arm) return curve == 0 ? forces.jointTorque[j].x() : forces.jointTorque[j].y();
    return bodies.drive.kind == k::DriveKind::Crank ? forces.driveTorque[j] : forces.driveAlong[j];
  };
  buildRuns(
      samplesOf(sweep, forces), [&](std::size_t j) { return forces.ok(j); },
      [&](std::size_t j) { return sampleX(sweep, j, x, unit); }, value, out);
}

void buildJointForceRuns(const k::SweepResult& sweep, const k::ForceSweep& forces, const ForceJoint& joint,
                         AngleUnit unit, SeriesRuns& out, const XSource& xSource) {
  const auto x = [&](std::size_t j) { return sampleX(sweep, j, xSource, unit); };
  const auto ok = [&](std::size_t j) { return forces.ok(j); };
  const bool present = joint.prismatic ? joint.index < forces.normal.size() : joint.index < forces.revolute.size();
  const std::size_t samples = present ? samplesOf(sweep, forces) : 0;
  if (joint.prismatic)
    buildRuns(
        samples, ok, x, [&](std::size_t j) { return std::abs(forces.normal[joint.index][j]); }, out);
  else
    buildRuns(
        samples, ok, x, [&](std::size_t j) { return forces.revolute[joint.index][j].norm(); }, out);
}

void buildPolarRuns(const k::ForceSweep& forces, std::size_t revolute, SeriesRuns& out) {
  const std::size_t samples = revolute < forces.revolute.size() ? forces.size() : 0;
  buildRuns(
      samples, [&](std::size_t j) { return forces.ok(j); },
      [&](std::size_t j) { return forces.revolute[revolute][j].x(); },
      [&](std::size_t j) { return forces.revolute[revolute][j].y(); }, out);
}

void buildShakingForceRuns(const k::SweepResult& sweep, const k::ForceSweep& forces, ShakingCurve curve, AngleUnit unit,
                           SeriesRuns& out, const XSource& x) {
  const auto value = [&](std::size_t j) {
    const Eigen::Vector2d& f = forces.shakingForce[j];
    return curve == ShakingCurve::X ? f.x() : curve == ShakingCurve::Y ? f.y() : f.norm();
  };
  buildRuns(
      samplesOf(sweep, forces), [&](std::size_t j) { return forces.ok(j); },
      [&](std::size_t j) { return sampleX(sweep, j, x, unit); }, value, out);
}

void buildShakingMomentRuns(const k::SweepResult& sweep, const k::ForceSweep& forces, AngleUnit unit, SeriesRuns& out,
                            const XSource& x) {
  buildRuns(
      samplesOf(sweep, forces), [&](std::size_t j) { return forces.ok(j); },
      [&](std::size_t j) { return sampleX(sweep, j, x, unit); }, [&](std::size_t j) { return forces.shakingMoment[j]; },
      out);
}

ShakingPeaks shakingPeaks(const k::ForceSweep& forces) {
  ShakingPeaks p;
  for (std::size_t j = 0; j < forces.size(); ++j) {
    if (!forces.ok(j)) continue;
    const double f = forces.shakingForce[j].norm();
    if (!p.any || f > p.force) {
      p.force = f;
      p.forceSample = j;
    }
    if (!p.any || std::abs(forces.shakingMoment[j]) > std::abs(p.moment)) {
      p.moment = forces.shakingMoment[j];
      p.momentSample = j;
    }
    p.any = true;
  }
  return p;
}

void buildShakingPolarRuns(const k::ForceSweep& forces, SeriesRuns& out) {
  buildRuns(
      forces.size(), [&](std::size_t j) { return forces.ok(j); },
      [&](std::size_t j) { return forces.shakingForce[j].x(); },
      [&](std::size_t j) { return forces.shakingForce[j].y(); }, out);
}

}  // namespace linkwright::ui
