#pragma once
// The side panel where a linkage's dimensions are typed or slid: one editor for every
// linkage. It lists the core's parameters (kinematics/design/parameters.h) point by point,
// a recognised four-bar's named lengths first, each as a spin box for exact values and a
// slider for quick changes, with the assembly branch where a joint has one (a four-bar's is
// in the Motion panel, in the four-bar's convention); a four-bar also offers its point on the
// coupler. Every change goes through the document (validated, undoable; a slider's drag is one
// undo step); a refused change shows why and the editors snap back to the document's values.
// The editors are rebuilt only when the linkage's structure changes (a dyad attached, another
// document), so typing keeps focus and a slider keeps its span while in use.

#include "ui/panels/dimension_fields.h"
#include "ui/panels/refusal_label.h"

#include <QWidget>

#include <optional>
#include <vector>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QGroupBox;
class QVBoxLayout;

namespace linkwright::ui {

class ParameterEditor;
class MechanismDocument;

class DimensionsPanel : public QWidget {
  Q_OBJECT
public:
  explicit DimensionsPanel(MechanismDocument* document, QWidget* parent = nullptr);

  /// The fields, in order, and their editors (same order).
  const std::vector<DimensionField>& fields() const { return m_fields; }
  ParameterEditor* parameterEditor(std::size_t index) const { return m_editors[index]; }
  /// The spin box of field `index`.
  QDoubleSpinBox* editor(std::size_t index) const;
  /// The field of `slot` (a four-bar's CouplerLength, …) and its spin box, if the linkage has one.
  std::optional<std::size_t> fieldIndex(kinematics::ParameterSlot slot) const;
  QDoubleSpinBox* editor(kinematics::ParameterSlot slot) const;
  /// The branch box of `point`, if it has one.
  QComboBox* branchBox(kinematics::PointId point) const;
  /// A four-bar's "point on the coupler" check box; hidden for any other linkage.
  QCheckBox* couplerPointBox() const { return m_couplerPoint; }
  /// The message shown when the last edit was refused (empty if it was accepted).
  QString refusalMessage() const;

private:
  void rebuild();
  void refresh();
  void resetSliderRanges();
  void editField(std::size_t index, double value, bool final);
  void editBranch(kinematics::PointId point, int index);
  void editCouplerPoint(bool wanted);
  void showOutcome(const std::optional<QString>& refusal);

  MechanismDocument* m_document;
  QGroupBox* m_box;
  QVBoxLayout* m_rowsLayout;
  QCheckBox* m_couplerPoint;
  RefusalLabel* m_message;
  std::vector<DimensionField> m_fields;
  std::vector<ParameterEditor*> m_editors;
  std::vector<std::pair<kinematics::PointId, QComboBox*>> m_branches;
  std::vector<QWidget*> m_rows;  // every widget in the list, deleted on rebuild
  int m_dragSerial = 0;          // separates consecutive slider drags into their own undo steps
  bool m_refreshing = false;
};

}  // namespace linkwright::ui
