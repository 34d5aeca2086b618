#include "ui/panels/parameter_editor.h"

#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSlider>
#include "ui/number_box.h"
#include "ui/quiet_update.h"

#include <algorithm>
#include <cmath>

namespace linkwright::ui {
namespace {
constexpr int kSliderSteps = 1000;
}

ParameterEditor::ParameterEditor(const QString& label, QWidget* parent)
    : QWidget(parent), m_label(new QLabel(label, this)), m_spin(new NumberBox(this)),
      m_slider(new QSlider(Qt::Horizontal, this)) {
  auto* layout = new QGridLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  m_label->setBuddy(m_spin);
  layout->addWidget(m_label, 0, 0);
  layout->addWidget(m_spin, 0, 1);
  layout->addWidget(m_slider, 1, 0, 1, 2);
  layout->setColumnStretch(1, 1);
  layout->setVerticalSpacing(0);
  m_spin->setDecimals(4);
  m_spin->setKeyboardTracking(false);  // typed numbers apply on Enter or focus out, not per digit
  m_spin->setAccelerated(true);
  m_slider->setRange(0, kSliderSteps);
  connect(m_spin, &QDoubleSpinBox::valueChanged, this, [this](double v) {
    if (m_updating) return;
    syncSlider();
    emit edited(v, true);
  });
  connect(m_slider, &QSlider::valueChanged, this, [this](int position) {
    if (m_updating) return;
    const double v = m_low + (m_high - m_low) * position / kSliderSteps;
    {
      const QSignalBlocker block(m_spin);
      m_spin->setValue(v);
    }
    emit edited(m_spin->value(), !m_slider->isSliderDown());
  });
  connect(m_slider, &QSlider::sliderReleased, this, [this] { emit edited(m_spin->value(), true); });
}

double ParameterEditor::value() const { return m_spin->value(); }

void ParameterEditor::setValue(double value) {
  m_updating = true;
  setValueQuietly(m_spin, value);
  syncSlider();
  m_updating = false;
}

void ParameterEditor::setLabel(const QString& label) { m_label->setText(label); }

void ParameterEditor::setSuffix(const QString& suffix) { setSuffixQuietly(m_spin, suffix); }

void ParameterEditor::setRange(double minimum, double maximum) {
  const QSignalBlocker block(m_spin);
  m_spin->setRange(minimum, maximum);
}

void ParameterEditor::setSliderRange(double low, double high) {
  m_low = low;
  m_high = std::max(high, low + 1e-9);
  const bool was = m_updating;
  m_updating = true;
  syncSlider();
  m_updating = was;
}

void ParameterEditor::syncSlider() {
  const QSignalBlocker block(m_slider);
  const double t = (m_spin->value() - m_low) / (m_high - m_low);
  m_slider->setValue(static_cast<int>(std::lround(std::clamp(t, 0.0, 1.0) * kSliderSteps)));
}

}  // namespace linkwright::ui
