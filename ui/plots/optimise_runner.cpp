#include "ui/plots/optimise_runner.h"

#include "ui/document/worker_pool.h"

#include <QtConcurrent>

#include <utility>

namespace linkwright::ui {

namespace k = kinematics;

namespace {
constexpr int kPollMs = 100;
}

OptimiseRunner::OptimiseRunner(QObject* parent) : QObject(parent) {
  m_poll.setInterval(kPollMs);
  connect(&m_poll, &QTimer::timeout, this, &OptimiseRunner::poll);
}

OptimiseRunner::~OptimiseRunner() {
  if (m_shared) m_shared->cancel = true;
  if (m_watcher) m_watcher->waitForFinished();
}

void OptimiseRunner::start(k::Design design, k::OptimiseRequest request) {
  if (m_watcher) {
    // One run at a time: the old one stops within one measurement, and is waited for.
    m_shared->cancel = true;
    m_watcher->waitForFinished();
  }
  m_outcome.reset();
  m_shared = std::make_shared<Shared>();
  m_shared->total = request.options.evaluations;
  m_running = true;
  m_dropped = false;
  m_watcher = std::make_unique<QFutureWatcher<Outcome>>();
  connect(m_watcher.get(), &QFutureWatcherBase::finished, this, &OptimiseRunner::onFinished);
  m_watcher->setFuture(QtConcurrent::run(
      workerPool(), [shared = m_shared, design = std::move(design), request = std::move(request)]() -> Outcome {
        return k::optimiseLinkage(design, request, &shared->cancel,
                                  [&shared](int done, int) { shared->done.store(done, std::memory_order_relaxed); });
      }));
  m_poll.start();
  emit progressed(0, m_shared->total);
}

void OptimiseRunner::cancel() {
  if (m_running) m_shared->cancel = true;
}

void OptimiseRunner::drop() {
  cancel();
  m_dropped = m_running;
}

void OptimiseRunner::poll() {
  if (m_shared) emit progressed(m_shared->done.load(std::memory_order_relaxed), m_shared->total);
}

void OptimiseRunner::onFinished() {
  m_poll.stop();
  m_running = false;
  if (std::exchange(m_dropped, false)) {
    emit droppedEnded();
    return;
  }
  poll();
  m_outcome = m_watcher->result();
  emit finished();
}

}  // namespace linkwright::ui
