// Catch2 runner for the GUI tests: a QApplication on the offscreen platform unless the caller
// chose another (QT_QPA_PLATFORM=xcb under Xvfb, say).
#define CATCH_CONFIG_RUNNER
#include "tests/support/catch.h"

#include <QApplication>

int main(int argc, char** argv) {
  if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
  QApplication app(argc, argv);
  QApplication::setOrganizationName("LinkwrightTests");  // keeps QSettings away from the user's
  QApplication::setApplicationName("linkwright-tests");
  return Catch::Session().run(argc, argv);
}
