#pragma once
// Path generation off the GUI thread: the core's synthesisePath runs on Qt's thread pool on a
// copy of the request; its progress callback is marshalled to the GUI thread by a queued
// invocation, and the result comes back as a value. Cancel sets the core's std::atomic<bool>,
// which it reads between starts, so the search returns what it has soon after. A newer
// search cancels the one before it, whose progress and result are then ignored. Nothing is
// shared but the cancel flag; the GUI thread never waits, except in the destructor, which
// cancels first.

#include "ui/synthesis/synthesis_solve.h"

#include <QFutureWatcher>
#include <QObject>

#include <atomic>
#include <memory>
#include <optional>

namespace linkwright::ui {

/// What one search gave: its result or the core's refusal.
struct PathSearchResult {
  PathRequest request;
  std::optional<kinematics::PathSynthesis> synthesis;
  std::optional<kinematics::Error> error;
};

class PathSearchWorker : public QObject {
  Q_OBJECT
public:
  explicit PathSearchWorker(QObject* parent = nullptr);
  ~PathSearchWorker() override;

  /// Starts a search for `request` with `bounds`, cancelling any running one.
  void start(const PathRequest& request, const kinematics::DefectBounds& bounds);
  /// Asks the running search to stop; it then finishes with what it found, marked cancelled.
  void cancel();
  bool isRunning() const { return m_running; }

signals:
  /// After each start of the running search (GUI thread).
  void progress(int done, int total);
  /// The running search ended (GUI thread): done, cancelled or refused.
  void finished(const linkwright::ui::PathSearchResult& result);

private:
  void onProgress(int serial, int done, int total);
  void onFinished(int serial, QFutureWatcher<PathSearchResult>* watcher);

  std::shared_ptr<std::atomic<bool>> m_cancel;
  QFutureWatcher<PathSearchResult>* m_watcher = nullptr;
  int m_serial = 0;
  bool m_running = false;
};

}  // namespace linkwright::ui
