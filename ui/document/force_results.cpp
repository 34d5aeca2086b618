#include "ui/document/force_results.h"

#include "ui/document/worker_pool.h"

#include "kinematics/model/number_text.h"

#include <QCoreApplication>
#include <QtConcurrent>

#include <algorithm>
#include <cmath>

namespace linkwright::ui {

namespace k = kinematics;

namespace {

// Every column of `columns` holds all `samples` samples.
template <typename Columns>
bool full(const Columns& columns, std::size_t count, std::size_t samples) {
  if (columns.size() != count) return false;
  return std::all_of(columns.begin(), columns.end(), [&](const auto& c) { return c.size() == samples; });
}

}  // namespace

ForceResults::ForceResults(MechanismDocument* document, QObject* parent) : QObject(parent), m_document(document) {
  connect(document, &MechanismDocument::changed, this, &ForceResults::onDocumentChanged);
}

// A job still running holds only its own copies; it is told to stop and waited for, so no
// thread outlives the object that started it.
ForceResults::~ForceResults() {
  if (!m_pending) return;
  m_pending->cancel->store(true);
  m_pending->job.waitForFinished();
}

void ForceResults::setEnabled(bool enabled) {
  if (enabled == m_enabled) return;
  m_enabled = enabled;
  if (enabled) solveCycle();
  else clear(State::Disabled, {});
  emit changed(true);
}

k::SolveRequest ForceResults::forcesRequest(k::SolveRequest base) {
  base.velocities = true;
  base.accelerations = true;
  base.only = {};
  return base;
}

bool ForceResults::sweepSuffices(const k::Mechanism& m, const k::SweepResult& s) {
  const std::size_t n = s.size();
  return s.request.accelerations && full(s.position, m.points.size(), n) && full(s.velocity, m.points.size(), n) &&
         full(s.acceleration, m.points.size(), n) && full(s.linkAngle, m.links.size(), n) &&
         full(s.linkOmega, m.links.size(), n) && full(s.linkAlpha, m.links.size(), n);
}

void ForceResults::onDocumentChanged(Changes what) {
  if (!m_enabled) return;
  if (what & (Changes(Change::Design) | Change::Request)) {
    solveCycle();
    // While a worker solves the cycle, only the pose forces are new.
    emit changed(!cyclePending());
  } else if (what & Change::Motion) {
    solvePose();
    emit changed(false);
  }
}

void ForceResults::clear(State state, const QString& message) {
  cancelPending();
  m_state = state;
  m_message = message;
  m_solver.reset();
  m_cycle.reset();
  m_poseOk = false;
}

void ForceResults::cancelPending() {
  if (!m_pending) return;
  m_pending->cancel->store(true);  // its continuation sees this and drops the result
  m_pending.reset();
}

void ForceResults::waitForCycle() {
  m_document->waitForSweep();  // the cycle is solved on it when it lands
  if (!m_pending) return;
  m_pending->job.waitForFinished();
  finishPending();
}

void ForceResults::finishPending() {
  if (!m_pending || !m_pending->job.isFinished()) return;
  const Outcome outcome = m_pending->job.result();
  m_pending.reset();
  adopt(std::move(*outcome));
  emit changed(true);
}

void ForceResults::solveCycle() {
  cancelPending();
  const k::LinkageDynamics& dynamics = m_document->design().dynamics;
  if (dynamics.empty()) {
    clear(State::NoDynamics,
          tr("This design has no masses or loads: give its links masses in the Links table above, or add a load."));
    return;
  }
  const k::Mechanism& mechanism = m_document->mechanism();
  auto solver = k::InverseDynamics::create(mechanism, dynamics);
  if (!solver) {
    clear(State::Failed, tr("No forces: %1").arg(QString::fromStdString(solver.error().message)));
    return;
  }
  // The pose forces follow the document at once; the cycle may come later.
  m_solver.emplace(std::move(solver).value());
  m_solver->prepare(m_pose);
  solvePose();
  // A drag's sweep in a worker is the design's of a moment ago: the cycle waits for it to land.
  if (m_document->sweepPending()) return;
  ForceCycleInput input{mechanism, dynamics, std::nullopt, m_document->displaySpec(),
                        forcesRequest(m_document->request())};
  if (sweepSuffices(mechanism, m_document->sweep())) input.sweep = m_document->sweep();
  const bool inWorker =
      m_threading == Threading::Worker || (m_threading == Threading::Adaptive && m_lastCycleMs > kWorkerAfterMs);
  if (!inWorker) {
    adopt(solveForceCycle(std::move(input)));
    return;
  }
  auto cancel = std::make_shared<std::atomic<bool>>(false);
  auto job = QtConcurrent::run(workerPool(), [input = std::move(input), cancel]() mutable {
    return std::make_shared<k::Result<ForceCycle>>(solveForceCycle(std::move(input), cancel.get()));
  });
  // The watcher goes with its job: a cancelled one is deleted, and its signal with it.
  auto watcher = std::make_unique<QFutureWatcher<Outcome>>();
  connect(watcher.get(), &QFutureWatcherBase::finished, this, &ForceResults::finishPending);
  watcher->setFuture(job);
  m_pending = std::make_unique<PendingCycle>(PendingCycle{std::move(cancel), std::move(job), std::move(watcher)});
}

void ForceResults::adopt(k::Result<ForceCycle> outcome) {
  if (!outcome) {
    clear(State::Failed, tr("No forces: %1").arg(QString::fromStdString(outcome.error().message)));
    return;
  }
  m_state = State::Ok;
  m_cycle.emplace(std::move(outcome).value());
  m_lastCycleMs = m_cycle->milliseconds;
  m_message.clear();
  if (m_cycle->singularSamples > 0)
    m_message =
        tr("Forces are not determined at %n sample(s) of the cycle (a toggle position or a redundant "
           "structure); the curves break there.",
           nullptr, static_cast<int>(m_cycle->singularSamples));
}

void ForceResults::solvePose() {
  m_poseOk = false;
  if (!m_solver || m_document->poseStatus() != k::PoseStatus::Ok) return;
  m_poseOk = m_solver->solveInto(m_document->pose(), m_pose) == k::PoseStatus::Ok;
}

QString formatForce(double value) {
  if (!std::isfinite(value)) return QStringLiteral("–");
  const double size = std::abs(value);
  if (size == 0.0) return QStringLiteral("0");
  const int digits = static_cast<int>(std::floor(std::log10(size)));
  return QString::fromStdString(kinematics::formatFixed(value, std::clamp(2 - digits, 0, 6)));
}

}  // namespace linkwright::ui
