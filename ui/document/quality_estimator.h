#pragma once
// Measures a design's QualityEstimate (quality_estimate.h) in a worker thread. The measurement
// finds the exact peaks of every rate over a turn and reads them off N samples: at Precise on
// a six-bar that is a tenth of a second or more, far past a frame, so the GUI thread only
// starts it and takes the result (issue 20: the GUI thread never blocks for longer than a
// frame). A newer start supersedes an older measurement, whose result is dropped; the core
// cannot stop one midway, so the newer one starts when it ends (at most one runs at a time).

#include "ui/document/quality_estimate.h"

#include "kinematics/model/mechanism.h"
#include "kinematics/solve/pose.h"

#include <QFutureWatcher>
#include <QObject>

#include <cstddef>
#include <optional>

namespace linkwright::ui {

class QualityEstimator : public QObject {
  Q_OBJECT
public:
  /// What estimatePeakError takes: copies, so the worker shares nothing with the document.
  struct Input {
    kinematics::Mechanism mechanism;
    double omega = 0.0;                    ///< rad/s
    std::size_t samplesPerRevolution = 0;  ///< N ≥ 3
    kinematics::NewtonSettings newton;
  };

  explicit QualityEstimator(QObject* parent = nullptr);
  /// Waits for a running measurement: no thread outlives its owner.
  ~QualityEstimator() override;

  /// Measures `input` in the thread pool and emits measured() with the result, unless a newer
  /// start() or cancel() comes first.
  void start(Input input);
  /// Drops the running and the waiting measurement: neither result is emitted.
  void cancel();
  /// A measurement is running or waiting to start.
  bool busy() const { return m_running || m_next.has_value(); }

signals:
  void measured(const linkwright::ui::QualityEstimate& estimate);

private:
  void launch(Input input);
  void onFinished();

  QFutureWatcher<QualityEstimate> m_watcher;
  // Set from launch until its finished() is handled (the watcher's own state turns false
  // before that signal arrives).
  bool m_running = false;
  std::optional<Input> m_next;  // waits for the running measurement to end
  bool m_dropRunning = false;   // the running measurement's result is stale
};

}  // namespace linkwright::ui
