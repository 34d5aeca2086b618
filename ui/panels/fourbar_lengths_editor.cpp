#include "ui/panels/fourbar_lengths_editor.h"

#include "ui/canvas/mechanism_drawing.h"
#include "ui/document/edit_design_command.h"
#include "ui/document/mechanism_document.h"
#include "ui/panels/length_editor.h"

#include "kinematics/design/fourbar_dimensions.h"

#include <QCheckBox>
#include <QGroupBox>
#include <QVBoxLayout>

#include <algorithm>

namespace linkwright::ui {

namespace k = kinematics;

namespace {

std::array<double, 4> lengthsArray(const k::FourBarLengths& l) { return {l.frame, l.crank, l.coupler, l.rocker}; }

}  // namespace

FourBarLengthsEditor::FourBarLengthsEditor(MechanismDocument* document, QWidget* parent)
    : QWidget(parent), m_document(document), m_hasCouplerPoint(new QCheckBox(this)),
      m_along(new LengthEditor(QString(), true, this)), m_across(new LengthEditor(QString(), true, this)) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  auto* box = new QGroupBox(tr("Link lengths"), this);
  auto* boxLayout = new QVBoxLayout(box);
  for (int i = 0; i < 4; ++i) {
    auto* editor = new LengthEditor(QString(), false, box);
    m_lengths[static_cast<std::size_t>(i)] = editor;
    boxLayout->addWidget(editor);
    connect(editor, &LengthEditor::edited, this, [this, i](double v, bool final) { editLength(i, v, final); });
  }
  layout->addWidget(box);
  auto* pointBox = new QGroupBox(tr("Point on the coupler"), this);
  auto* pointLayout = new QVBoxLayout(pointBox);
  pointLayout->addWidget(m_hasCouplerPoint);
  pointLayout->addWidget(m_along);
  pointLayout->addWidget(m_across);
  layout->addWidget(pointBox);
  connect(m_hasCouplerPoint, &QCheckBox::toggled, this, [this] { editCouplerPoint(); });
  connect(m_along, &LengthEditor::edited, this, [this] { editCouplerPoint(); });
  connect(m_across, &LengthEditor::edited, this, [this] { editCouplerPoint(); });
}

void FourBarLengthsEditor::refresh() {
  const auto& s = m_document->fourBar();
  if (!s) return;
  const k::Mechanism& m = m_document->mechanism();
  // Named by the linkage's own points: "Crank O2–B" for makeFourBar's, whatever they are called.
  const auto name = [&m](k::PointId p) { return QString::fromStdString(m.points[p.index].name); };
  const std::array<QString, 4> labels{
      tr("Frame %1–%2").arg(name(s->o2), name(s->o4)), tr("Crank %1–%2").arg(name(s->o2), name(s->b)),
      tr("Coupler %1–%2").arg(name(s->b), name(s->c)), tr("Rocker %1–%2").arg(name(s->o4), name(s->c))};
  const std::array<double, 4> values = lengthsArray(s->lengths);
  const QString unit = QString::fromStdString(m.lengthUnit);
  for (std::size_t i = 0; i < 4; ++i) {
    m_lengths[i]->setLabel(labels[i]);
    m_lengths[i]->setUnit(unit);
    m_lengths[i]->setValue(values[i]);
  }
  const auto point = k::couplerPointOf(m, *s);
  {
    const QSignalBlocker block(m_hasCouplerPoint);
    m_hasCouplerPoint->setText(tr("Coupler point %1").arg(point ? name(point->id) : QStringLiteral("P")));
    m_hasCouplerPoint->setChecked(point.has_value());
  }
  m_along->setLabel(tr("along %1→%2").arg(name(s->b), name(s->c)));
  m_across->setLabel(tr("across (left of %1→%2)").arg(name(s->b), name(s->c)));
  m_along->setEnabled(point.has_value());
  m_across->setEnabled(point.has_value());
  m_along->setUnit(unit);
  m_across->setUnit(unit);
  if (point) {
    m_along->setValue(point->spec.along);
    m_across->setValue(point->spec.across);
  }
}

void FourBarLengthsEditor::resetSliderRanges() {
  const auto& s = m_document->fourBar();
  if (!s) return;
  const std::array<double, 4> l = lengthsArray(s->lengths);
  const double longest = *std::max_element(l.begin(), l.end());
  for (LengthEditor* e : m_lengths) e->setSliderRange(0.02 * longest, 3.0 * longest);
  m_along->setSliderRange(-2.0 * longest, 2.0 * longest);
  m_across->setSliderRange(-2.0 * longest, 2.0 * longest);
}

void FourBarLengthsEditor::editLength(int index, double value, bool final) {
  const auto& s = m_document->fourBar();
  if (!s) return;
  k::FourBarLengths lengths = s->lengths;
  std::array<double*, 4> fields{&lengths.frame, &lengths.crank, &lengths.coupler, &lengths.rocker};
  *fields[static_cast<std::size_t>(index)] = value;
  k::Design d = m_document->design();
  d.mechanism = k::withFourBarLengths(d.mechanism, *s, lengths);
  const std::array<QString, 4> what{tr("Change frame length"), tr("Change crank length"), tr("Change coupler length"),
                                    tr("Change rocker length")};
  const MergeKey key{ContinuousEdit::Length, static_cast<std::size_t>(index), m_dragSerial};
  const auto refusal = m_document->edit(d, what[static_cast<std::size_t>(index)], key);
  if (final) ++m_dragSerial;
  refresh();  // a refused value snaps back to the document's
  emit edited(refusal);
}

void FourBarLengthsEditor::editCouplerPoint() {
  const auto& s = m_document->fourBar();
  if (!s) return;
  std::optional<k::CouplerPointSpec> spec;
  if (m_hasCouplerPoint->isChecked()) {
    // A new point starts at the coupler's middle.
    const bool had = k::couplerPointOf(m_document->mechanism(), *s).has_value();
    spec = k::CouplerPointSpec{had ? m_along->value() : s->lengths.coupler / 2.0, had ? m_across->value() : 0.0};
  }
  k::Design d = m_document->design();
  auto withPoint = k::withCouplerPoint(d.mechanism, *s, spec);
  std::optional<QString> refusal;
  if (!withPoint) refusal = QString::fromStdString(withPoint.error().message);
  else {
    d.mechanism = std::move(withPoint.value());
    refusal = m_document->edit(d, tr("Change coupler point"), MergeKey{ContinuousEdit::CouplerPoint, 0, m_dragSerial});
  }
  ++m_dragSerial;
  refresh();
  emit edited(refusal);
}

}  // namespace linkwright::ui
