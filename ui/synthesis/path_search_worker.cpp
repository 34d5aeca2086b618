#include "ui/synthesis/path_search_worker.h"

#include "ui/document/worker_pool.h"

#include <QPointer>
#include <QtConcurrent/QtConcurrentRun>

namespace linkwright::ui {

namespace k = kinematics;

PathSearchWorker::PathSearchWorker(QObject* parent) : QObject(parent) {}

PathSearchWorker::~PathSearchWorker() {
  // Each search reads its flag between starts, so it ends within one start; its queued
  // progress calls die with this object.
  // Superseded searches were cancelled when the next one started; wait for them all, so that
  // none posts to this object once it is gone.
  if (m_cancel) m_cancel->store(true);
  // QFutureWatcher<T> has no Q_OBJECT of its own (Qt 6.8 refuses it in findChildren); every
  // child watcher here is one of ours, found through the base that has one.
  for (auto* watcher : findChildren<QFutureWatcherBase*>()) watcher->waitForFinished();
}

void PathSearchWorker::start(const PathRequest& request, const k::DefectBounds& bounds) {
  cancel();
  const int serial = ++m_serial;
  auto flag = std::make_shared<std::atomic<bool>>(false);
  m_cancel = flag;
  m_running = true;
  auto* watcher = new QFutureWatcher<PathSearchResult>(this);
  connect(watcher, &QFutureWatcherBase::finished, this, [this, serial, watcher] { onFinished(serial, watcher); });
  m_watcher = watcher;
  QPointer<PathSearchWorker> self(this);
  watcher->setFuture(QtConcurrent::run(workerPool(), [request, bounds, flag, serial, self]() {
    // Called on the worker thread; the destructor waits for this thread, so `self` outlives it.
    const k::PathProgress report = [&self, serial](int done, int total) {
      QMetaObject::invokeMethod(
          self.data(),
          [self, serial, done, total] {
            if (self) self->onProgress(serial, done, total);
          },
          Qt::QueuedConnection);
    };
    PathSearchResult out{request, std::nullopt, std::nullopt};
    auto result = k::synthesisePath(request.target, request.options, bounds, flag.get(), report);
    if (result) out.synthesis = std::move(result).value();
    else out.error = result.error();
    return out;
  }));
}

void PathSearchWorker::cancel() {
  if (m_cancel) m_cancel->store(true);
}

void PathSearchWorker::onProgress(int serial, int done, int total) {
  if (serial == m_serial && m_running) emit progress(done, total);
}

void PathSearchWorker::onFinished(int serial, QFutureWatcher<PathSearchResult>* watcher) {
  watcher->deleteLater();
  if (watcher == m_watcher) m_watcher = nullptr;
  if (serial != m_serial) return;  // superseded by a newer search
  m_running = false;
  emit finished(watcher->result());
}

}  // namespace linkwright::ui
