#pragma once
// Keeps the mouse wheel for scrolling in a scroll area full of controls. A spin box, combo box
// or slider takes the wheel by default, and is given focus by it: scrolling the side panel
// changed whatever control passed under the pointer (the branch flipped, a length moved, the
// document became modified). Inside the guarded scroll area such a control takes the wheel
// only once it has focus (a click or Tab gives it); until then the wheel scrolls the area.

#include <QObject>

class QScrollArea;

namespace linkwright::ui {

class WheelGuard : public QObject {
  Q_OBJECT
public:
  /// Guards every spin box, combo box and slider inside `area`, those made later included
  /// (the dimensions editor rebuilds its fields for each linkage). Watches the application's
  /// events for as long as it lives; `area` should be its parent or outlive it.
  explicit WheelGuard(QScrollArea* area);

protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

private:
  QScrollArea* m_area;
};

}  // namespace linkwright::ui
