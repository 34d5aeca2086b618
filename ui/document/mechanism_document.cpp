#include "ui/document/mechanism_document.h"

#include "kinematics/solve/law_inverse.h"
#include "ui/document/edit_design_command.h"

#include "kinematics/model/driver.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace linkwright::ui {

namespace k = kinematics;

// Until a view resets it, the document holds a plain four-bar, the thesis's.
MechanismDocument::MechanismDocument(QObject* parent)
    : QObject(parent), m_design(k::fourBarDesign(k::kThesisCrankRocker).value()) {
  m_request.newton.tolerance = qualityPreset(m_quality).newtonTolerance;
  m_estimateTimer.setSingleShot(true);
  m_estimateTimer.setInterval(kEstimateSettleMs);
  connect(&m_estimateTimer, &QTimer::timeout, this, &MechanismDocument::measureQuality);
  connect(&m_estimator, &QualityEstimator::measured, this, &MechanismDocument::adoptEstimate);
  connect(&m_sweeper, &DisplaySweeper::landed, this, [this] { emit changed(Change::Request); });
  connect(&m_grid.sweeper, &DisplaySweeper::landed, this, &MechanismDocument::adoptGridAnalysis);
  rebuild(SweepNow::Yes);
  connect(&m_undo, &QUndoStack::cleanChanged, this, [this] { emit changed(Change::File); });
}

std::optional<QString> MechanismDocument::validate(const k::Design& design) const {
  m_grid.accepted.reset();
  // A field out of its range is refused before anything is swept.
  if (auto e = k::checkDesign(design)) return QString::fromStdString(e->message);
  const bool needsGrid = k::needsGridSweep(design.mechanism);
  // A drag's design (the grid and structure of the one shown, only other lengths) that
  // assembles at the instant shown is accepted at once where a worker sweeps the grid: it is
  // derived when that sweep lands (gridDeferred).
  if (needsGrid && gridDeferred(design) && assemblesAtInstant(design)) return std::nullopt;
  static const k::SweepResult kNoGrid;
  // Checked above: derived from the mechanism, so the design is not checked twice.
  auto derived = k::deriveDesign(design.mechanism, needsGrid ? sweepGrid(design) : kNoGrid);
  if (!derived) return QString::fromStdString(derived.error().message);
  m_grid.accepted = DesignGrid::Accepted{design, m_request.newton, std::move(derived).value()};
  return std::nullopt;
}

const std::optional<k::AdvantageSeries>& MechanismDocument::ratios() const {
  // Serial 0 is no sweep yet: the caches start stale.
  if (m_ratiosSerial != m_sweeper.serial() || m_ratiosSerial == 0) {
    auto series = k::advantageSeries(m_design.mechanism, m_sweeper.result());
    m_ratios = series ? std::optional<k::AdvantageSeries>(std::move(series).value()) : std::nullopt;
    m_ratiosSerial = m_sweeper.serial();
  }
  return m_ratios;
}

const k::Centrodes& MechanismDocument::centrodes() const {
  if (m_centrodesSerial != m_sweeper.serial() || m_centrodesSerial == 0) {
    auto curves = k::centrodes(m_design.mechanism, m_sweeper.result());
    m_centrodes = curves ? std::move(curves).value() : k::Centrodes{};
    m_centrodesSerial = m_sweeper.serial();
  }
  return m_centrodes;
}

const CentresAtPose& MechanismDocument::centresAtPose() const {
  if (m_centresSerial == m_poseSerial && m_poseSerial != 0) return m_centresAtPose;
  m_centresSerial = m_poseSerial;
  const k::Mechanism& m = m_design.mechanism;
  if (!m_centreModel || m_centreModelFor != m) {  // the bodies found once per mechanism
    m_centreModel = k::centreModel(m);
    m_centreModelFor = m;
  }
  m_centresAtPose = {};
  const auto& model = *m_centreModel;
  if (!model) m_centresAtPose.reason = QString::fromStdString(model.error().message);
  else if (m_pose.position.size() == m.points.size() &&
           std::all_of(m_pose.position.begin(), m_pose.position.end(), [](const auto& p) { return p.allFinite(); })) {
    m_centresAtPose.centres = k::instantCentres(m, *model, m_pose);
    if (model->centrodeBody != 0) m_centresAtPose.frame = k::couplerFrame(*model, m_pose);
  }
  return m_centresAtPose;
}

