#include "ui/panels/dimensions_panel.h"

#include "ui/canvas/mechanism_drawing.h"
#include "ui/document/edit_design_command.h"
#include "ui/document/mechanism_document.h"
#include "ui/panels/parameter_editor.h"

#include "kinematics/design/fourbar_dimensions.h"

#include <QCheckBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace linkwright::ui {

namespace k = kinematics;

namespace {

// The heading a field is listed under: a four-bar's lengths together, any other number under
// its point.
QString groupOf(const k::Mechanism& m, const DimensionField& f) {
  using S = k::ParameterSlot;
  if (k::isFourBarDimension(f.parameter.slot) && f.parameter.slot != S::FrameAngle)
    return QCoreApplication::translate("DimensionsPanel", "<b>Link lengths</b>");
  const k::PointId p = f.point();
  return QStringLiteral("<b>%1</b> &nbsp;<span style='color:#666'>%2</span>")
      .arg(pointDisplayName(m.points[p.index].name).toHtmlEscaped(), pointRole(m, p).toHtmlEscaped());
}

// The linkage's size, from which the sliders' spans are set: its longest length.
double sizeOf(const std::vector<DimensionField>& fields, const std::vector<double>& values) {
  double size = 0.0;
  for (std::size_t i = 0; i < fields.size(); ++i)
    if (fields[i].unit() == k::ParameterUnit::Length) size = std::max(size, values[i]);
  for (std::size_t i = 0; i < fields.size(); ++i)
    if (size == 0.0 && fields[i].unit() == k::ParameterUnit::Offset) size = std::max(size, std::abs(values[i]));
  return size > 0.0 ? size : 1.0;
}

}  // namespace

DimensionsPanel::DimensionsPanel(MechanismDocument* document, QWidget* parent)
    : QWidget(parent), m_document(document), m_box(new QGroupBox(tr("Dimensions"), this)),
      m_rowsLayout(new QVBoxLayout), m_couplerPoint(new QCheckBox(m_box)), m_message(new RefusalLabel(document, this)) {
  auto* layout = new QVBoxLayout(this);
  auto* boxLayout = new QVBoxLayout(m_box);
  m_rowsLayout->setSpacing(2);
  boxLayout->addLayout(m_rowsLayout);
  boxLayout->addWidget(m_couplerPoint);
  layout->addWidget(m_box);
  layout->addWidget(m_message);
  m_couplerPoint->setToolTip(tr("A point fixed on the coupler, whose path is the coupler curve"));
  connect(m_couplerPoint, &QCheckBox::toggled, this, &DimensionsPanel::editCouplerPoint);
  connect(document, &MechanismDocument::changed, this, [this](Changes what) {
    if (what & Change::Design) refresh();
    // Another document: the sliders span its sizes (they keep their span within a document).
    if ((what & Change::File) && m_document->undoStack()->count() == 0) resetSliderRanges();
  });
  refresh();
}

QDoubleSpinBox* DimensionsPanel::editor(std::size_t index) const { return m_editors[index]->spinBox(); }

std::optional<std::size_t> DimensionsPanel::fieldIndex(k::ParameterSlot slot) const {
  for (std::size_t i = 0; i < m_fields.size(); ++i)
    if (m_fields[i].parameter.slot == slot) return i;
  return std::nullopt;
}

QDoubleSpinBox* DimensionsPanel::editor(k::ParameterSlot slot) const {
  const auto index = fieldIndex(slot);
  return index ? editor(*index) : nullptr;
}

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
  const auto& fourBar = m_document->fourBar();
  m_fields = dimensionFields(m);
  const QString lengthSuffix = QStringLiteral(" ") + QString::fromStdString(m.lengthUnit);
  QString heading;
  const auto addHeading = [&](const QString& text) {
    if (text == heading) return;
    heading = text;
    auto* label = new QLabel(text, m_box);
    m_rows.push_back(label);
    m_rowsLayout->addWidget(label);
  };
  const auto addBranch = [&](k::PointId p) {
    // A four-bar's branch is the Motion panel's, in the four-bar's convention.
    if (branchOf(m.points[p.index]) == nullptr || (fourBar && p == fourBar->c)) return;
    addHeading(groupOf(m, {k::Parameter{p}, {}}));
    auto* row = new QWidget(m_box);
    auto* rowLayout = new QHBoxLayout(row);
    rowLayout->setContentsMargins(10, 0, 0, 0);
    auto* label = new QLabel(tr("branch"), row);
    auto* box = new QComboBox(row);
    label->setBuddy(box);
    rowLayout->addWidget(label);
    rowLayout->addWidget(box, 1);
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
    m_rows.push_back(row);
    m_rowsLayout->addWidget(row);
    m_branches.emplace_back(p, box);
    connect(box, &QComboBox::currentIndexChanged, this, [this, p](int index) {
      if (!m_refreshing) editBranch(p, index);
    });
  };
  for (std::size_t i = 0; i < m_fields.size(); ++i) {
    const DimensionField& f = m_fields[i];
    // A point's branch follows its last number.
    if (i > 0 && !k::isFourBarDimension(m_fields[i - 1].parameter.slot) && m_fields[i - 1].point() != f.point())
      addBranch(m_fields[i - 1].point());
    addHeading(groupOf(m, f));
    auto* editor = new ParameterEditor(f.label, m_box);
    editor->setContentsMargins(10, 0, 0, 0);
    if (f.unit() == k::ParameterUnit::Angle) {
      editor->setRange(-360.0, 360.0);
      editor->setSuffix(QStringLiteral("°"));
    } else {
      editor->setRange(f.unit() == k::ParameterUnit::Length ? 1e-6 : -1e9, 1e9);
      editor->setSuffix(lengthSuffix);
    }
    m_rows.push_back(editor);
    m_rowsLayout->addWidget(editor);
    m_editors.push_back(editor);
    connect(editor, &ParameterEditor::edited, this, [this, i](double v, bool final) {
      if (!m_refreshing) editField(i, v, final);
    });
  }
  if (!m_fields.empty() && !k::isFourBarDimension(m_fields.back().parameter.slot)) addBranch(m_fields.back().point());
  resetSliderRanges();
}

