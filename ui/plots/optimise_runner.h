#pragma once
// Runs an optimisation of a linkage (kinematics/tune/optimise_linkage.h) on a worker
// thread for Edit ▸ Optimise…: the design and request are copied to the worker, the result
// comes back as a value, and the worker's progress is read from an atomic counter by a timer
// on this thread, so nothing is shared but that counter and the cancel flag. Cancel asks the
// run to stop and still delivers the best found; drop stops it and delivers nothing (the
// design it was for has changed).

#include "kinematics/tune/optimise_linkage.h"

#include <QFutureWatcher>
#include <QObject>
#include <QTimer>

#include <atomic>
#include <memory>
#include <optional>

namespace linkwright::ui {

class OptimiseRunner : public QObject {
  Q_OBJECT
public:
  using Outcome = kinematics::Result<kinematics::LinkageOptimisation>;

  explicit OptimiseRunner(QObject* parent = nullptr);
  /// Stops a run and waits for its thread to end.
  ~OptimiseRunner() override;

  /// Starts optimising `design`; a run already going is dropped first.
  void start(kinematics::Design design, kinematics::OptimiseRequest request);
  /// Asks the run to stop; finished() still comes, with the best found before.
  void cancel();
  /// Stops the run; finished() does not come for it, droppedEnded() does.
  void drop();
  bool running() const { return m_running; }
  /// The last run's outcome (valid after finished()).
  const std::optional<Outcome>& outcome() const { return m_outcome; }

signals:
  /// Designs measured so far, of the budget.
  void progressed(int done, int total);
  void finished();
  /// A dropped run has ended: a new one may start without waiting.
  void droppedEnded();

private:
  struct Shared {
    std::atomic<bool> cancel{false};
    std::atomic<int> done{0};
    int total = 0;
  };
  void poll();
  void onFinished();

  // One watcher a run: a replaced run's watcher goes with its undelivered signals.
  std::unique_ptr<QFutureWatcher<Outcome>> m_watcher;
  QTimer m_poll;
  std::shared_ptr<Shared> m_shared;
  std::optional<Outcome> m_outcome;
  bool m_running = false;
  bool m_dropped = false;
};

}  // namespace linkwright::ui
