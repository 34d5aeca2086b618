#include "ui/panels/lengths_panel.h"

#include "ui/document/edit_design_command.h"
#include "ui/document/mechanism_document.h"
#include "ui/panels/length_editor.h"

#include <QCheckBox>
#include <QGroupBox>
#include <QLabel>
#include <QVBoxLayout>

#include <algorithm>

namespace linkwright::ui {

namespace k = kinematics;

LengthsPanel::LengthsPanel(MechanismDocument* document, QWidget* parent)
    : QWidget(parent), m_document(document), m_hasCouplerPoint(new QCheckBox(tr("Coupler point P"), this)),
      m_along(new LengthEditor(tr("along B→C"), true, this)),
      m_across(new LengthEditor(tr("across (left of B→C)"), true, this)), m_message(new QLabel(this)) {
  auto* layout = new QVBoxLayout(this);
  auto* box = new QGroupBox(tr("Link lengths"), this);
  auto* boxLayout = new QVBoxLayout(box);
  const std::array<QString, 4> names{tr("Frame O2–O4"), tr("Crank O2–B"), tr("Coupler B–C"), tr("Rocker O4–C")};
  for (int i = 0; i < 4; ++i) {
    auto* editor = new LengthEditor(names[static_cast<std::size_t>(i)], false, box);
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
  m_message->setWordWrap(true);
  m_message->setStyleSheet("color: #b00020;");
  m_message->hide();
  layout->addWidget(m_message);
  layout->addStretch();
  connect(m_hasCouplerPoint, &QCheckBox::toggled, this, [this] { editCouplerPoint(); });
  connect(m_along, &LengthEditor::edited, this, [this] { editCouplerPoint(); });
  connect(m_across, &LengthEditor::edited, this, [this] { editCouplerPoint(); });
  connect(document, &MechanismDocument::changed, this, [this](Changes what) {
    const bool fourBar = m_document->fourBar() != nullptr;
    // Back to a four-bar (undo after attaching a dyad): its sliders need ranges again.
    if ((what & Change::Design) && fourBar && !m_hadFourBar) resetSliderRanges();
    if (what & Change::Design) refresh();
    if ((what & Change::File) && m_document->undoStack()->count() == 0) resetSliderRanges();
    m_hadFourBar = fourBar;
  });
  m_hadFourBar = m_document->fourBar() != nullptr;
  resetSliderRanges();
  refresh();
}

QString LengthsPanel::refusalMessage() const { return m_message->isVisible() ? m_message->text() : QString(); }

void LengthsPanel::refresh() {
  if (m_document->fourBar() == nullptr) return;  // hidden: the dimensions panel edits other linkages
  const k::FourBarDesign& d = *m_document->fourBar();
  const std::array<double, 4> values{d.lengths.frame, d.lengths.crank, d.lengths.coupler, d.lengths.rocker};
  const QString unit = QString::fromStdString(d.lengthUnit);
  for (std::size_t i = 0; i < 4; ++i) {
    m_lengths[i]->setUnit(unit);
    m_lengths[i]->setValue(values[i]);
  }
  const bool hasPoint = d.couplerPoint.has_value();
  {
    const QSignalBlocker block(m_hasCouplerPoint);
    m_hasCouplerPoint->setChecked(hasPoint);
  }
  m_along->setEnabled(hasPoint);
  m_across->setEnabled(hasPoint);
  m_along->setUnit(unit);
  m_across->setUnit(unit);
  if (hasPoint) {
    m_along->setValue(d.couplerPoint->along);
    m_across->setValue(d.couplerPoint->across);
  }
}

// Sliders span a fixed range per document so they do not jump while in use.
void LengthsPanel::resetSliderRanges() {
  if (m_document->fourBar() == nullptr) return;
  const k::FourBarLengths& l = m_document->fourBar()->lengths;
  const double longest = std::max({l.frame, l.crank, l.coupler, l.rocker});
  for (LengthEditor* e : m_lengths) e->setSliderRange(0.02 * longest, 3.0 * longest);
  m_along->setSliderRange(-2.0 * longest, 2.0 * longest);
  m_across->setSliderRange(-2.0 * longest, 2.0 * longest);
}

void LengthsPanel::editLength(int index, double value, bool final) {
  if (m_document->fourBar() == nullptr) return;
  k::FourBarDesign d = *m_document->fourBar();
  std::array<double*, 4> fields{&d.lengths.frame, &d.lengths.crank, &d.lengths.coupler, &d.lengths.rocker};
  *fields[static_cast<std::size_t>(index)] = value;
  const std::array<QString, 4> what{tr("Change frame length"), tr("Change crank length"), tr("Change coupler length"),
                                    tr("Change rocker length")};
  const MergeKey key{ContinuousEdit::Length, static_cast<std::size_t>(index), m_dragSerial};
  if (auto why = m_document->edit(d, what[static_cast<std::size_t>(index)], key)) showRefusal(*why);
  else m_message->hide();
  if (final) ++m_dragSerial;
  refresh();  // a refused value snaps back to the document's
}

void LengthsPanel::editCouplerPoint() {
  if (m_document->fourBar() == nullptr) return;
  k::FourBarDesign d = *m_document->fourBar();
  if (m_hasCouplerPoint->isChecked()) {
    // A new point starts at the coupler's middle.
    const double along = d.couplerPoint ? m_along->value() : d.lengths.coupler / 2.0;
    const double across = d.couplerPoint ? m_across->value() : 0.0;
    d.couplerPoint = k::CouplerPointSpec{along, across};
  } else {
    d.couplerPoint.reset();
  }
  if (auto why =
          m_document->edit(d, tr("Change coupler point"), MergeKey{ContinuousEdit::CouplerPoint, 0, m_dragSerial}))
    showRefusal(*why);
  else m_message->hide();
  ++m_dragSerial;
  refresh();
}

void LengthsPanel::showRefusal(const QString& reason) {
  m_message->setText(tr("Not applied: %1").arg(reason));
  m_message->show();
}

}  // namespace linkwright::ui
