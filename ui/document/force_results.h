#pragma once
// The forces the views show, solved by the core from the document: the joint reactions,
// driving torque and shaking force over the displayed cycle (kinematics::sweepForces on the
// document's sweep) and at the current crank angle (InverseDynamics at the document's pose).
// Nothing is solved while disabled: forces cost a linear solve per sample, so they are
// computed only while something on screen shows them (the force plots, the canvas arrows).
//
// Forces need accelerations of every point and link. The document's sweep has them when its
// request is forcesRequest(…); until it is, the forces are solved on a sweep of our own over
// the same grid (displaySpec()), so they are right either way, at the cost of a second sweep.
// A crank move (Change::Motion) re-solves the pose forces only.

#include "ui/document/mechanism_document.h"

#include "kinematics/dynamics/force_sweep.h"
#include "kinematics/dynamics/inverse_dynamics.h"
#include "kinematics/solve/sweep.h"

#include <QObject>
#include <QString>

#include <optional>

namespace linkwright::ui {

class ForceResults : public QObject {
  Q_OBJECT
public:
  enum class State {
    Disabled,    ///< nothing needs forces: nothing is solved
    NoDynamics,  ///< the design gives no masses and no loads
    Failed,      ///< the core refused the dynamics (message() says why: an unknown length unit, …)
    Ok,          ///< cycleForces() holds the cycle (some samples may still be Singular)
  };

  /// Observes `document` (which must outlive this). Starts disabled.
  explicit ForceResults(MechanismDocument* document, QObject* parent = nullptr);
  ~ForceResults() override;

  /// Solves now and on every document change while `enabled`; clears the results when not.
  void setEnabled(bool enabled);
  bool isEnabled() const { return m_enabled; }

  /// `base` with what forces need added: velocities and accelerations of every point and link
  /// (Selection cleared). The document's request should be this while forces are enabled.
  static kinematics::SolveRequest forcesRequest(kinematics::SolveRequest base);
  /// Whether `sweep` (of `mechanism`) holds what sweepForces needs.
  static bool sweepSuffices(const kinematics::Mechanism& mechanism, const kinematics::SweepResult& sweep);

  State state() const { return m_state; }
  /// One sentence for the user: why there are no forces, or which samples have none; empty
  /// when every sample is solved.
  const QString& message() const { return m_message; }

  /// The forces over the cycle (null unless state() is Ok); sample j is cycleSweep()'s j.
  const kinematics::ForceSweep* cycleForces() const { return m_cycle ? &*m_cycle : nullptr; }
  /// The kinematic sweep cycleForces() was solved on: the document's, or our own over its grid.
  const kinematics::SweepResult* cycleSweep() const;
  /// True when cycleSweep() is a sweep of our own (the document's request lacks accelerations).
  bool usesOwnSweep() const { return m_ownSweep.has_value(); }
  /// Samples of the cycle whose forces are Singular (not determined) though the kinematics are Ok.
  std::size_t singularSamples() const { return m_singularSamples; }
  /// Largest joint reaction over the cycle, N: |F| of revolute joints, |N| of prismatic ones.
  double peakJointForce() const { return m_peakJoint; }

  /// The forces at the document's crank angle; null when not Ok or the pose is singular.
  const kinematics::PoseForces* poseForces() const { return m_poseOk ? &m_pose : nullptr; }
  /// The joints the forces belong to (null unless state() is Ok).
  const kinematics::BodyModel* bodies() const { return m_solver ? &m_solver->bodies() : nullptr; }

signals:
  /// The results changed: `cycle` true when the whole cycle was re-solved, false when only
  /// the pose forces moved (a crank move).
  void changed(bool cycle);

private:
  void onDocumentChanged(Changes what);
  void solveCycle();
  void solvePose();
  void clear(State state, const QString& message);

  MechanismDocument* m_document;
  bool m_enabled = false;
  State m_state = State::Disabled;
  QString m_message;
  std::optional<kinematics::InverseDynamics> m_solver;
  std::optional<kinematics::SweepResult> m_ownSweep;
  std::optional<kinematics::ForceSweep> m_cycle;
  std::size_t m_singularSamples = 0;
  double m_peakJoint = 0.0;
  kinematics::PoseForces m_pose;
  bool m_poseOk = false;
};

/// A force (N) or torque (N·m) with three significant digits, for labels: "0.512", "12.3", "1530".
QString formatForce(double value);

}  // namespace linkwright::ui
