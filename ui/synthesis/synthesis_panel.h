#pragma once
// The designer's synthesis panel (issue 19): choose a problem, type its targets (or pick them
// on the canvas), see the candidates the core finds in a table (error, Grashof class, worst
// transmission angle, defects with their reasons) and the chosen one dashed on the canvas at
// its first target, then "Use this linkage" to make it the document's design in one undoable
// step. The closed-form problems solve again on every edit; path generation runs in a worker
// (PathSearchWorker) with a progress bar and Cancel. A refused input is shown, naming the field, and
// the last good candidates stay. The panel computes nothing itself: synthesis_solve.h calls
// the core.

#include "ui/document/mechanism_document.h"
#include "ui/synthesis/synthesis_outcome.h"

#include "kinematics/synthesis/candidate.h"

#include <QPointer>
#include <QWidget>

#include <array>
#include <optional>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QStackedWidget;

namespace linkwright::ui {

class CandidateTable;
class ClosedForm;
class LinkageView;
class PathForm;
class PathSearchWorker;
struct PathSearchResult;
class ProblemForm;
class RefusalLabel;
class SynthesisPreviewItem;

class SynthesisPanel : public QWidget {
  Q_OBJECT
public:
  /// Draws its preview in `view`'s scene and picks targets through `view`.
  SynthesisPanel(MechanismDocument* document, LinkageView* view, QWidget* parent = nullptr);
  ~SynthesisPanel() override;

  /// Shows `problem`'s form (and solves it, if it is closed-form).
  void setProblem(SynthesisProblem problem);
  SynthesisProblem problem() const;
  QComboBox* problemBox() const { return m_problem; }
  /// The form of `problem`.
  ProblemForm* form(SynthesisProblem problem) const { return m_forms[static_cast<std::size_t>(problem)]; }
  PathForm* pathForm() const { return m_pathForm; }
  QDoubleSpinBox* transmissionBoundBox() const { return m_transmissionBound; }
  CandidateTable* candidates() const { return m_table; }
  QPushButton* useButton() const { return m_use; }
  QPushButton* searchButton() const { return m_search; }
  QPushButton* cancelButton() const { return m_cancel; }
  QProgressBar* progressBar() const { return m_progress; }
  PathSearchWorker* pathSearch() const { return m_pathSearch; }
  SynthesisPreviewItem* preview() const { return m_preview; }
  /// The candidates shown for the current problem, if any.
  const std::optional<SynthesisOutcome>& outcome() const;
  /// The refusal shown ("Not applied: Time ratio Q: …"); empty when none.
  QString refusalMessage() const;

  /// Solves the current closed-form problem from its fields now (what an edit does); false if
  /// refused (the refusal is shown) or the problem is not closed-form.
  bool solveNow();
  /// Starts a path search from the path form's fields (the Search button).
  void startPathSearch();
  /// Makes the chosen candidate the document's design, undoably (the "Use this linkage"
  /// button), keeping the targets it was found for. Returns why not, if the document refuses
  /// or nothing is chosen.
  std::optional<QString> useChosen();

  /// The targets and bounds as the forms hold them: what the document saves.
  kinematics::SynthesisTargets targets() const;
  /// Shows saved targets in the forms (and solves the problem shown), without editing the document.
  void loadTargets(const kinematics::SynthesisTargets& targets);

protected:
  void showEvent(QShowEvent* event) override;
  void hideEvent(QHideEvent* event) override;

private:
  QWidget* buildSearchRow();
  void onEdited(SynthesisProblem problem);
  // Puts the forms' targets into the document: one undo step per run of edits.
  void saveTargets();
  void showOutcome(SynthesisProblem problem, SynthesisOutcome outcome);
  void onPathFinished(const PathSearchResult& result);
  void onPointPicked(const QPointF& model);
  void onPosePicked(const QPointF& model, double angle);
  void setPicking(bool on);
  void stopPicking();
  void updatePreview();
  void showPreview(bool visible);
  void updateControls();
  kinematics::DefectBounds bounds() const;
  ClosedForm* closedForm(SynthesisProblem problem) const;

  MechanismDocument* m_document;
  QPointer<LinkageView> m_view;  // null once the view (and its scene, with the preview) is gone
  QComboBox* m_problem;
  QDoubleSpinBox* m_transmissionBound;
  QStackedWidget* m_stack;
  std::array<ProblemForm*, kSynthesisProblemCount> m_forms{};
  PathForm* m_pathForm = nullptr;
  QWidget* m_searchRow = nullptr;
  QPushButton* m_search = nullptr;
  QPushButton* m_cancel = nullptr;
  QProgressBar* m_progress = nullptr;
  RefusalLabel* m_refusal;
  QLabel* m_summary;
  CandidateTable* m_table;
  QPushButton* m_use;
  PathSearchWorker* m_pathSearch;
  SynthesisPreviewItem* m_preview;  // in m_view's scene
  std::array<std::optional<SynthesisOutcome>, kSynthesisProblemCount> m_outcomes{};
  bool m_shown = false;
  // The targets last loaded from or saved to the document: a design change that brings
  // others (an undo, a file opened) loads them.
  kinematics::SynthesisTargets m_synced;
  bool m_loading = false;   // loading saved targets: the forms' changes are not edits
  int m_editSerial = 0;     // targets' edits merge into one undo step while it stays the same
  int m_targetsIndex = -1;  // the undo stack's index after the last targets' edit
};

}  // namespace linkwright::ui