k::SolveRequest MechanismDocument::gridRequest() const { return k::gridSweepRequest(m_request.newton); }

const k::SweepResult& MechanismDocument::sweepGrid(const k::Design& design) const {
  ++m_sweepsRun;
  // Only checked designs get here (checkDesign passed), so the sweep runs.
  m_grid.sweeper.sweepNow(design.mechanism, k::designSweepSpec(design), gridRequest());
  return m_grid.sweeper.result();
}

std::optional<k::DerivedDesign> MechanismDocument::takeAccepted(const k::Design& design) {
  auto accepted = std::exchange(m_grid.accepted, std::nullopt);
  if (!accepted || accepted->design != design || accepted->newton != m_request.newton) return std::nullopt;
  return std::move(accepted->derived);
}

bool MechanismDocument::gridDeferred(const k::Design& design) const {
  return !design.time && m_grid.sweeper.defers(design.mechanism, k::designSweepSpec(design), gridRequest());
}

bool MechanismDocument::assemblesAtInstant(const k::Design& design) const {
  m_candidatePose = m_pose;  // prepared for this structure; its free points start the solve
  const k::DriverState driver{m_crankAngle, design.omega, design.alpha};
  return k::solvePoseInto(design.mechanism, driver, {false, false}, m_candidatePose).status !=
         k::PoseStatus::NotAssemblable;
}

void MechanismDocument::adoptGridAnalysis() {
  // The drag's design assembled at the instant shown; a grid none of whose samples assemble
  // (the instant lies between them) leaves the analysis it had.
  auto derived = k::deriveDesign(m_design.mechanism, m_grid.sweeper.result());
  if (!derived) return;
  const k::DesignAnalysis& a = derived->analysis;
  if (a.inputRange == analysis().inputRange && a.notAssembled == analysis().notAssembled) return;
  m_derived = std::move(derived).value();
  const double angle = m_crankAngle;
  clampMotion();
  Changes what = Change::Analysis;
  if (m_crankAngle != angle) {
    solvePoseNow();
    what |= Change::Motion;
  }
  emit changed(what);
}

std::optional<QString> MechanismDocument::edit(const k::Design& design, const QString& description,
                                               std::optional<MergeKey> mergeKey,
                                               std::optional<double> crankAngleAfter) {
  return push(design, description, mergeKey, crankAngleAfter, false);
}

std::optional<QString> MechanismDocument::replace(const k::Design& design, const QString& description) {
  return push(design, description, std::nullopt, std::nullopt, true);
}

std::optional<QString> MechanismDocument::push(const k::Design& design, const QString& description,
                                               std::optional<MergeKey> mergeKey, std::optional<double> crankAngleAfter,
                                               bool another) {
  if (auto why = validate(design)) return why;
  const double angleAfter = crankAngleAfter.value_or(m_crankAngle);
  // On a time base the instant is the motion state: a move of the crank (a drag of its tip)
  // goes to when the law has it there.
  double timeAfter = m_time;
  if (design.time && crankAngleAfter)
    timeAfter = k::timeNearestPosition(*design.time, *crankAngleAfter, m_time, k::inputPeriod(design.mechanism));
  if (design == m_design && angleAfter == m_crankAngle && timeAfter == m_time) return std::nullopt;
  m_undo.push(new EditDesignCommand(this, {m_design, m_crankAngle, m_time}, {design, angleAfter, timeAfter},
                                    description, mergeKey, another));
  return std::nullopt;
}

void MechanismDocument::applyDesign(const DesignState& state, bool another) {
  m_design = state.design;
  m_crankAngle = state.crankAngle;
  m_time = state.time;
  rebuild(SweepNow::No);
  Changes what = Changes(Change::Design) | Change::Motion;
  if (another) what |= Change::Linkage;
  emit changed(what);
}

void MechanismDocument::setCrankAngle(double angle) {
  if (m_design.time) {
    setTime(k::timeNearestPosition(*m_design.time, angle, m_time, k::inputPeriod(m_design.mechanism)));
    return;
  }
  const double clamped = analysis().inputRange.clamp(angle);
  if (clamped == m_crankAngle) return;
  m_crankAngle = clamped;
  solvePoseNow();
  emit changed(Change::Motion);
}

void MechanismDocument::setTime(double t) {
  if (!m_design.time || !std::isfinite(t)) return;
  const double clamped = std::clamp(t, m_design.time->fromTime, m_design.time->toTime);
  if (clamped == m_time) return;
  m_time = clamped;
  clampMotion();
  solvePoseNow();
  emit changed(Change::Motion);
}

