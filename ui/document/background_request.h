#pragma once
// One capability's run (a core request's run function) on the document's worker pool, for the
// view that shows it: never on the GUI thread, one at a time. A newer start, or cancel() (the
// design it was made for replaced), sets the older run's cancel flag and drops its result, so a
// view only ever receives the answer to the last thing it asked. The work must own copies of
// what it reads: it may outlive the view that started it.

#include "ui/document/worker_pool.h"

#include <QFutureWatcher>
#include <QtConcurrent>

#include <atomic>
#include <functional>
#include <memory>
#include <utility>

namespace linkwright::ui {

/// `Result` is a default-constructible value (QFuture holds it).
template <typename Result>
class BackgroundRequest {
public:
  using Work = std::function<Result(const std::atomic<bool>& cancel)>;
  using Landed = std::function<void(const Result& result)>;

  /// `landed` gets each run's result on the GUI thread, unless a newer run or cancel() came first.
  explicit BackgroundRequest(Landed landed) : m_landed(std::move(landed)) {}
  ~BackgroundRequest() { cancel(); }
  BackgroundRequest(const BackgroundRequest&) = delete;
  BackgroundRequest& operator=(const BackgroundRequest&) = delete;

  void start(Work work) {
    cancel();
    auto flag = std::make_shared<std::atomic<bool>>(false);
    m_cancel = flag;
    m_watcher = std::make_unique<QFutureWatcher<Result>>();
    QFutureWatcher<Result>* watcher = m_watcher.get();
    QObject::connect(watcher, &QFutureWatcherBase::finished, watcher, [this, watcher] { deliver(watcher); });
    watcher->setFuture(QtConcurrent::run(workerPool(), [work = std::move(work), flag] { return work(*flag); }));
  }

  /// Stops the run under way, if any, and drops its result.
  void cancel() {
    if (m_cancel) m_cancel->store(true);
    m_cancel.reset();
    retire();  // the pool finishes the task; nobody hears of it
  }

  bool pending() const { return m_watcher != nullptr; }

  /// Blocks until the run under way lands, and delivers it now (tests, export).
  void wait() {
    if (m_watcher) {
      m_watcher->waitForFinished();
      deliver(m_watcher.get());
    }
  }

private:
  void deliver(QFutureWatcher<Result>* watcher) {
    if (watcher != m_watcher.get()) return;  // replaced, or already delivered by wait()
    const Result result = watcher->result();
    retire();
    m_cancel.reset();
    m_landed(result);
  }

  // Deleted once its signals are done: deliver() may run inside the watcher's own signal.
  void retire() {
    if (m_watcher) m_watcher.release()->deleteLater();
  }

  Landed m_landed;
  std::shared_ptr<std::atomic<bool>> m_cancel;
  std::unique_ptr<QFutureWatcher<Result>> m_watcher;
};

}  // namespace linkwright::ui
