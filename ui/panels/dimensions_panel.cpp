#include "ui/panels/dimensions_panel.h"

#include "ui/canvas/mechanism_drawing.h"
#include "ui/document/edit_design_command.h"
#include "ui/document/mechanism_document.h"
#include "ui/panels/fourbar_lengths_editor.h"
#include "ui/quiet_update.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QGroupBox>
#include <QLabel>
#include <QSignalBlocker>
#include <QVBoxLayout>

namespace linkwright::ui {

namespace k = kinematics;

DimensionsPanel::DimensionsPanel(MechanismDocument* document, QWidget* parent)
    : QWidget(parent), m_document(document), m_fourBar(new FourBarLengthsEditor(document, this)),
      m_box(new QGroupBox(tr("Dimensions"), this)), m_grid(new QGridLayout(m_box)),
      m_message(new RefusalLabel(document, this)) {
  auto* layout = new QVBoxLayout(this);
  m_grid->setColumnStretch(1, 1);
  m_grid->setVerticalSpacing(3);
  layout->addWidget(m_fourBar);
  layout->addWidget(m_box);
  layout->addWidget(m_message);
  connect(m_fourBar, &FourBarLengthsEditor::edited, this, &DimensionsPanel::showOutcome);
  connect(document, &MechanismDocument::changed, this, [this](Changes what) {
    if ((what & Change::File) && m_document->undoStack()->count() == 0) m_fourBar->resetSliderRanges();
    if (what & Change::Design) refresh();
  });
  refresh();
}

LengthEditor* DimensionsPanel::lengthEditor(int index) const { return m_fourBar->lengthEditor(index); }

QComboBox* DimensionsPanel::branchBox(k::PointId point) const {
  for (const auto& [p, box] : m_branches)
    if (p == point) return box;
  return nullptr;
}

QString DimensionsPanel::refusalMessage() const { return m_message->refusal(); }

void DimensionsPanel::rebuild() {
  for (QWidget* w : m_rows) delete w;
  m_rows.clear();
  m_editors.clear();
  m_branches.clear();
  const k::Mechanism& m = m_document->mechanism();
  m_fields = dimensionFields(m);
  const QString unit = QStringLiteral(" ") + QString::fromStdString(m.lengthUnit);
  int row = 0;
  std::size_t next = 0;
  for (std::size_t i = 0; i < m.points.size(); ++i) {
    const k::PointId p{i};
    auto* heading =
        new QLabel(QStringLiteral("<b>%1</b> &nbsp;<span style='color:#666'>%2</span>")
                       .arg(pointDisplayName(m.points[i].name).toHtmlEscaped(), pointRole(m, p).toHtmlEscaped()),
                   m_box);
    m_rows.push_back(heading);
    m_grid->addWidget(heading, row++, 0, 1, 2);
    for (; next < m_fields.size() && m_fields[next].point() == p; ++next) {
      const DimensionField& f = m_fields[next];
      auto* label = new QLabel(f.label, m_box);
      auto* spin = new QDoubleSpinBox(m_box);
      spin->setDecimals(4);
      spin->setKeyboardTracking(false);  // typed numbers apply on Enter or focus out
      spin->setAccelerated(true);
      if (f.unit() == k::ParameterUnit::Angle) {
        spin->setRange(-360.0, 360.0);
        spin->setSuffix(QStringLiteral("°"));
      } else {
        spin->setRange(f.unit() == k::ParameterUnit::Length ? 1e-6 : -1e9, 1e9);
        spin->setSuffix(unit);
      }
      label->setBuddy(spin);
      label->setIndent(10);
      m_grid->addWidget(label, row, 0);
      m_grid->addWidget(spin, row++, 1);
      m_rows.push_back(label);
      m_rows.push_back(spin);
      m_editors.push_back(spin);
      connect(spin, &QDoubleSpinBox::valueChanged, this, [this, index = m_editors.size() - 1](double v) {
        if (!m_refreshing) editField(index, v);
      });
    }
    if (branchOf(m.points[i]) != nullptr) {
      auto* label = new QLabel(tr("branch"), m_box);
      auto* box = new QComboBox(m_box);
      // An arm's elbow in the words of robotics; any other joint in the linkage's.
      if (m_document->design().kind == "two-link arm") {
        box->addItems({tr("Elbow up"), tr("Elbow down")});
        box->setToolTip(
            tr("Elbow up: the elbow left of the line from the shoulder to the tip, as seen along it "
               "(the open assembly); elbow down: its mirror image"));
      } else {
        box->addItems({tr("Open"), tr("Crossed")});
        box->setToolTip(
            tr("Which of the two assemblies: open puts the joint left of the line from its first to its "
               "second parent (a slider: further along its guide)"));
      }
      label->setIndent(10);
      m_grid->addWidget(label, row, 0);
      m_grid->addWidget(box, row++, 1);
      m_rows.push_back(label);
      m_rows.push_back(box);
      m_branches.emplace_back(p, box);
      connect(box, &QComboBox::currentIndexChanged, this, [this, p](int index) {
        if (!m_refreshing) editBranch(p, index);
      });
    }
  }
}

void DimensionsPanel::refresh() {
  const bool fourBar = m_document->fourBar().has_value();
  m_fourBar->setVisible(fourBar);
  m_box->setVisible(!fourBar);
  if (fourBar && !m_wasFourBar) m_fourBar->resetSliderRanges();
  m_wasFourBar = fourBar;
  if (fourBar) {
    m_fourBar->refresh();
    return;
  }
  const k::Mechanism& m = m_document->mechanism();
  if (dimensionFields(m) != m_fields || m_editors.empty()) rebuild();
  m_refreshing = true;
  for (std::size_t i = 0; i < m_fields.size(); ++i) setValueQuietly(m_editors[i], fieldValue(m, m_fields[i]));
  for (const auto& [p, box] : m_branches) box->setCurrentIndex(*branchOf(m.points[p.index]) == k::Branch::Open ? 0 : 1);
  m_refreshing = false;
}

void DimensionsPanel::editField(std::size_t index, double value) {
  k::Design d = m_document->design();
  setFieldValue(d.mechanism, m_fields[index], value);
  const DimensionField& f = m_fields[index];
  const QString what = tr("Change %1: %2").arg(pointDisplayName(d.mechanism.points[f.point().index].name), f.label);
  showOutcome(m_document->edit(d, what));
}

void DimensionsPanel::editBranch(k::PointId point, int index) {
  k::Design d = m_document->design();
  *branchOf(d.mechanism.points[point.index]) = index == 0 ? k::Branch::Open : k::Branch::Crossed;
  showOutcome(
      m_document->edit(d, tr("Switch branch of %1").arg(pointDisplayName(d.mechanism.points[point.index].name))));
}

void DimensionsPanel::showOutcome(const std::optional<QString>& refusal) {
  m_message->showOutcome(refusal);
  refresh();  // a refused value snaps back to the document's
}

}  // namespace linkwright::ui
