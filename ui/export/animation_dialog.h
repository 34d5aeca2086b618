#pragma once
// File ▸ Export ▸ Animation…: asks the format (an animated GIF, an MP4 or a WebM video), the
// frames per cycle, the time each GIF frame shows or the video's frame rate, the image size
// (pre-filled with the canvas's; a note says when H.264 makes an odd side one pixel less) and
// whether the GIF loops. A video format whose FFmpeg encoder is absent is listed, disabled,
// with the reason as its tooltip. The boxes' ranges are AnimationSettings' (cycle_animation.h),
// which the export checks again.

#include "ui/export/cycle_animation.h"

#include <QDialog>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
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
  AnimationFormat format() const;
  /// The file dialog's filter for format() ("MP4 video, H.264 (*.mp4)") and its suffix ("mp4").
  QString fileFilter() const;
  QString suffix() const;

  QComboBox* formatBox() const { return m_format; }
  QSpinBox* framesBox() const { return m_frames; }
  QSpinBox* delayBox() const { return m_delay; }
  QDoubleSpinBox* rateBox() const { return m_rate; }
  QSpinBox* widthBox() const { return m_width; }
  QSpinBox* heightBox() const { return m_height; }
  QLabel* sizeNote() const { return m_sizeNote; }

private:
  void updateFormat();
  void updateDuration();

  QFormLayout* m_form;
  QComboBox* m_format;
  QSpinBox* m_frames;
  QSpinBox* m_delay;
  QDoubleSpinBox* m_rate;
  QSpinBox* m_width;
  QSpinBox* m_height;
  QCheckBox* m_loop;
  QLabel* m_duration;
  QLabel* m_sizeNote;
};

}  // namespace linkwright::ui
