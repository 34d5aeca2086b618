#pragma once
// Drive and motion controls: crank speed (rpm or rad/s) and acceleration, a four-bar's assembly branch,
// play / pause, step forward and back by a chosen angle, loop, and the crank angle itself.

#include <QWidget>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QLabel;
class QPushButton;
class QSlider;

namespace linkwright::ui {

class CrankAnimator;
class MechanismDocument;
class Settings;

class MotionPanel : public QWidget {
  Q_OBJECT
public:
  MotionPanel(MechanismDocument* document, CrankAnimator* animator, Settings* settings, QWidget* parent = nullptr);

  QPushButton* playButton() const { return m_play; }
  QComboBox* branchBox() const { return m_branch; }
  QDoubleSpinBox* speedBox() const { return m_speed; }

private:
  void refreshDesign();
  void refreshMotion();
  void editSpeed();
  void editAlpha();
  void editBranch();

  MechanismDocument* m_document;
  CrankAnimator* m_animator;
  Settings* m_settings;
  QDoubleSpinBox* m_speed;
  QComboBox* m_speedUnit;
  QFormLayout* m_driveForm = nullptr;
  QDoubleSpinBox* m_alpha;
  QComboBox* m_branch;
  QPushButton* m_play;
  QPushButton* m_back;
  QPushButton* m_forward;
  QDoubleSpinBox* m_step;
  QCheckBox* m_loop;
  QSlider* m_angle;
  QLabel* m_angleText;
  int m_editSerial = 0;
};

}  // namespace linkwright::ui
