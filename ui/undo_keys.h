#pragma once
// Ctrl+Z and Ctrl+Shift+Z (the platform's Undo and Redo) undo the design, even from a number
// field. A spin box's line edit takes them for its own text: after a length typed and Enter,
// Ctrl+Z put the old digits back in the field while the design kept the new length, and a
// refusal stayed under the panel. Inside `window` the keys go to Edit ▸ Undo and Redo.

#include <QObject>

class QWidget;

namespace linkwright::ui {

class UndoKeysToDocument : public QObject {
  Q_OBJECT
public:
  /// Watches the application's events for as long as `window` lives (its parent).
  explicit UndoKeysToDocument(QWidget* window);

protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

private:
  QWidget* m_window;
};

}  // namespace linkwright::ui
