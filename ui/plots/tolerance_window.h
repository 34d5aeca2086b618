#pragma once
// View ▸ Tolerances… (issue 46): how much the motion moves when the parts are made a little
// wrong. For the ± typed (one tolerance on every length and pivot coordinate, in the length
// unit), the Monte-Carlo band of the chosen output over the design's grid (nominal, lowest and
// highest of the samples: kinematics/tune/tolerance_monte_carlo.h) and the exact sensitivity of
// that output to each dimension against the input (tolerance_sensitivity.h), with the worst
// deviation, the first-order worst case and the samples that did not assemble. It computes
// while shown, once an edit has settled, on the worker pool (an edit drops the study under way,
// Cancel stops it); a design it cannot study leaves it saying why, with
// nothing drawn from before. Not modal.

#include "ui/document/background_request.h"
#include "ui/document/tolerance_job.h"
#include "ui/plots/angle_unit.h"

#include "kinematics/tune/tolerance_monte_carlo.h"
#include "kinematics/tune/tolerance_sensitivity.h"

#include <QTimer>
#include <QWidget>

#include <optional>

class QComboBox;
class QProgressBar;
class QPushButton;
class QDoubleSpinBox;
class QLabel;
class QSpinBox;
class QTableWidget;

namespace linkwright::ui {

class ForceChartView;
class MechanismDocument;

class ToleranceWindow : public QWidget {
  Q_OBJECT
public:
  explicit ToleranceWindow(MechanismDocument* document, QWidget* parent = nullptr);

  QDoubleSpinBox* toleranceField() const { return m_tolerance; }
  QSpinBox* samplesField() const { return m_samples; }
  QSpinBox* seedField() const { return m_seed; }
  QComboBox* outputBox() const { return m_output; }
  ForceChartView* bandChart() const { return m_band; }
  ForceChartView* sensitivityChart() const { return m_sensitivity; }
  /// One row per dimension of the design: its name and its own ± (blank: the common ±).
  QTableWidget* ownTolerancesTable() const { return m_own; }
  /// The figures of the chosen output, or why there are none.
  QString summaryText() const;
  /// Starts the study on the worker pool for the design and fields as they are (tests; the
  /// settle timer's end); an edit or a field changed meanwhile drops it.
  void refresh();
  /// Blocks until the study under way has landed and is shown (tests).
  void waitForStudy();
  /// Stops the study under way (the window's Cancel button).
  QPushButton* cancelButton() const { return m_cancel; }

protected:
  void showEvent(QShowEvent* event) override;

private:
  void scheduleRefresh();
  void display(const ToleranceOutcome& outcome);
  void redraw();
  // The table's rows for the design's dimensions, each ± typed kept by the dimension's name.
  void showDimensions();

  MechanismDocument* m_document;
  QDoubleSpinBox* m_tolerance;
  QSpinBox* m_samples;
  QSpinBox* m_seed;
  QTableWidget* m_own;
  QComboBox* m_output;
  QLabel* m_summary;
  ForceChartView* m_band;
  ForceChartView* m_sensitivity;
  QProgressBar* m_busy;  // shown while a study runs
  QPushButton* m_cancel;
  BackgroundRequest<ToleranceOutcome> m_run;
  QTimer m_settle;
  std::optional<kinematics::MonteCarloResult> m_monteCarlo;
  std::optional<kinematics::SweepSensitivities> m_sensitivities;
  std::optional<kinematics::SensitivitySummary> m_firstOrder;  // the refined first-order worst cases
};

}  // namespace linkwright::ui
