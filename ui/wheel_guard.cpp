#include "ui/wheel_guard.h"

#include <QAbstractSlider>
#include <QAbstractSpinBox>
#include <QApplication>
#include <QComboBox>
#include <QEvent>
#include <QScrollArea>

namespace linkwright::ui {
namespace {

bool takesTheWheel(const QObject* object) {
  return qobject_cast<const QAbstractSpinBox*>(object) != nullptr ||
         qobject_cast<const QComboBox*>(object) != nullptr || qobject_cast<const QAbstractSlider*>(object) != nullptr;
}

}  // namespace

WheelGuard::WheelGuard(QScrollArea* area) : QObject(area), m_area(area) { qApp->installEventFilter(this); }

bool WheelGuard::eventFilter(QObject* watched, QEvent* event) {
  const QEvent::Type type = event->type();
  if (type != QEvent::Show && type != QEvent::Wheel) return false;
  if (!takesTheWheel(watched)) return false;
  auto* control = static_cast<QWidget*>(watched);
  // The area's own scroll bars keep the wheel; only the controls in its widget are guarded.
  if (m_area->widget() == nullptr || !m_area->widget()->isAncestorOf(control)) return false;
  if (type == QEvent::Show) {
    // Qt gives a WheelFocus control focus on the wheel before any filter sees the event, so
    // the wheel must not be a way in: a click or Tab focuses it. A control is shown before
    // it can be under the pointer, wherever it was made and polished.
    if (control->focusPolicy() == Qt::WheelFocus) control->setFocusPolicy(Qt::StrongFocus);
    return false;
  }
  if (control->hasFocus()) return false;
  // Not accepted, so QApplication offers the wheel to the parents: the scroll area scrolls.
  event->ignore();
  return true;
}

}  // namespace linkwright::ui
