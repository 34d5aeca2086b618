#pragma once
// A small table of targets typed by the user (points: x, y; poses: x, y, angle; a crank angle
// per point when timing is prescribed), with Add / Remove row buttons and a "Pick on canvas"
// toggle: while it is on, the panel appends what the user clicks on the canvas. Cells are
// read as numbers (C locale or the user's); an empty or unreadable cell is refused naming its
// row and column.

#include "kinematics/model/result.h"

#include <QStringList>
#include <QWidget>

#include <vector>

class QPushButton;
class QTableWidget;

namespace linkwright::ui {

class TargetTable : public QWidget {
  Q_OBJECT
public:
  /// `rowName` names a row in messages ("Point", "Pose": "Point 3"); rows between `minRows`
  /// and `maxRows`.
  TargetTable(const QStringList& headers, const QString& rowName, int minRows, int maxRows, QWidget* parent = nullptr);

  QTableWidget* table() const { return m_table; }
  QPushButton* pickButton() const { return m_pick; }
  int rowCount() const;
  /// Replaces every row (each as many values as there are columns).
  void setRows(const std::vector<std::vector<double>>& rows);
  /// Appends a row; false (and nothing changes) if the table is full.
  bool appendRow(const std::vector<double>& values);
  /// Every row's values; `skipColumn` (≥ 0) is not read (a hidden column). Refused with the
  /// cell named if one cannot be read, or if there are too few or too many rows.
  kinematics::Result<std::vector<std::vector<double>>> values(int skipColumn = -1) const;
  /// "Point 3" for row index 2.
  QString rowLabel(int row) const { return QStringLiteral("%1 %2").arg(m_rowName).arg(row + 1); }
  int maxRows() const { return m_maxRows; }

signals:
  void edited();
  void pickToggled(bool on);

private:
  void setRow(int row, const std::vector<double>& values);
  void updateButtons();

  QTableWidget* m_table;
  QPushButton* m_add;
  QPushButton* m_remove;
  QPushButton* m_pick;
  QString m_rowName;
  int m_minRows;
  int m_maxRows;
  bool m_filling = false;
};

}  // namespace linkwright::ui