void MechanismDocument::setPlotAxis(PlotAxis axis) {
  if (axis == m_plotAxis) return;
  const PlotAxis shown = plotAxis();
  m_plotAxis = axis;
  // Without a time base the plots show the input either way: nothing to redraw.
  if (plotAxis() != shown) emit changed(Change::PlotAxis);
}

void MechanismDocument::setRequest(const k::SolveRequest& request) {
  k::SolveRequest wanted = request;
  wanted.newton = m_request.newton;
  if (wanted == m_request) return;
  m_request = wanted;
  resweep();
  emit changed(Change::Request);
}

void MechanismDocument::setRequestSource(QObject* owner, RequestSource source) {
  m_requestOwner = owner;
  m_requestSource = std::move(source);
}

void MechanismDocument::setQuality(SamplingQuality quality) {
  if (quality == m_quality) return;
  m_quality = quality;
  m_request.newton.tolerance = qualityPreset(quality).newtonTolerance;
  resweep();
  scheduleEstimate();
  emit changed(Change::Request);
}

void MechanismDocument::setDisplayWidth(double pixels) {
  if (!std::isfinite(pixels) || pixels <= 0.0 || pixels == m_displayWidth) return;
  m_displayWidth = pixels;
  // Most width changes (a window drag) leave the count alone at Draft, or move it by a
  // sample or two: only a different grid is worth a sweep.
  if (wantedDisplaySpec() == m_displaySpec) return;
  resweep();
  scheduleEstimate();
  emit changed(Change::Request);
}

void MechanismDocument::measureQualityNow() {
  if (!qualityEstimatePending()) return;
  m_estimateTimer.stop();
  m_estimator.cancel();
  if (auto unmeasured = unmeasuredEstimate()) m_estimate = std::move(*unmeasured);
  else {
    const QualityEstimator::Input in = estimateInput();
    m_estimate = estimatePeakError(in.mechanism, in.omega, in.samplesPerRevolution, in.newton);
  }
  emit changed(Change::Estimate);
}

void MechanismDocument::measureQuality() {
  if (auto unmeasured = unmeasuredEstimate()) {
    m_estimator.cancel();
    m_estimate = std::move(*unmeasured);
    emit changed(Change::Estimate);
    return;
  }
  m_estimator.start(estimateInput());  // measured() lands in adoptEstimate
}

std::optional<QualityEstimate> MechanismDocument::unmeasuredEstimate() const {
  QualityEstimate none;
  if (m_design.time) {
    // The estimate reads peaks off a crank turning at one speed; a law's samples are evenly
    // spaced in time, not in angle, so that measurement would not be this sampling's.
    none.unavailable = tr("not measured on a time base");
    return none;
  }
  if (k::inputKind(m_design.mechanism) != k::InputKind::Angle) {
    none.unavailable = tr("not measured for a linear input");  // its cycle is a crank's turn
    return none;
  }
  return std::nullopt;
}

QualityEstimator::Input MechanismDocument::estimateInput() const {
  return {m_design.mechanism, m_displaySpec.omega, samplesPerRevolution(m_displaySpec.samples, displaySpanDeg()),
          m_request.newton};
}

void MechanismDocument::adoptEstimate(const QualityEstimate& estimate) {
  m_estimate = estimate;
  emit changed(Change::Estimate);
}

void MechanismDocument::scheduleEstimate() {
  m_estimator.cancel();  // measured for what is changing now
  m_estimateTimer.start();
}

void MechanismDocument::reset(const k::Design& design, const QString& filePath) {
  m_undo.clear();
  m_design = design;
  m_filePath = filePath;
  m_crankAngle = 0.0;
  m_time = design.time ? design.time->fromTime : 0.0;
  rebuild(SweepNow::Yes);
  m_undo.setClean();
  emit changed(Changes(Change::Design) | Change::File);
}

void MechanismDocument::setFilePath(const QString& path) {
  m_filePath = path;
  emit changed(Change::File);
}

void MechanismDocument::markSaved() { m_undo.setClean(); }

