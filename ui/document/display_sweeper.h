#pragma once
// The document's displayed sweep (mechanism_document.h), solved in the GUI thread or in a
// worker. With Adaptive threading (the designer's), once a sweep took longer than
// kWorkerAfterMs (a Newton linkage at Precise: 3601 samples), a drag's next sweep runs in a
// worker thread (QtConcurrent). It has the shape of the sweep shown (the same grid, request and
// structure, only other lengths), so the views keep reading the last result, whose columns
// still fit the design, until the new one lands and landed() is emitted. A newer job cancels
// an older one (the core's sweep stops within a few samples) and its result is dropped. Both
// paths run the same kinematics::sweepInto on the same inputs, so they give the same numbers.
// The document keeps a second one for its design's grid, which the analysis reads; a drag's
// grid always goes to a worker there (Threading::Worker) unless the document is GuiThread.

#include "kinematics/model/mechanism.h"
#include "kinematics/solve/sweep.h"

#include <QFuture>
#include <QFutureWatcher>
#include <QObject>

#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>

namespace linkwright::ui {

class DisplaySweeper : public QObject {
  Q_OBJECT
public:
  explicit DisplaySweeper(QObject* parent = nullptr);
  ~DisplaySweeper() override;

  /// Where a drag's sweeps run: always in the GUI thread (the default: every sweep is there
  /// when sweep() returns), in a worker once the last sweep took longer than kWorkerAfterMs
  /// (Adaptive, the designer's), or always in a worker.
  enum class Threading { GuiThread, Adaptive, Worker };
  void setThreading(Threading threading) { m_threading = threading; }
  static constexpr double kWorkerAfterMs = 4.0;

  /// The last sweep that landed (empty when it failed: the document checked its inputs).
  const kinematics::SweepResult& result() const { return m_result; }
  /// Grows each time result() changes: what is derived from a result is kept while it stays.
  std::uint64_t serial() const { return m_serial; }
  /// Wall time that sweep took, ms.
  double milliseconds() const { return m_milliseconds; }
  /// A worker is sweeping a newer job; result() is the last one.
  bool pending() const { return m_pending != nullptr; }

  /// Sweeps now, in this thread, into result()'s memory; cancels a pending job.
  void sweepNow(const kinematics::Mechanism& mechanism, const kinematics::SweepSpec& spec,
                const kinematics::SolveRequest& request);
  /// Sweeps in a worker (on copies) if the threading allows it and the sweep has result()'s
  /// shape; else now. Returns true when it went to a worker (then landed() follows).
  bool sweep(const kinematics::Mechanism& mechanism, const kinematics::SweepSpec& spec,
             const kinematics::SolveRequest& request);
  /// Whether sweep() would send this sweep to a worker.
  bool defers(const kinematics::Mechanism& mechanism, const kinematics::SweepSpec& spec,
              const kinematics::SolveRequest& request) const;
  /// Drops a pending job: its result never lands.
  void cancel() { cancelPending(); }
  /// Blocks until a pending job has landed (exports, tests); no-op if none is pending.
  void waitForResult();

signals:
  /// A worker's result became result().
  void landed();

private:
  // What a result's columns depend on: a job of the same shape leaves the views' reading of
  // the shown sweep valid.
  struct Shape {
    kinematics::SweepSpec spec;
    kinematics::SolveRequest request;
    std::vector<std::size_t> pointKinds;  // each point definition's alternative
    std::vector<kinematics::Link> links;
    bool operator==(const Shape&) const = default;
  };
  static Shape shapeOf(const kinematics::Mechanism& mechanism, const kinematics::SweepSpec& spec,
                       const kinematics::SolveRequest& request);

  struct Outcome {
    std::shared_ptr<kinematics::SweepResult> result;  // the job's memory, lent by m_spare
    bool ok = false;
    double milliseconds = 0.0;
  };
  using SharedOutcome = std::shared_ptr<Outcome>;  // shared: no copy between threads
  struct PendingJob {
    std::shared_ptr<std::atomic<bool>> cancel;
    QFuture<SharedOutcome> job;                              // runs in the pool
    std::unique_ptr<QFutureWatcher<SharedOutcome>> watcher;  // tells this thread it is done
  };

  void cancelPending();
  // Adopts the pending job's result once it has finished.
  void finishPending();

  kinematics::SweepResult m_result;
  std::uint64_t m_serial = 0;
  Shape m_shape;  // of m_result
  double m_milliseconds = 0.0;
  Threading m_threading = Threading::GuiThread;
  std::shared_ptr<kinematics::SweepResult> m_spare;  // the last result replaced: a job's memory
  std::unique_ptr<PendingJob> m_pending;
};

}  // namespace linkwright::ui
