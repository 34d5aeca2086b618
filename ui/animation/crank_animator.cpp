#include "ui/animation/crank_animator.h"

#include "ui/document/mechanism_document.h"

#include "kinematics/model/units.h"

#include <algorithm>
#include <cmath>

namespace linkwright::ui {

namespace k = kinematics;

CrankAnimator::CrankAnimator(MechanismDocument* document, QObject* parent)
    : QObject(parent), m_document(document), m_stepAngle(k::degToRad(30.0)) {
  m_timer.setInterval(16);  // about 60 frames per second
  m_timer.setTimerType(Qt::PreciseTimer);
  connect(&m_timer, &QTimer::timeout, this, [this] {
    const double dt = static_cast<double>(m_clock.restart()) / 1000.0;
    advance(std::min(dt, 0.1));  // after a stall, resume smoothly rather than jump
  });
}

void CrankAnimator::play() {
  if (isPlaying()) return;
  m_travelled = 0.0;
  // A time base played to its end starts again from its beginning.
  if (const auto& time = m_document->design().time; time && !m_loop && m_document->time() >= time->toTime)
    m_document->setTime(time->fromTime);
  m_clock.start();
  m_timer.start();
  emit playingChanged(true);
}

void CrankAnimator::pause() {
  if (!isPlaying()) return;
  m_timer.stop();
  emit playingChanged(false);
}

void CrankAnimator::togglePlay() { isPlaying() ? pause() : play(); }

void CrankAnimator::stepForward() {
  if (m_document->onTimeBase()) m_document->setTime(m_document->time() + m_stepTime);
  else moveBy(m_stepAngle);
}

void CrankAnimator::stepBackward() {
  if (m_document->onTimeBase()) m_document->setTime(m_document->time() - m_stepTime);
  else moveBy(-m_stepAngle);
}

void CrankAnimator::advance(double dt) {
  if (m_document->onTimeBase()) {
    advanceInTime(dt);
    return;
  }
  // A crank at rest still animates, at 1 rad/s, so "play" always shows the motion.
  const double omega = m_document->design().omega;
  const double rate = omega != 0.0 ? omega : 1.0;
  moveBy(m_direction * rate * dt);
  m_travelled += std::abs(rate * dt);
  if (!m_loop && m_travelled >= 2.0 * k::kPi) pause();
}

void CrankAnimator::advanceInTime(double dt) {
  const double from = m_document->design().time->fromTime;
  const double to = m_document->design().time->toTime;
  m_direction = 1;
  double t = m_document->time() + dt;
  // Reaching the end within round-off shows the end, not the start again.
  constexpr double kRoundOff = 1e-9;
  if (t > to && t <= to + kRoundOff * std::max(1.0, to - from)) t = to;
  if (t > to) {
    if (!m_loop) {
      m_document->setTime(to);
      pause();
      return;
    }
    // Over the end: on from the start by what is left, as a clock does.
    const double span = to - from;
    t = span > 0.0 ? from + std::fmod(t - from, span) : from;
  }
  m_document->setTime(t);
}

void CrankAnimator::moveBy(double delta) {
  const k::InputRange& range = m_document->analysis().inputRange;
  const double target = m_document->crankAngle() + delta;
  if (range.fullRotation) {
    m_document->setCrankAngle(std::remainder(target, 2.0 * k::kPi));  // stay within one turn
    return;
  }
  if (range.contains(target)) {
    m_document->setCrankAngle(target);
    return;
  }
  // Past an end of the assemblable range: stop there and turn back (a rocking input).
  m_document->setCrankAngle(range.clamp(target));
  m_direction = -m_direction;
}

}  // namespace linkwright::ui
