#include "ui/document/mechanism_document.h"

#include "ui/document/edit_design_command.h"

#include "kinematics/solve/pose_solver.h"


namespace linkwright::ui {

namespace k = kinematics;


MechanismDocument::MechanismDocument(QObject* parent) : QObject(parent) {
  rebuild();
  connect(&m_undo, &QUndoStack::cleanChanged, this, [this] { emit changed(Change::File); });
}

std::optional<QString> MechanismDocument::validate(const k::FourBarDesign& design) const {
  if (auto e = k::checkDesign(design)) return QString::fromStdString(e->message);
  if (k::fourBarInputRange(design.lengths).ranges.empty())
    return tr("These lengths cannot be assembled at any crank angle: the coupler and rocker cannot "
              "reach between the crank tip and the rocker pivot.");
  return std::nullopt;
}

std::optional<QString> MechanismDocument::edit(const k::FourBarDesign& design, const QString& description, int mergeKey,
                                               std::optional<double> crankAngleAfter) {
  if (auto why = validate(design)) return why;
  const double angleAfter = crankAngleAfter.value_or(m_crankAngle);
  if (design == m_design && angleAfter == m_crankAngle) return std::nullopt;
  m_undo.push(new EditDesignCommand(this, {m_design, m_crankAngle}, {design, angleAfter}, description, mergeKey));
  return std::nullopt;
}

void MechanismDocument::applyDesign(const k::FourBarDesign& design, double crankAngle) {
  m_design = design;
  m_crankAngle = crankAngle;
  rebuild();
  emit changed(Changes(Change::Design) | Change::Motion);
}

void MechanismDocument::setCrankAngle(double angle) {
  const double clamped = m_analysis.inputRange.clamp(angle);
  if (clamped == m_crankAngle) return;
  m_crankAngle = clamped;
  solvePoseNow();
  emit changed(Change::Motion);
}

void MechanismDocument::setRequest(const k::SolveRequest& request) {
  if (request == m_request) return;
  m_request = request;
  resweep();
  emit changed(Change::Request);
}

void MechanismDocument::reset(const k::FourBarDesign& design, const QString& filePath) {
  m_undo.clear();
  m_design = design;
  m_filePath = filePath;
  m_crankAngle = 0.0;
  rebuild();
  m_undo.setClean();
  emit changed(Changes(Change::Design) | Change::File);
}

void MechanismDocument::setFilePath(const QString& path) {
  m_filePath = path;
  emit changed(Change::File);
}

void MechanismDocument::markSaved() { m_undo.setClean(); }

void MechanismDocument::rebuild() {
  // Designs reach here validated (edit/validate, or the document reader), so this builds.
  m_mechanism = k::buildMechanism(m_design).value();
  m_analysis.grashof = k::classifyGrashof(m_design.lengths);
  m_analysis.mobility = k::mobility(m_mechanism);
  m_analysis.inputRange = k::fourBarInputRange(m_design.lengths);
  m_analysis.transmission = k::fourBarTransmissionRange(m_design.lengths);
  m_analysis.limits = k::fourBarLimitPositions(m_design.lengths, m_design.branch);
  m_crankAngle = m_analysis.inputRange.clamp(m_crankAngle);
  resweep();
  solvePoseNow();
}

void MechanismDocument::resweep() { m_sweep = k::sweep(m_mechanism, k::designSweepSpec(m_design), m_request).value(); }

void MechanismDocument::solvePoseNow() {
  k::preparePose(m_mechanism, m_pose);
  const k::PoseReport report = k::solvePoseInto(m_mechanism, {m_crankAngle, m_design.omega, m_design.alpha}, {true, true}, m_pose);
  m_poseStatus = report.status;
}

} // namespace linkwright::ui
