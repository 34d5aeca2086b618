#pragma once
// File ▸ Export ▸ Links as DXF: asks the pivot hole diameter and the plate width, in the
// document's length unit, each pre-filled with the core's default for this linkage (a fifth of
// the shortest joint spacing on one link; twice the hole). The ranges are the core's: the
// drawing itself refuses a hole too large for a link or a plate no wider than its hole, and the
// window shows that sentence.

#include "kinematics/analysis/link_drawing.h"

#include <QDialog>

class QDoubleSpinBox;

namespace linkwright::ui {

class DxfOptionsDialog : public QDialog {
  Q_OBJECT
public:
  /// `defaults` are the core's choices for this linkage (LinkDrawing's holeDiameter and
  /// plateWidth), `lengthUnit` the document's.
  DxfOptionsDialog(double defaultHole, double defaultWidth, const QString& lengthUnit, QWidget* parent = nullptr);

  /// What the user chose.
  kinematics::DrawingOptions options() const;

  QDoubleSpinBox* holeBox() const { return m_hole; }
  QDoubleSpinBox* widthBox() const { return m_width; }

private:
  QDoubleSpinBox* m_hole;
  QDoubleSpinBox* m_width;
};

}  // namespace linkwright::ui
