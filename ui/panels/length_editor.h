#pragma once
// One length (or offset) as a spin box for exact values and a slider for quick changes, with
// its unit. Emits edited() while the user changes it; setValue() updates it silently.

#include <QWidget>

class QDoubleSpinBox;
class QSlider;
class QLabel;

namespace linkwright::ui {

class LengthEditor : public QWidget {
  Q_OBJECT
public:
  /// `allowNonPositive`: offsets (coupler point) may be zero or negative; lengths may not.
  LengthEditor(const QString& label, bool allowNonPositive, QWidget* parent = nullptr);

  double value() const;
  /// Shows `value` without emitting edited().
  void setValue(double value);
  void setUnit(const QString& unit);
  void setLabel(const QString& label);
  /// The slider spans [low, high]; the spin box accepts anything valid.
  void setSliderRange(double low, double high);

signals:
  /// `final` is false while a slider is being dragged, true when the edit is complete.
  void edited(double value, bool final);

private:
  void syncSlider();

  QLabel* m_label;
  QDoubleSpinBox* m_spin;
  QSlider* m_slider;
  double m_low = 0.0;
  double m_high = 100.0;
  bool m_updating = false;
};

}  // namespace linkwright::ui
