#include "ui/document/quality_estimator.h"

#include "ui/document/worker_pool.h"

#include <QtConcurrent>

#include <utility>

namespace linkwright::ui {

QualityEstimator::QualityEstimator(QObject* parent) : QObject(parent) {
  connect(&m_watcher, &QFutureWatcherBase::finished, this, &QualityEstimator::onFinished);
}

QualityEstimator::~QualityEstimator() { m_watcher.waitForFinished(); }

void QualityEstimator::start(Input input) {
  if (m_running) {
    m_next = std::move(input);
    m_dropRunning = true;
    return;
  }
  launch(std::move(input));
}

void QualityEstimator::cancel() {
  m_next.reset();
  m_dropRunning = m_running;
}

void QualityEstimator::launch(Input input) {
  m_running = true;
  m_dropRunning = false;
  m_watcher.setFuture(QtConcurrent::run(workerPool(), [input = std::move(input)] {
    return estimatePeakError(input.mechanism, input.omega, input.samplesPerRevolution, input.newton);
  }));
}

void QualityEstimator::onFinished() {
  m_running = false;
  if (m_next) {
    launch(*std::exchange(m_next, std::nullopt));
    return;
  }
  if (std::exchange(m_dropRunning, false)) return;
  emit measured(m_watcher.result());
}

}  // namespace linkwright::ui
