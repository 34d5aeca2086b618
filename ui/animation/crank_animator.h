#pragma once
// Plays the linkage. On an angle grid it advances the document's crank angle in real time at
// the design's crank speed, steps it by a chosen angle, loops, and makes a crank that cannot
// turn fully rock between the ends of its assemblable range instead of failing there. On a
// time base it runs the law's own clock: the document's instant advances in real time from the
// time base's start to its end (the crank where the law has it, at the law's ω and α), then
// starts over, or stops there when not looping; a step moves the instant by a chosen time.

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
  /// Loop forever (default) or stop after one cycle (on a time base: at its end).
  void setLooping(bool loop) { m_loop = loop; }
  bool isLooping() const { return m_loop; }
  /// Step size for stepForward/stepBackward on an angle grid, rad (default 30°, the thesis's step).
  void setStepAngle(double angle) { m_stepAngle = angle; }
  double stepAngle() const { return m_stepAngle; }
  /// Step size for stepForward/stepBackward on a time base, s (default 0.1 s).
  void setStepTime(double seconds) { m_stepTime = seconds; }
  double stepTime() const { return m_stepTime; }
  /// +1 while the crank turns with ω, −1 while a rocking crank returns (always +1 in time).
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
  void advanceInTime(double dt);

  MechanismDocument* m_document;
  QTimer m_timer;
  QElapsedTimer m_clock;
  bool m_loop = true;
  double m_stepAngle;
  double m_stepTime = 0.1;
  double m_travelled = 0.0;  // since play(), rad: one cycle ends a non-looping play
  int m_direction = 1;
};

}  // namespace linkwright::ui
