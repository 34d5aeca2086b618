#pragma once
// Edit ▸ Optimise… (issue 46): a better linkage by one measure, from the design the user has.
// The objective (peak |α| of a link, the worst transmission angle, the distance of a point's
// path from target points, the RMS driving torque), the ± range on each length, the ground
// pivots kept and the seed are chosen here; Run optimises in the background
// (optimise_runner.h) with a progress bar and Cancel; then the objective's curve before
// (dashed) and after on one chart, the figures and the dimensions changed. Accept applies the
// result as one undoable edit; Discard leaves the design. An edit of the design while the
// window is open drops a result computed for the design before it, and stops a run. Not modal.

#include "kinematics/tune/optimise_linkage.h"

#include <QWidget>

#include <optional>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QProgressBar;
class QPushButton;
class QSpinBox;

namespace linkwright::ui {

class ForceChartView;
class MechanismDocument;
class OptimiseRunner;

class OptimiseWindow : public QWidget {
  Q_OBJECT
public:
  explicit OptimiseWindow(MechanismDocument* document, QWidget* parent = nullptr);
  ~OptimiseWindow() override;

  QComboBox* objectiveBox() const { return m_objective; }
  QComboBox* linkBox() const { return m_link; }
  QComboBox* pointBox() const { return m_point; }
  QComboBox* measureBox() const { return m_measure; }
  QLineEdit* targetsField() const { return m_targets; }
  QDoubleSpinBox* rangeField() const { return m_range; }
  QListWidget* pivotsList() const { return m_pivots; }
  QSpinBox* seedField() const { return m_seed; }
  QSpinBox* evaluationsField() const { return m_evaluations; }
  QPushButton* runButton() const { return m_run; }
  QPushButton* cancelButton() const { return m_cancel; }
  QPushButton* acceptButton() const { return m_accept; }
  QPushButton* discardButton() const { return m_discard; }
  QProgressBar* progressBar() const { return m_progress; }
  ForceChartView* chart() const { return m_chart; }
  QString summaryText() const;
  /// The result shown, if any: it belongs to the document's design as it is.
  const std::optional<kinematics::LinkageOptimisation>& result() const { return m_result; }
  bool running() const;

  /// The request the fields make, or the sentence why they make none (targets typed wrong).
  kinematics::Result<kinematics::OptimiseRequest> request() const;

signals:
  /// A run ended: with a result, or with the reason there is none.
  void runEnded();

private:
  void run();
  void cancelRun();
  void acceptResult();
  void discardResult();
  void followDesign();
  void onFinished();
  void showResult();
  void updateFields();

  MechanismDocument* m_document;
  OptimiseRunner* m_runner;
  QComboBox* m_objective;
  QComboBox* m_link;
  QComboBox* m_point;
  QComboBox* m_measure;
  QLineEdit* m_targets;
  QDoubleSpinBox* m_range;
  QListWidget* m_pivots;
  QSpinBox* m_seed;
  QSpinBox* m_evaluations;
  QPushButton* m_run;
  QPushButton* m_cancel;
  QPushButton* m_accept;
  QPushButton* m_discard;
  QProgressBar* m_progress;
  QLabel* m_summary;
  ForceChartView* m_chart;
  std::optional<kinematics::LinkageOptimisation> m_result;
  bool m_applying = false;  // our own Accept is editing the document
  bool m_applied = false;   // the summary and chart tell of the design Accept applied
};

}  // namespace linkwright::ui
