// Catch2 runner for the GUI tests: a QApplication on the offscreen platform unless the caller
// chose another (QT_QPA_PLATFORM=xcb under Xvfb, say). Built with LINKWRIGHT_TEST_SCREENS (the
// journeys), the offscreen platform has the screens that file lists: a 1366×768 laptop first,
// a 1024×768 projector beside it.
#define CATCH_CONFIG_RUNNER
#include "tests/support/catch.h"

#include <QApplication>

int main(int argc, char** argv) {
#ifdef LINKWRIGHT_TEST_SCREENS
  if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
    qputenv("QT_QPA_PLATFORM", "offscreen:configfile=" LINKWRIGHT_TEST_SCREENS);
#endif
  if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
  QApplication app(argc, argv);
  QApplication::setOrganizationName("LinkwrightTests");  // keeps QSettings away from the user's
  QApplication::setApplicationName("linkwright-tests");
  return Catch::Session().run(argc, argv);
}
