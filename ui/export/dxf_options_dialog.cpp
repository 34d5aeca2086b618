#include "ui/export/dxf_options_dialog.h"

#include "ui/number_box.h"

#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>

namespace linkwright::ui {

namespace {

// Wide enough for any linkage a document holds: the core checks the real bounds.
QDoubleSpinBox* lengthBox(double value, const QString& unit, QWidget* parent) {
  auto* box = new NumberBox(parent);
  box->setDecimals(6);
  box->setRange(1e-6, 1e9);
  box->setSuffix(QStringLiteral(" ") + unit);
  box->setValue(value);
  box->setStepType(QAbstractSpinBox::AdaptiveDecimalStepType);
  return box;
}

}  // namespace

DxfOptionsDialog::DxfOptionsDialog(double defaultHole, double defaultWidth, const QString& lengthUnit, QWidget* parent)
    : QDialog(parent), m_hole(lengthBox(defaultHole, lengthUnit, this)),
      m_width(lengthBox(defaultWidth, lengthUnit, this)) {
  setWindowTitle(tr("Export links as DXF"));
  auto* form = new QFormLayout(this);
  auto* intro = new QLabel(tr("Each link at true size, drawn where it is now: its plate outline and a hole at each "
                              "joint, one layer per link, the ground pivots on the GROUND layer."),
                           this);
  intro->setWordWrap(true);
  form->addRow(intro);
  form->addRow(tr("Pivot &hole diameter"), m_hole);
  form->addRow(tr("Plate &width"), m_width);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
  form->addRow(buttons);
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
}

kinematics::DrawingOptions DxfOptionsDialog::options() const {
  kinematics::DrawingOptions o;
  o.holeDiameter = m_hole->value();
  o.plateWidth = m_width->value();
  return o;
}

}  // namespace linkwright::ui
