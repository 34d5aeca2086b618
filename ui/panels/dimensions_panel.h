#pragma once
// The side panel for any linkage other than a four-bar: each point with the numbers that
// define it (dimension_fields.h) in spin boxes, and its assembly branch where it has one.
// Every change goes through the document (validated, undoable); a refused change shows why
// and the editors snap back to the document's values. The editors are rebuilt only when the
// linkage's structure changes (a dyad attached, another document), so typing keeps focus.

#include "ui/panels/dimension_fields.h"

#include <QWidget>

#include <vector>

class QComboBox;
class QDoubleSpinBox;
class QGridLayout;
class QGroupBox;
class QLabel;

namespace linkwright::ui {

class MechanismDocument;

class DimensionsPanel : public QWidget {
  Q_OBJECT
public:
  explicit DimensionsPanel(MechanismDocument* document, QWidget* parent = nullptr);

  /// The fields shown, in order, and their editors (same order).
  const std::vector<DimensionField>& fields() const { return m_fields; }
  QDoubleSpinBox* editor(std::size_t index) const { return m_editors[index]; }
  /// The branch box of `point`, if it has one.
  QComboBox* branchBox(kinematics::PointId point) const;
  /// The message shown when the last edit was refused (empty if it was accepted).
  QString refusalMessage() const;

private:
  void rebuild();
  void refresh();
  void editField(std::size_t index, double value);
  void editBranch(kinematics::PointId point, int index);
  void showOutcome(const std::optional<QString>& refusal);

  MechanismDocument* m_document;
  QGroupBox* m_box;
  QGridLayout* m_grid;
  QLabel* m_message;
  std::vector<DimensionField> m_fields;
  std::vector<QDoubleSpinBox*> m_editors;
  std::vector<std::pair<kinematics::PointId, QComboBox*>> m_branches;
  std::vector<QWidget*> m_rows;  // every widget in the grid, deleted on rebuild
  bool m_refreshing = false;
};

}  // namespace linkwright::ui
