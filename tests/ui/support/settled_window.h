#pragma once
// The designer's window as the export tests want it: shown at a fixed size, laid out, and
// every computation it started finished, so what it draws is the design's.

#include "ui/main_window.h"

#include <QApplication>

namespace linkwright::test {

inline void showSettled(ui::MainWindow& window) {
  window.resize(1400, 880);
  window.show();
  for (int i = 0; i < 5; ++i) QApplication::processEvents();
  window.settle();
  for (int i = 0; i < 5; ++i) QApplication::processEvents();
}

}  // namespace linkwright::test
