#include "ui/undo_keys.h"

#include <QAbstractSpinBox>
#include <QApplication>
#include <QKeyEvent>
#include <QLineEdit>

namespace linkwright::ui {

UndoKeysToDocument::UndoKeysToDocument(QWidget* window) : QObject(window), m_window(window) {
  qApp->installEventFilter(this);
}

bool UndoKeysToDocument::eventFilter(QObject* watched, QEvent* event) {
  if (event->type() != QEvent::ShortcutOverride) return false;
  const auto* key = static_cast<QKeyEvent*>(event);
  if (!key->matches(QKeySequence::Undo) && !key->matches(QKeySequence::Redo)) return false;
  // The spin box has the focus and hands the event to its line edit: either may be watched.
  const auto* widget = qobject_cast<const QWidget*>(watched);
  const bool spin = qobject_cast<const QAbstractSpinBox*>(widget) != nullptr ||
                    (qobject_cast<const QLineEdit*>(widget) != nullptr &&
                     qobject_cast<const QAbstractSpinBox*>(widget->parentWidget()) != nullptr);
  if (!spin || !m_window->isAncestorOf(widget)) return false;
  // Not overridden: the key is the window's shortcut, Edit ▸ Undo or Redo.
  event->ignore();
  return true;
}

}  // namespace linkwright::ui
