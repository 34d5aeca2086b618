#pragma once
// Widget updates a drag can make on every move without disturbing the window. Qt re-lays out
// every layout from the changed widget up to the main window whenever a child's size hint may
// have changed (QLayout::activate calls updateGeometry on its widget whatever the outcome), and
// then repaints what moved: a combo box refilled with the same items or a suffix set again
// costs a re-layout of the whole window unless these guards stop it at the source. A spin box
// repaints itself, and every child in it, on every setValue, even to the value it shows.
// Read-outs whose text changes on every move are ReadoutLabels (ui/readout_label.h).

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QSpinBox>
#include <QStringList>

namespace linkwright::ui {

/// Replaces `box`'s items only when they differ from `items` (the current index then is 0).
inline void setComboItems(QComboBox* box, const QStringList& items) {
  bool same = box->count() == items.size();
  for (int i = 0; same && i < items.size(); ++i) same = box->itemText(i) == items[i];
  if (same) return;
  box->clear();
  box->addItems(items);
}

/// Sets a spin box's suffix only when it differs (QDoubleSpinBox::setSuffix always re-lays out).
inline void setSuffixQuietly(QDoubleSpinBox* box, const QString& suffix) {
  if (box->suffix() != suffix) box->setSuffix(suffix);
}

/// Sets a spin box's value only when the number it shows changes.
inline void setValueQuietly(QDoubleSpinBox* box, double value) {
  if (box->textFromValue(value) != box->textFromValue(box->value())) box->setValue(value);
}

inline void setValueQuietly(QSpinBox* box, int value) {
  if (value != box->value()) box->setValue(value);
}

}  // namespace linkwright::ui
