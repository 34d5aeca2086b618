#pragma once
// The side panel where a linkage's dimensions are typed. A linkage recognised as a four-bar
// shows its named lengths with sliders and its coupler point (fourbar_lengths_editor.h); any
// other lists each point with the numbers that define it (dimension_fields.h) in spin boxes,
// and its assembly branch where it has one. Every change goes through the document
// (validated, undoable); a refused change shows why and the editors snap back to the
// document's values. The point editors are rebuilt only when the linkage's structure changes
// (a dyad attached, another document), so typing keeps focus.

#include "ui/panels/dimension_fields.h"
#include "ui/panels/refusal_label.h"

#include <QWidget>

#include <vector>

class QComboBox;
class QDoubleSpinBox;
class QGridLayout;
class QGroupBox;
class QLabel;

namespace linkwright::ui {

class FourBarLengthsEditor;
class LengthEditor;
class MechanismDocument;

class DimensionsPanel : public QWidget {
  Q_OBJECT
public:
  explicit DimensionsPanel(MechanismDocument* document, QWidget* parent = nullptr);

  /// The four-bar face, shown while the linkage is a four-bar.
  FourBarLengthsEditor* fourBarEditor() const { return m_fourBar; }
  /// The point-by-point face, shown for any other linkage.
  QGroupBox* pointsBox() const { return m_box; }
  /// Its editor of frame (0), crank (1), coupler (2), rocker (3).
  LengthEditor* lengthEditor(int index) const;
  /// The point-by-point fields (any other linkage), in order, and their editors (same order).
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
  FourBarLengthsEditor* m_fourBar;
  bool m_wasFourBar = false;  // a four-bar again (undo after attaching a dyad): its sliders need ranges
  QGroupBox* m_box;
  QGridLayout* m_grid;
  RefusalLabel* m_message;
  std::vector<DimensionField> m_fields;
  std::vector<QDoubleSpinBox*> m_editors;
  std::vector<std::pair<kinematics::PointId, QComboBox*>> m_branches;
  std::vector<QWidget*> m_rows;  // every widget in the grid, deleted on rebuild
  bool m_refreshing = false;
};

}  // namespace linkwright::ui
