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
//
// Threads: a cycle solve that took longer than kWorkerAfterMs the last time runs in a worker
// thread (QtConcurrent), so a drag at Precise with forces never waits for it: the views keep
// the last cycle (cyclePending() says a newer one is coming) and get changed(true) when it
// lands. A newer document change cancels the older solve (sweepForces stops at its next
// sample) and its result is dropped. While the document's own sweep is in a worker
// (sweepPending()), the cycle waits for it: it lands as a Change::Request, which solves it.
// Both paths run solveForceCycle (force_cycle.h) on a copy of the document's data, so they
// give the same numbers. The pose forces stay synchronous: one sample costs microseconds.

#include "ui/document/force_cycle.h"
#include "ui/document/mechanism_document.h"

#include "kinematics/dynamics/force_sweep.h"
#include "kinematics/dynamics/inverse_dynamics.h"
#include "kinematics/solve/sweep.h"

#include <QFuture>
#include <QFutureWatcher>
#include <QObject>
#include <QString>

#include <atomic>
#include <memory>
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

  /// Where cycle solves run: in the GUI thread unless the last one took longer than
  /// kWorkerAfterMs (Adaptive, the default), always in the GUI thread, or always in a worker.
  enum class Threading { Adaptive, GuiThread, Worker };
  void setThreading(Threading threading) { m_threading = threading; }
  static constexpr double kWorkerAfterMs = 4.0;
  /// A worker is solving a newer cycle, or the document's sweep it needs is still coming;
  /// cycleForces() and cycleSweep() are the last result.
  bool cyclePending() const { return m_pending != nullptr || (m_solver && m_document->sweepPending()); }
  /// Blocks until a pending cycle has landed (tests, export); no-op if none is pending.
  void waitForCycle();

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
  const kinematics::ForceSweep* cycleForces() const { return m_cycle ? &m_cycle->forces : nullptr; }
  /// The kinematic sweep cycleForces() was solved on: a copy of the document's, or our own
  /// over its grid (null unless state() is Ok).
  const kinematics::SweepResult* cycleSweep() const { return m_cycle ? &m_cycle->sweep : nullptr; }
  /// True when cycleSweep() is a sweep of our own (the document's request lacks accelerations).
  bool usesOwnSweep() const { return m_cycle && m_cycle->ownSweep; }
  /// Samples of the cycle whose forces are Singular (not determined) though the kinematics are Ok.
  std::size_t singularSamples() const { return m_cycle ? m_cycle->singularSamples : 0; }
  /// Largest joint reaction over the cycle, N: |F| of revolute joints, |N| of prismatic ones.
  double peakJointForce() const { return m_cycle ? m_cycle->peakJointForce : 0.0; }
  /// The shaking force's and moment's peaks over the cycle, refined between samples (null
  /// unless state() is Ok and some sample's forces are solved).
  const kinematics::ShakingPeaks* shakingPeaks() const {
    return m_cycle && m_cycle->shakingPeaks ? &*m_cycle->shakingPeaks : nullptr;
  }

  /// The forces at the document's crank angle; null when not Ok or the pose is singular.
  const kinematics::PoseForces* poseForces() const { return m_poseOk ? &m_pose : nullptr; }
  /// The joints the forces belong to (null unless state() is Ok).
  const kinematics::BodyModel* bodies() const { return m_solver ? &m_solver->bodies() : nullptr; }

signals:
  /// The results changed: `cycle` true when the whole cycle was re-solved, false when only
  /// the pose forces moved (a crank move).
  void changed(bool cycle);

private:
  // A cycle solve in a worker: the flag that cancels it, and its result to come.
  using Outcome = std::shared_ptr<kinematics::Result<ForceCycle>>;  // shared: no copy between threads
  struct PendingCycle {
    std::shared_ptr<std::atomic<bool>> cancel;
    QFuture<Outcome> job;                              // runs in the pool
    std::unique_ptr<QFutureWatcher<Outcome>> watcher;  // tells this thread it is done
  };

  void onDocumentChanged(Changes what);
  void solveCycle();
  void solvePose();
  void clear(State state, const QString& message);
  void cancelPending();
  // Adopts the pending cycle once its job has finished.
  void finishPending();
  // Takes a cycle solve's outcome as the current result (sets state and message).
  void adopt(kinematics::Result<ForceCycle> outcome);

  MechanismDocument* m_document;
  bool m_enabled = false;
  State m_state = State::Disabled;
  QString m_message;
  std::optional<kinematics::InverseDynamics> m_solver;
  std::optional<ForceCycle> m_cycle;
  Threading m_threading = Threading::Adaptive;
  double m_lastCycleMs = 0.0;  // wall time of the last cycle solve
  std::unique_ptr<PendingCycle> m_pending;
  kinematics::PoseForces m_pose;
  bool m_poseOk = false;
};

/// A force (N) or torque (N·m) with three significant digits, for labels: "0.512", "12.3", "1530".
QString formatForce(double value);

}  // namespace linkwright::ui
