#include "ui/synthesis/synthesis_panel.h"

#include "ui/canvas/linkage_view.h"
#include "ui/geometry.h"
#include "ui/number_box.h"
#include "ui/panels/refusal_label.h"
#include "ui/synthesis/candidate_table.h"
#include "ui/synthesis/path_search_worker.h"
#include "ui/synthesis/synthesis_forms.h"
#include "ui/synthesis/synthesis_preview_item.h"
#include "ui/synthesis/target_forms.h"
#include "ui/synthesis/target_table.h"

#include "kinematics/design/synthesis_ranges.h"
#include "kinematics/model/driver.h"
#include "kinematics/model/units.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGraphicsScene>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalBlocker>
#include <QStackedWidget>
#include <QUndoStack>
#include <QVBoxLayout>

#include <utility>

namespace linkwright::ui {

namespace k = kinematics;

SynthesisPanel::SynthesisPanel(MechanismDocument* document, LinkageView* view, QWidget* parent)
    : QWidget(parent), m_document(document), m_view(view), m_problem(new QComboBox(this)),
      m_transmissionBound(new NumberBox(this)), m_stack(new QStackedWidget(this)),
      m_refusal(new RefusalLabel(document, this)), m_summary(new QLabel(this)), m_table(new CandidateTable(this)),
      m_use(new QPushButton(tr("Use this linkage"), this)), m_pathSearch(new PathSearchWorker(this)),
      m_preview(new SynthesisPreviewItem) {
  setObjectName(QStringLiteral("SynthesisPanel"));
  auto* layout = new QVBoxLayout(this);
  auto* header = new QFormLayout;
  m_problem->addItems({tr("Crank-rocker for a rocker swing"), tr("Slider-crank for a stroke"),
                       tr("Crank-shaper for a stroke"), tr("Function generator"), tr("Motion: coupler poses"),
                       tr("Path: coupler point through points")});
  header->addRow(tr("Problem"), m_problem);
  m_transmissionBound->setRange(-k::kMaxTransmissionBoundDeg, k::kMaxTransmissionBoundDeg);
  m_transmissionBound->setDecimals(1);
  m_transmissionBound->setValue(k::radToDeg(k::DefectBounds{}.minTransmission));
  m_transmissionBound->setSuffix(tr("°"));
  m_transmissionBound->setToolTip(tr("A candidate whose worst transmission angle is below this is marked"));
  header->addRow(tr("Transmission at least"), m_transmissionBound);
  layout->addLayout(header);

  m_forms = {new CrankRockerForm(this), new SliderCrankForm(this), new ShaperForm(this),
             new FunctionForm(this),    new MotionForm(this),      new PathForm(this)};
  m_pathForm = static_cast<PathForm*>(m_forms[static_cast<std::size_t>(SynthesisProblem::Path)]);
  for (std::size_t i = 0; i < m_forms.size(); ++i) {
    ProblemForm* form = m_forms[i];
    form->setLengthUnit(QString::fromStdString(document->lengthUnit()));
    m_stack->addWidget(form);
    const auto problem = static_cast<SynthesisProblem>(i);
    connect(form, &ProblemForm::edited, this, [this, problem] { onEdited(problem); });
  }
  layout->addWidget(m_stack);
  layout->addWidget(buildSearchRow());
  m_refusal->setObjectName(QStringLiteral("synthesis_message"));
  layout->addWidget(m_refusal);
  m_summary->setWordWrap(true);
  layout->addWidget(m_summary);
  layout->addWidget(m_table, 1);
  m_use->setToolTip(tr("Replace the document's linkage by the chosen candidate (Edit ▸ Undo brings it back)"));
  layout->addWidget(m_use);

  for (TargetTable* table : {static_cast<MotionForm*>(form(SynthesisProblem::Motion))->poses(), m_pathForm->points()})
    connect(table, &TargetTable::pickToggled, this, &SynthesisPanel::setPicking);
  if (m_view) {
    m_view->linkageScene()->addItem(m_preview);
    connect(m_view, &LinkageView::pointPicked, this, &SynthesisPanel::onPointPicked);
    connect(m_view, &LinkageView::posePicked, this, &SynthesisPanel::onPosePicked);
  }
  m_preview->setVisible(false);

  connect(m_problem, &QComboBox::currentIndexChanged, this,
          [this](int index) { setProblem(static_cast<SynthesisProblem>(index)); });
  connect(m_transmissionBound, &QDoubleSpinBox::valueChanged, this, [this] { onEdited(problem()); });
  connect(m_table, &CandidateTable::rowChosen, this, [this] {
    updatePreview();
    updateControls();
  });
  connect(m_use, &QPushButton::clicked, this, [this] {
    const std::optional<QString> refusal = useChosen();
    m_refusal->showOutcome(refusal);
    // The candidate is the linkage drawn now; its preview over it would only hide it. Picking
    // a candidate in the table shows the preview again.
    if (!refusal) showPreview(false);
  });
  connect(m_pathSearch, &PathSearchWorker::progress, this, [this](int done, int total) {
    m_progress->setRange(0, total);
    m_progress->setValue(done);
  });
  connect(m_pathSearch, &PathSearchWorker::finished, this, &SynthesisPanel::onPathFinished);
  connect(document, &MechanismDocument::changed, this, [this](Changes what) {
    if (!(what & Change::Design)) return;
    // A document opened, or an undo, brings its own targets: the forms show them.
    const auto& saved = m_document->design().synthesis;
    if (saved && *saved != m_synced) loadTargets(*saved);
    const QString unit = QString::fromStdString(m_document->lengthUnit());
    if (unit == m_forms.front()->lengthUnit()) return;
    for (ProblemForm* f : m_forms) f->setLengthUnit(unit);
    if (closedForm(problem())) solveNow();
  });
  if (const auto& saved = document->design().synthesis) {
    loadTargets(*saved);
  } else {
    m_loading = true;  // the panel's defaults are not an edit of the document
    setProblem(SynthesisProblem::Swing);
    m_loading = false;
  }
}

SynthesisPanel::~SynthesisPanel() {
  // The scene owns the preview once it is added: while the view lives, take it back.
  if (m_view) {
    m_view->setPickMode(LinkageView::PickMode::None);
    m_view->linkageScene()->removeItem(m_preview);
    delete m_preview;
  } else if (m_preview->scene() == nullptr) {
    delete m_preview;
  }
}

QWidget* SynthesisPanel::buildSearchRow() {
  m_searchRow = new QWidget(this);
  auto* row = new QHBoxLayout(m_searchRow);
  row->setContentsMargins(0, 0, 0, 0);
  m_search = new QPushButton(tr("Search"), m_searchRow);
  m_search->setToolTip(tr("Search for four-bars through the points (runs in the background)"));
  m_cancel = new QPushButton(tr("Cancel"), m_searchRow);
  m_cancel->setToolTip(tr("Stop the search and keep what it has found"));
  m_progress = new QProgressBar(m_searchRow);
  m_progress->setRange(0, 1);
  m_progress->setValue(0);
  row->addWidget(m_search);
  row->addWidget(m_cancel);
  row->addWidget(m_progress, 1);
  connect(m_search, &QPushButton::clicked, this, &SynthesisPanel::startPathSearch);
  connect(m_cancel, &QPushButton::clicked, m_pathSearch, &PathSearchWorker::cancel);
  return m_searchRow;
}

void SynthesisPanel::setProblem(SynthesisProblem problem) {
  stopPicking();
  if (m_problem->currentIndex() != static_cast<int>(problem)) {
    m_problem->setCurrentIndex(static_cast<int>(problem));  // comes back here through the signal
    return;
  }
  m_stack->setCurrentIndex(static_cast<int>(problem));
  // The stack as tall as the form shown, not the tallest: the table below gets the rest.
  for (int i = 0; i < m_stack->count(); ++i) {
    const QSizePolicy::Policy policy = i == m_stack->currentIndex() ? QSizePolicy::Preferred : QSizePolicy::Ignored;
    m_stack->widget(i)->setSizePolicy(policy, policy);
  }
  m_stack->adjustSize();
  m_refusal->showOutcome(std::nullopt);
  const auto& shown = m_outcomes[static_cast<std::size_t>(problem)];
  if (closedForm(problem)) {
    if (solveNow()) saveTargets();
  } else if (shown) {
    m_summary->setText(shown->summary);
    m_table->showOutcome(*shown);
  } else {
    m_summary->setText(tr("Enter the points (or pick them on the canvas), then Search."));
    m_table->clearRows();
  }
  updatePreview();
  updateControls();
}

SynthesisProblem SynthesisPanel::problem() const { return static_cast<SynthesisProblem>(m_problem->currentIndex()); }

const std::optional<SynthesisOutcome>& SynthesisPanel::outcome() const {
  return m_outcomes[static_cast<std::size_t>(problem())];
}

QString SynthesisPanel::refusalMessage() const { return m_refusal->refusal(); }

ClosedForm* SynthesisPanel::closedForm(SynthesisProblem problem) const {
  return problem == SynthesisProblem::Path ? nullptr : static_cast<ClosedForm*>(form(problem));
}

k::DefectBounds SynthesisPanel::bounds() const {
  k::DefectBounds b;
  b.minTransmission = k::degToRad(m_transmissionBound->value());
  return b;
}

void SynthesisPanel::onEdited(SynthesisProblem edited) {
  if (edited != problem()) return;
  // Targets are kept in the document once the core accepts them: a refused value loses nothing.
  if (closedForm(edited)) {
    if (solveNow()) saveTargets();
    return;
  }
  if (m_pathForm->request()) saveTargets();
  // The path's candidates were found for other targets: they are dropped, the targets shown.
  m_outcomes[static_cast<std::size_t>(edited)].reset();
  m_table->clearRows();
  m_summary->setText(tr("The targets changed: Search again."));
  updatePreview();
  updateControls();
}

bool SynthesisPanel::solveNow() {
  ClosedForm* form = closedForm(problem());
  if (form == nullptr) return false;
  if (!(m_transmissionBound->value() >= 0.0 && m_transmissionBound->value() <= 90.0)) {
    m_refusal->showOutcome(
        tr("Transmission at least: must be between 0° and 90° (got %1°)").arg(m_transmissionBound->value()));
    return false;
  }
  const auto request = form->request();
  if (!request) {
    m_refusal->showOutcome(QString::fromStdString(request.error().message));
    return false;
  }
  auto solved = solveClosedForm(*request, bounds());
  if (!solved) {
    m_refusal->showOutcome(form->explain(solved.error().field, solved.error().message));
    return false;
  }
  m_refusal->showOutcome(std::nullopt);
  showOutcome(problem(), std::move(solved).value());
  return true;
}

void SynthesisPanel::showOutcome(SynthesisProblem shownProblem, SynthesisOutcome outcome) {
  auto& slot = m_outcomes[static_cast<std::size_t>(shownProblem)];
  slot = std::move(outcome);
  if (shownProblem != problem()) return;
  // Keep the row the user chose while they tune the numbers.
  const std::optional<std::size_t> chosen = m_table->selectedRow();
  m_summary->setText(slot->summary);
  m_table->showOutcome(*slot);
  if (chosen && *chosen < slot->rows.size()) m_table->selectRow(*chosen);
}

void SynthesisPanel::startPathSearch() {
  if (!(m_transmissionBound->value() >= 0.0 && m_transmissionBound->value() <= 90.0)) {
    m_refusal->showOutcome(
        tr("Transmission at least: must be between 0° and 90° (got %1°)").arg(m_transmissionBound->value()));
    return;
  }
  const auto request = m_pathForm->request();
  if (!request) {
    m_refusal->showOutcome(QString::fromStdString(request.error().message));
    return;
  }
  m_refusal->showOutcome(std::nullopt);
  m_progress->setRange(0, request->options.starts);
  m_progress->setValue(0);
  m_summary->setText(tr("Searching…"));
  m_pathSearch->start(*request, bounds());
  updateControls();
}

void SynthesisPanel::onPathFinished(const PathSearchResult& result) {
  updateControls();
  if (result.error) {
    m_summary->clear();
    m_refusal->showOutcome(m_pathForm->explain(result.error->field, result.error->message));
    return;
  }
  showOutcome(SynthesisProblem::Path, pathOutcome(*result.synthesis, result.request.target));
}

std::optional<QString> SynthesisPanel::useChosen() {
  const auto& shown = outcome();
  const std::optional<std::size_t> row = m_table->selectedRow();
  if (!shown || !row || *row >= shown->rows.size()) return tr("Choose a candidate in the table first");
  const SynthesisRow& chosen = shown->rows[*row];
  const QString name = QString::fromStdString(chosen.candidate.design.kind);
  k::Design design = chosen.candidate.design;
  design.synthesis = targets();
  // The motor stays as it was: the new linkage is driven at the document's speed.
  const k::Design& current = m_document->design();
  if (k::inputKind(current.mechanism) == k::inputKind(design.mechanism)) {
    design.omega = current.omega;
    design.alpha = current.alpha;
  }
  const k::SynthesisTargets previous = std::exchange(m_synced, *design.synthesis);
  auto refusal = m_document->replace(design, tr("Use synthesised %1").arg(name));
  if (refusal) m_synced = previous;
  return refusal;
}

k::SynthesisTargets SynthesisPanel::targets() const {
  k::SynthesisTargets t = m_document->design().synthesis.value_or(k::SynthesisTargets{});
  t.problem = problem();
  for (const ProblemForm* f : m_forms) f->store(t);
  t.bounds.minTransmission = k::degToRad(m_transmissionBound->value());
  return t;
}

void SynthesisPanel::loadTargets(const k::SynthesisTargets& t) {
  m_synced = t;
  m_loading = true;
  for (ProblemForm* f : m_forms) f->load(t);
  {
    const QSignalBlocker block(m_transmissionBound);
    m_transmissionBound->setValue(k::radToDeg(t.bounds.minTransmission));
  }
  // Other problems' candidates were found for other targets.
  for (auto& shown : m_outcomes) shown.reset();
  m_problem->setCurrentIndex(static_cast<int>(t.problem));
  setProblem(t.problem);
  m_loading = false;
}

void SynthesisPanel::saveTargets() {
  if (m_loading) return;
  k::Design d = m_document->design();
  const k::SynthesisTargets t = targets();
  if (d.synthesis == t) return;
  d.synthesis = t;
  // One undo step while the user goes on typing; a new one once anything else was done or undone.
  QUndoStack* undo = m_document->undoStack();
  if (undo->index() != m_targetsIndex) ++m_editSerial;
  // Synced first: the document announces the edit before edit() returns.
  const k::SynthesisTargets previous = std::exchange(m_synced, t);
  if (m_document->edit(d, tr("Change synthesis targets"),
                       MergeKey{ContinuousEdit::SynthesisTargets, 0, m_editSerial})) {
    m_synced = previous;
    return;
  }
  m_targetsIndex = undo->index();
}

void SynthesisPanel::setPicking(bool on) {
  if (!m_view) return;
  if (!on) {
    m_view->setPickMode(LinkageView::PickMode::None);
    return;
  }
  m_view->setPickMode(problem() == SynthesisProblem::Motion ? LinkageView::PickMode::Pose
                                                            : LinkageView::PickMode::Point);
}

void SynthesisPanel::stopPicking() {
  for (TargetTable* table : {static_cast<MotionForm*>(form(SynthesisProblem::Motion))->poses(), m_pathForm->points()})
    table->pickButton()->setChecked(false);  // each toggles the view's pick mode off
}

void SynthesisPanel::onPointPicked(const QPointF& model) {
  if (problem() != SynthesisProblem::Path || !m_pathForm->points()->pickButton()->isChecked()) return;
  if (!m_pathForm->appendPoint(toEigen(model)))
    m_refusal->showOutcome(
        tr("Targets: the table holds at most %1 points; remove one first").arg(m_pathForm->points()->maxRows()));
}

void SynthesisPanel::onPosePicked(const QPointF& model, double angle) {
  auto* motion = static_cast<MotionForm*>(form(SynthesisProblem::Motion));
  if (problem() != SynthesisProblem::Motion || !motion->poses()->pickButton()->isChecked()) return;
  if (!motion->appendPose(toEigen(model), angle))
    m_refusal->showOutcome(
        tr("Poses: the table holds at most %1 poses; remove one first").arg(motion->poses()->maxRows()));
}

void SynthesisPanel::updatePreview() {
  const auto& shown = outcome();
  const std::optional<std::size_t> row = m_table->selectedRow();
  if (!m_shown || !shown || !row || *row >= shown->rows.size()) {
    // Path targets typed or picked before a search are still worth seeing.
    if (m_shown && problem() == SynthesisProblem::Path) {
      if (const auto request = m_pathForm->request()) {
        m_preview->setPreview({}, 0.0, {request->target.points, {}});
        showPreview(true);
        return;
      }
    }
    showPreview(false);
    return;
  }
  const SynthesisRow& chosen = shown->rows[*row];
  PreviewMarks targets = shown->targets;
  targets.points.insert(targets.points.end(), chosen.targets.points.begin(), chosen.targets.points.end());
  targets.poses.insert(targets.poses.end(), chosen.targets.poses.begin(), chosen.targets.poses.end());
  m_preview->setPreview(chosen.candidate.design.mechanism, chosen.previewInput, targets);
  showPreview(true);
}

// A candidate may lie far from the document's linkage (its own scale and pivots): the view
// keeps the preview on screen, zooming out to it when it appears off screen.
void SynthesisPanel::showPreview(bool visible) {
  m_preview->setVisible(visible);
  if (m_view) m_view->setExtraRegion(visible ? m_preview->sceneBoundingRect() : QRectF());
}

void SynthesisPanel::updateControls() {
  const bool path = problem() == SynthesisProblem::Path;
  m_searchRow->setVisible(path);
  m_cancel->setEnabled(m_pathSearch->isRunning());
  m_progress->setEnabled(m_pathSearch->isRunning());
  m_use->setEnabled(m_table->selectedRow().has_value());
}

void SynthesisPanel::showEvent(QShowEvent* event) {
  QWidget::showEvent(event);
  m_shown = true;
  updatePreview();
}

void SynthesisPanel::hideEvent(QHideEvent* event) {
  QWidget::hideEvent(event);
  m_shown = false;
  stopPicking();
  updatePreview();
}

}  // namespace linkwright::ui
