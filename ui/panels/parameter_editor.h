#pragma once
// One number of a design (a length, an offset, a coordinate or an angle) as a spin box for
// exact values and a slider for quick changes, with its unit. Emits edited() while the user
// changes it; setValue() updates it silently.

#include <QWidget>

class QDoubleSpinBox;
class QSlider;
class QLabel;

namespace linkwright::ui {

class ParameterEditor : public QWidget {
  Q_OBJECT
public:
  explicit ParameterEditor(const QString& label, QWidget* parent = nullptr);

  double value() const;
  /// Shows `value` without emitting edited().
  void setValue(double value);
  void setLabel(const QString& label);
  /// What the spin box accepts and the unit after its number (" mm", "°").
  void setRange(double minimum, double maximum);
  void setSuffix(const QString& suffix);
  /// The slider spans [low, high]; the spin box accepts its whole range.
  void setSliderRange(double low, double high);
  QDoubleSpinBox* spinBox() const { return m_spin; }
  QSlider* slider() const { return m_slider; }

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
