#include "ui/document/force_results.h"

#include "ui/number_text.h"

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

double peakOf(const k::ForceSweep& f) {
  double peak = 0.0;
  for (std::size_t j = 0; j < f.size(); ++j) {
    if (!f.ok(j)) continue;
    for (const auto& column : f.revolute) peak = std::max(peak, column[j].norm());
    for (const auto& column : f.normal) peak = std::max(peak, std::abs(column[j]));
  }
  return peak;
}

}  // namespace

ForceResults::ForceResults(MechanismDocument* document, QObject* parent) : QObject(parent), m_document(document) {
  connect(document, &MechanismDocument::changed, this, &ForceResults::onDocumentChanged);
}

ForceResults::~ForceResults() = default;

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

const k::SweepResult* ForceResults::cycleSweep() const {
  if (!m_cycle) return nullptr;
  return m_ownSweep ? &*m_ownSweep : &m_document->sweep();
}

void ForceResults::onDocumentChanged(Changes what) {
  if (!m_enabled) return;
  if (what & (Changes(Change::Design) | Change::Request)) {
    solveCycle();
    emit changed(true);
  } else if (what & Change::Motion) {
    solvePose();
    emit changed(false);
  }
}

void ForceResults::clear(State state, const QString& message) {
  m_state = state;
  m_message = message;
  m_solver.reset();
  m_ownSweep.reset();
  m_cycle.reset();
  m_singularSamples = 0;
  m_peakJoint = 0.0;
  m_poseOk = false;
}

void ForceResults::solveCycle() {
  const k::LinkageDynamics& dynamics = m_document->design().dynamics;
  if (dynamics.empty()) {
    clear(State::NoDynamics, tr("This design has no masses or loads: set them in Properties."));
    return;
  }
  const k::Mechanism& mechanism = m_document->mechanism();
  auto solver = k::InverseDynamics::create(mechanism, dynamics);
  if (!solver) {
    clear(State::Failed, tr("No forces: %1").arg(QString::fromStdString(solver.error().message)));
    return;
  }
  clear(State::Ok, {});
  m_solver.emplace(std::move(solver).value());
  m_solver->prepare(m_pose);
  if (!sweepSuffices(mechanism, m_document->sweep()))
    m_ownSweep = k::sweep(mechanism, m_document->displaySpec(), forcesRequest(m_document->request())).value();
  const k::SweepResult& kinematic = m_ownSweep ? *m_ownSweep : m_document->sweep();
  auto cycle = k::sweepForces(mechanism, dynamics, kinematic);
  if (!cycle) {
    clear(State::Failed, tr("No forces: %1").arg(QString::fromStdString(cycle.error().message)));
    return;
  }
  m_cycle.emplace(std::move(cycle).value());
  for (std::size_t j = 0; j < m_cycle->size(); ++j)
    if (kinematic.ok(j) && !m_cycle->ok(j)) ++m_singularSamples;
  m_peakJoint = peakOf(*m_cycle);
  if (m_singularSamples > 0)
    m_message =
        tr("Forces are not determined at %n sample(s) of the cycle (a toggle position or a redundant "
           "structure); the curves break there.",
           nullptr, static_cast<int>(m_singularSamples));
  solvePose();
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
  return numberText(value, 'f', std::clamp(2 - digits, 0, 6));
}

}  // namespace linkwright::ui