void MechanismDocument::rebuild(SweepNow now) {
  // Designs reach here accepted (edit/validate, or the document reader and validate): what
  // validate derived a moment ago serves; else the core derives it here.
  std::optional<k::DerivedDesign> derived = takeAccepted(m_design);
  // The crank range and gaps the panel states are the design's grid's, as in the CSV export,
  // whatever the plots' resolution; positions alone decide them. A four-bar whose crank turns
  // fully (closed form) has no gaps, so it skips this sweep.
  if (!k::needsGridSweep(m_design.mechanism)) m_grid.sweeper.cancel();  // an older design's grid must not land
  if (!derived) {
    static const k::SweepResult kNoGrid;
    const k::SweepResult* grid = &kNoGrid;
    if (k::needsGridSweep(m_design.mechanism)) {
      // A drag's grid may go to a worker (gridDeferred): until it lands, the design is derived
      // from the last grid, of the same samples, and adoptGridAnalysis announces what changed.
      if (now == SweepNow::No && gridDeferred(m_design)) {
        ++m_sweepsRun;
        m_grid.sweeper.sweep(m_design.mechanism, k::designSweepSpec(m_design), gridRequest());
      } else {
        sweepGrid(m_design);
      }
      grid = &m_grid.sweeper.result();
    }
    auto fresh = k::deriveDesign(m_design.mechanism, *grid);
    // Only an accepted design gets here, so a refusal can only be a deferred grid's (the last
    // one, of a design before the drag): its analysis is kept until the new grid lands.
    if (fresh) derived = std::move(fresh).value();
    else derived = k::DerivedDesign{k::asFourBar(m_design.mechanism, k::PointsOnLinks::AnyLink), m_derived.analysis};
  }
  m_derived = std::move(*derived);
  // Sized once per design: free points then start each solve from the last pose shown.
  k::preparePose(m_design.mechanism, m_pose);
  if (m_requestOwner && m_requestSource) {
    k::SolveRequest wanted = m_requestSource(m_design.mechanism, m_pose);
    wanted.newton = m_request.newton;
    m_request = wanted;
  }
  resweep(now);
  clampMotion();
  solvePoseNow();
  scheduleEstimate();
}

void MechanismDocument::clampMotion() {
  if (!m_design.time) {
    m_time = 0.0;
    m_crankAngle = analysis().inputRange.clamp(m_crankAngle);
    return;
  }
  // The law decides where the crank is, assembled or not: a sample it cannot reach shows
  // as a gap in the plots, as on an angle grid.
  m_time = std::clamp(m_time, m_design.time->fromTime, m_design.time->toTime);
  m_crankAngle = k::motionAt(m_design.time->law, m_time).position;
}

double MechanismDocument::displaySpanDeg() const {
  // The floor of samples per revolution is a crank's; a linear input has no turns (0: none).
  if (k::inputKind(m_design.mechanism) != k::InputKind::Angle) return 0.0;
  if (m_design.time) return k::radToDeg(k::lawTravel(*m_design.time));
  return m_design.toDeg - m_design.fromDeg;
}

k::SweepSpec MechanismDocument::wantedDisplaySpec() const {
  k::SweepSpec spec = k::designSweepSpec(m_design);
  spec.samples = displaySampleCount(m_quality, m_displayWidth, displaySpanDeg());
  return spec;
}

void MechanismDocument::setForcesNeeded(bool needed) {
  if (needed == m_forcesNeeded) return;
  m_forcesNeeded = needed;
  resweep();
  emit changed(Change::Request);
}

void MechanismDocument::resweep(SweepNow now) {
  m_displaySpec = wantedDisplaySpec();
  // Forces need every point's acceleration (inertia forces are m·a), whatever the plots show.
  k::SolveRequest request = m_request;
  if (m_forcesNeeded) {
    request.velocities = request.accelerations = true;
    request.only = {};
  }
  ++m_sweepsRun;
  if (now == SweepNow::Yes) m_sweeper.sweepNow(m_design.mechanism, m_displaySpec, request);
  else m_sweeper.sweep(m_design.mechanism, m_displaySpec, request);
}

void MechanismDocument::solvePoseNow() {
  k::DriverState driver{m_crankAngle, m_design.omega, m_design.alpha};
  if (m_design.time) {
    const k::DriverState s = k::motionAt(m_design.time->law, m_time);
    driver = {s.position, s.velocity, s.acceleration};
  }
  const k::PoseReport report = k::solvePoseInto(m_design.mechanism, driver, {true, true}, m_pose);
  m_poseStatus = report.status;
  ++m_poseSerial;
}

}  // namespace linkwright::ui
