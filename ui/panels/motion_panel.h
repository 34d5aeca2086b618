#pragma once
// Motion controls in one row (the window's Motion bar): a four-bar's assembly branch, play /
// pause, step forward and back by a chosen angle (on a time base, a chosen time), loop, and the
// crank angle itself (on a time base, the instant). How the crank is driven (ω, α or a motion law) is the drive panel's.

#include <QWidget>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSlider;

namespace linkwright::ui {

class CrankAnimator;
class MechanismDocument;
class ReadoutLabel;

class MotionPanel : public QWidget {
  Q_OBJECT
public:
  MotionPanel(MechanismDocument* document, CrankAnimator* animator, QWidget* parent = nullptr);

  QPushButton* playButton() const { return m_play; }
  QComboBox* branchBox() const { return m_branch; }
  /// The crank angle (tenths of a degree); a linear input over its grid, or on a time base the
  /// instant (thousandths of the span).
  QSlider* positionSlider() const { return m_position; }
  QDoubleSpinBox* stepBox() const { return m_step; }
  /// "Crank angle θ₂ = 30.0°", "actuator A–C length = 1.5 m", or on a time base
  /// "t = 0.250 s · crank angle θ₂ = 45.0°".
  QString positionText() const;

  /// Slider steps across a time base or a linear input's grid.
  static constexpr int kTimeSliderSteps = 1000;

private:
  void refreshDesign();
  void refreshMotion();
  void editBranch();
  void onSlider(int value);
  void onStep(double value);

  MechanismDocument* m_document;
  CrankAnimator* m_animator;
  QComboBox* m_branch;
  QPushButton* m_play;
  QPushButton* m_back;
  QPushButton* m_forward;
  QDoubleSpinBox* m_step;
  QCheckBox* m_loop;
  QSlider* m_position;
  ReadoutLabel* m_positionText;
  QLabel* m_branchLabel;
  // What the slider and the step box are showing: a crank's angle (degrees), a linear input
  // over its grid (its length unit), or the time base's instants (s).
  enum class Scale { CrankAngle, LinearInput, Time };
  Scale m_scale = Scale::CrankAngle;
  double m_span = 0.0;  // the time base's or linear grid's span the step was chosen for
};

}  // namespace linkwright::ui
