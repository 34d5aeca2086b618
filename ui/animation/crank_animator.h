#pragma once
// Plays the linkage: advances the document's crank angle in real time at the design's crank
// speed, steps it by a chosen angle, loops, and makes a crank that cannot turn fully rock
// between the ends of its assemblable range instead of failing there.

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

namespace linkwright::ui {

class MechanismDocument;

class CrankAnimator : public QObject {
  Q_OBJECT
public:
  explicit CrankAnimator(MechanismDocument* document, QObject* parent = nullptr);

  bool isPlaying() const { return m_timer.isActive(); }
  /// Loop forever (default) or stop after one cycle.
  void setLooping(bool loop) { m_loop = loop; }
  bool isLooping() const { return m_loop; }
  /// Step size for stepForward/stepBackward, rad (default 30°, the thesis's step).
  void setStepAngle(double angle) { m_stepAngle = angle; }
  double stepAngle() const { return m_stepAngle; }
  /// +1 while the crank turns with ω, −1 while a rocking crank returns.
  int direction() const { return m_direction; }

public slots:
  void play();
  void pause();
  void togglePlay();
  void stepForward();
  void stepBackward();
  /// Advances by `dt` seconds of motion (the timer calls it; tests call it directly).
  void advance(double dt);

signals:
  void playingChanged(bool playing);

private:
  void moveBy(double delta);

  MechanismDocument* m_document;
  QTimer m_timer;
  QElapsedTimer m_clock;
  bool m_loop = true;
  double m_stepAngle;
  double m_travelled = 0.0;  // since play(), rad: one cycle ends a non-looping play
  int m_direction = 1;
};

}  // namespace linkwright::ui
