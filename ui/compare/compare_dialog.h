#pragma once
// File ▸ Compare…: another tool's table (read by kinematics/io/numeric_table_csv.h) against
// the document's exact solution. The user maps the columns (ColumnMapEditor), chooses the
// crank-angle offset (fitted robustly, none, or a value) and the tolerance, and
// Compare shows each column's worst and rms deviation and, for the column selected, every row
// with the ones beyond the tolerance highlighted; "Draw the rows on the plots" puts the table's
// rows over the designer's curves (PlotPanel::setComparison). Every number is the core's
// (kinematics/compare/table_comparison.h); a mapping the core refuses shows its sentence and
// leaves the last comparison as it was.

#include "kinematics/compare/table_comparison.h"
#include "kinematics/design/design.h"

#include <QDialog>

#include <optional>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QTableWidget;

namespace linkwright::ui {

class ColumnMapEditor;

class CompareDialog : public QDialog {
  Q_OBJECT
public:
  /// `table` read from `path`, compared with `design` (its mechanism, speed and motion law).
  CompareDialog(const kinematics::Design& design, const kinematics::io::NumericTable& table, const QString& path,
                QWidget* parent = nullptr);

  /// Runs the comparison with the mapping and options shown; false (and the reason shown) when
  /// the core refuses them.
  bool compare();

  /// The last comparison that ran.
  const std::optional<kinematics::compare::Comparison>& comparison() const { return m_comparison; }

  ColumnMapEditor* mapEditor() const { return m_editor; }
  QComboBox* offsetChoice() const { return m_offsetMode; }
  QDoubleSpinBox* offsetBox() const { return m_offset; }
  QDoubleSpinBox* toleranceBox() const { return m_tolerance; }
  QTableWidget* summaryTable() const { return m_summary; }
  QTableWidget* rowsTable() const { return m_rows; }
  QLabel* messageLabel() const { return m_message; }
  QCheckBox* drawOnPlotsBox() const { return m_drawOnPlots; }

signals:
  /// What the plots should draw: the last comparison while "Draw the rows on the plots" is
  /// ticked, else nothing. Emitted after each comparison and when the box is toggled.
  void plotOverlayChanged(const std::optional<kinematics::compare::Comparison>& comparison);

private:
  kinematics::compare::CompareOptions options() const;
  void showSummary();
  void showRows(int column);
  void emitPlotOverlay();

  kinematics::Design m_design;
  kinematics::io::NumericTable m_table;
  ColumnMapEditor* m_editor;
  QComboBox* m_offsetMode;
  QDoubleSpinBox* m_offset;
  QDoubleSpinBox* m_tolerance;
  QLabel* m_message;
  QLabel* m_result;
  QTableWidget* m_summary;
  QTableWidget* m_rows;
  QCheckBox* m_drawOnPlots;
  std::optional<kinematics::compare::Comparison> m_comparison;
};

}  // namespace linkwright::ui
