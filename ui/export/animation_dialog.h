#pragma once
// File ▸ Export ▸ Animation…: asks the frames per cycle, the time each frame shows, the image
// size (pre-filled with the canvas's) and whether the GIF loops. The boxes' ranges are
// AnimationSettings' (cycle_animation.h), which the export checks again.

#include "ui/export/cycle_animation.h"

#include <QDialog>

class QCheckBox;
class QLabel;
class QSpinBox;

namespace linkwright::ui {

class AnimationDialog : public QDialog {
  Q_OBJECT
public:
  /// `canvasSize` pre-fills the image size; `cycle` says what one cycle is ("one turn of the crank").
  AnimationDialog(const QSize& canvasSize, const QString& cycle, QWidget* parent = nullptr);

  /// What the user chose.
  AnimationSettings settings() const;

  QSpinBox* framesBox() const { return m_frames; }
  QSpinBox* delayBox() const { return m_delay; }

private:
  void updateDuration();

  QSpinBox* m_frames;
  QSpinBox* m_delay;
  QSpinBox* m_width;
  QSpinBox* m_height;
  QCheckBox* m_loop;
  QLabel* m_duration;
};

}  // namespace linkwright::ui
