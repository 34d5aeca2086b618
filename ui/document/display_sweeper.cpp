#include "ui/document/display_sweeper.h"

#include "ui/document/worker_pool.h"

#include <QtConcurrent>

#include <chrono>
#include <utility>

namespace linkwright::ui {

namespace k = kinematics;

DisplaySweeper::DisplaySweeper(QObject* parent) : QObject(parent) {}

// A job still running holds only its own copies; it is told to stop and waited for, so no
// thread outlives the object that started it.
DisplaySweeper::~DisplaySweeper() {
  if (!m_pending) return;
  m_pending->cancel->store(true);
  m_pending->job.waitForFinished();
}

DisplaySweeper::Shape DisplaySweeper::shapeOf(const k::Mechanism& mechanism, const k::SweepSpec& spec,
                                              const k::SolveRequest& request) {
  Shape shape{spec, request, {}, mechanism.links};
  shape.pointKinds.reserve(mechanism.points.size());
  for (const k::Point& p : mechanism.points) shape.pointKinds.push_back(p.definition.index());
  return shape;
}

void DisplaySweeper::sweepNow(const k::Mechanism& mechanism, const k::SweepSpec& spec, const k::SolveRequest& request) {
  cancelPending();
  const auto start = std::chrono::steady_clock::now();
  // Into the same result: a drag re-sweeps on every frame without new allocations.
  if (auto error = k::sweepInto(mechanism, spec, request, m_result)) m_result = k::SweepResult{};
  ++m_serial;
  m_milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  m_shape = shapeOf(mechanism, spec, request);
}

bool DisplaySweeper::defers(const k::Mechanism& mechanism, const k::SweepSpec& spec,
                            const k::SolveRequest& request) const {
  const bool slow =
      m_threading == Threading::Worker || (m_threading == Threading::Adaptive && m_milliseconds > kWorkerAfterMs);
  return slow && shapeOf(mechanism, spec, request) == m_shape;
}

bool DisplaySweeper::sweep(const k::Mechanism& mechanism, const k::SweepSpec& spec, const k::SolveRequest& request) {
  if (!defers(mechanism, spec, request)) {
    sweepNow(mechanism, spec, request);
    return false;
  }
  cancelPending();
  // The result this one replaced lends its memory; a cancelled job keeps its own.
  std::shared_ptr<k::SweepResult> target = m_spare ? std::move(m_spare) : std::make_shared<k::SweepResult>();
  auto cancel = std::make_shared<std::atomic<bool>>(false);
  auto future = QtConcurrent::run(workerPool(), [mechanism, spec, request, target, cancel] {
    const auto start = std::chrono::steady_clock::now();
    auto outcome = std::make_shared<Outcome>();
    outcome->ok = !k::sweepInto(mechanism, spec, request, *target, cancel.get());
    outcome->result = target;
    outcome->milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return outcome;
  });
  // The watcher goes with its job: a cancelled one is deleted, and its signal with it.
  auto watcher = std::make_unique<QFutureWatcher<SharedOutcome>>();
  connect(watcher.get(), &QFutureWatcherBase::finished, this, &DisplaySweeper::finishPending);
  watcher->setFuture(future);
  m_pending = std::make_unique<PendingJob>(PendingJob{std::move(cancel), std::move(future), std::move(watcher)});
  return true;
}

void DisplaySweeper::cancelPending() {
  if (!m_pending) return;
  m_pending->cancel->store(true);  // the sweep stops early; its result is never read
  m_pending.reset();
}

void DisplaySweeper::waitForResult() {
  if (!m_pending) return;
  m_pending->job.waitForFinished();
  finishPending();
}

void DisplaySweeper::finishPending() {
  if (!m_pending || !m_pending->job.isFinished()) return;
  const SharedOutcome outcome = m_pending->job.result();
  m_pending.reset();  // its shape was m_shape's: it went to the worker for that
  // Only a job that was not cancelled gets here, so a failure is the core's refusal.
  if (outcome->ok) {
    std::swap(m_result, *outcome->result);
    m_spare = outcome->result;  // now holding the replaced result's columns
  } else {
    m_result = k::SweepResult{};
  }
  ++m_serial;
  m_milliseconds = outcome->milliseconds;
  emit landed();
}

}  // namespace linkwright::ui
