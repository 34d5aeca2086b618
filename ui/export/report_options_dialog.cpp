#include "ui/export/report_options_dialog.h"

#include "ui/number_box.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>

#include <algorithm>
#include <array>

namespace linkwright::ui {

ReportOptionsDialog::ReportOptionsDialog(double at, double maxStep, const QString& unit, QWidget* parent)
    : QDialog(parent), m_at(new NumberBox(this)), m_step(new NumberBox(this)), m_paper(new QComboBox(this)),
      m_units(new QComboBox(this)) {
  setWindowTitle(tr("Lab report as PDF"));
  const QString suffix = unit == QStringLiteral("°") ? unit : QStringLiteral(" ") + unit;
  m_at->setDecimals(4);
  m_at->setRange(-1e6, 1e6);
  m_at->setSuffix(suffix);
  m_at->setValue(at);
  m_step->setDecimals(4);
  // The core refuses a step that is not positive: the smallest the box allows is positive.
  m_step->setRange(1e-4, maxStep);
  m_step->setSuffix(suffix);
  m_step->setValue(std::min(unit == QStringLiteral("°") ? 30.0 : maxStep / 12.0, maxStep));
  m_paper->addItem(tr("A4"), static_cast<int>(kinematics::report::Paper::A4));
  m_paper->addItem(tr("Letter"), static_cast<int>(kinematics::report::Paper::Letter));
  // The three conventions of the seeds' tools: the thesis's Excel, SolidWorks Motion, MATLAB.
  m_units->addItem(tr("deg, rad/s, rad/s² (as the thesis)"));
  m_units->addItem(tr("deg, deg/s, deg/s² (as SolidWorks)"));
  m_units->addItem(tr("rad, rad/s, rad/s²"));
  auto* form = new QFormLayout(this);
  auto* intro = new QLabel(tr("The linkage drawn with its link lengths, the Grashof and mobility analysis, a table of "
                              "the link angles, ω and α, the extremes, the plots and, with masses, the forces: the "
                              "report linkwright-cli report writes."),
                           this);
  intro->setWordWrap(true);
  form->addRow(intro);
  form->addRow(tr("&Draw at"), m_at);
  form->addRow(tr("Table &step"), m_step);
  form->addRow(tr("Angles, ω and α &in"), m_units);
  form->addRow(tr("&Paper"), m_paper);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
  form->addRow(buttons);
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
}

double ReportOptionsDialog::at() const { return m_at->value(); }
double ReportOptionsDialog::step() const { return m_step->value(); }

kinematics::report::Paper ReportOptionsDialog::paper() const {
  return static_cast<kinematics::report::Paper>(m_paper->currentData().toInt());
}

namespace {

namespace kr = kinematics::report;
const std::array<kr::ReportUnits, 3> kUnitChoices{kr::ReportUnits{kr::AngleUnit::Degrees, kr::RateUnit::Radians},
                                                  kr::ReportUnits{kr::AngleUnit::Degrees, kr::RateUnit::Degrees},
                                                  kr::ReportUnits{kr::AngleUnit::Radians, kr::RateUnit::Radians}};

}  // namespace

kinematics::report::ReportUnits ReportOptionsDialog::units() const {
  return kUnitChoices[static_cast<std::size_t>(std::max(0, m_units->currentIndex()))];
}

void ReportOptionsDialog::setUnits(const kinematics::report::ReportUnits& units) {
  for (std::size_t i = 0; i < kUnitChoices.size(); ++i)
    if (kUnitChoices[i] == units) m_units->setCurrentIndex(static_cast<int>(i));
}

}  // namespace linkwright::ui