void DimensionsPanel::resetSliderRanges() {
  const k::Mechanism& m = m_document->mechanism();
  // Recognised once for the fields and their values (the document's may lag a drag's grid).
  const auto fourBar = k::asFourBar(m, k::PointsOnLinks::AnyLink);
  if (dimensionFields(m, fourBar) != m_fields) return;  // refresh() rebuilds, and sets them
  const std::vector<double> values = fieldValues(m, m_fields, fourBar);
  const double size = sizeOf(m_fields, values);
  for (std::size_t i = 0; i < m_fields.size(); ++i) {
    const double v = values[i];
    switch (m_fields[i].unit()) {
    case k::ParameterUnit::Length:
      m_editors[i]->setSliderRange(std::min(0.02 * size, 0.5 * v), std::max(3.0 * size, 1.5 * v));
      break;
    case k::ParameterUnit::Offset: m_editors[i]->setSliderRange(v - 2.0 * size, v + 2.0 * size); break;
    case k::ParameterUnit::Angle: m_editors[i]->setSliderRange(v - 180.0, v + 180.0); break;
    }
  }
}

void DimensionsPanel::refresh() {
  const k::Mechanism& m = m_document->mechanism();
  const auto recognised = k::asFourBar(m, k::PointsOnLinks::AnyLink);  // once, for the fields and their values
  if (dimensionFields(m, recognised) != m_fields || m_editors.empty()) rebuild();
  m_refreshing = true;
  const std::vector<double> values = fieldValues(m, m_fields, recognised);
  for (std::size_t i = 0; i < m_fields.size(); ++i) m_editors[i]->setValue(values[i]);
  for (const auto& [p, box] : m_branches) box->setCurrentIndex(*branchOf(m.points[p.index]) == k::Branch::Open ? 0 : 1);
  const auto& fourBar = m_document->fourBar();
  m_couplerPoint->setVisible(fourBar.has_value());
  if (fourBar) {
    const auto point = k::couplerPointOf(m, *fourBar);
    const QSignalBlocker block(m_couplerPoint);
    m_couplerPoint->setText(tr("Point %1 on the coupler")
                                .arg(point ? pointDisplayName(m.points[point->id.index].name) : QStringLiteral("P")));
    m_couplerPoint->setChecked(point.has_value());
  }
  m_refreshing = false;
}

void DimensionsPanel::editField(std::size_t index, double value, bool final) {
  k::Design d = m_document->design();
  const DimensionField& f = m_fields[index];
  setFieldValue(d, f, value);
  const QString what =
      k::isFourBarDimension(f.parameter.slot)
          ? tr("Change %1").arg(f.label)
          : tr("Change %1: %2").arg(pointDisplayName(d.mechanism.points[f.point().index].name), f.label);
  const MergeKey key{ContinuousEdit::Parameter, index, m_dragSerial};
  const auto refusal = m_document->edit(d, what, key);
  if (final) ++m_dragSerial;
  showOutcome(refusal);
}

void DimensionsPanel::editBranch(k::PointId point, int index) {
  k::Design d = m_document->design();
  *branchOf(d.mechanism.points[point.index]) = index == 0 ? k::Branch::Open : k::Branch::Crossed;
  showOutcome(
      m_document->edit(d, tr("Switch branch of %1").arg(pointDisplayName(d.mechanism.points[point.index].name))));
}

void DimensionsPanel::editCouplerPoint(bool wanted) {
  const auto& s = m_document->fourBar();
  if (!s) return;
  // A new point starts at the coupler's middle.
  std::optional<k::CouplerPointSpec> spec;
  if (wanted) spec = k::CouplerPointSpec{s->lengths.coupler / 2.0, 0.0};
  k::Design d = m_document->design();
  auto withPoint = k::withCouplerPoint(d.mechanism, *s, spec);
  if (!withPoint) {
    showOutcome(QString::fromStdString(withPoint.error().message));
    return;
  }
  d.mechanism = std::move(withPoint).value();
  showOutcome(m_document->edit(d, wanted ? tr("Add coupler point") : tr("Remove coupler point")));
}

void DimensionsPanel::showOutcome(const std::optional<QString>& refusal) {
  m_message->showOutcome(refusal);
  refresh();  // a refused value snaps back to the document's
}

}  // namespace linkwright::ui
