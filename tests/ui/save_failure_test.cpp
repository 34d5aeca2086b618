// Saves lose nothing: a full disk, a read-only file system and a folder that vanished each
// leave the previous file as it was, keep the document marked modified under its old path,
// and tell the user which file could not be written and why. Tests run as root in CI, where
// permission bits do not stop a write, so the failures are real ones: a file-size limit
// (tests/support/file_size_limit.h: a full disk as a writer sees it), /proc (no new files
// can be made there), and a folder removed before the save.

#include "ui/document/document_file.h"
#include "ui/document/mechanism_document.h"
#include "ui/main_window.h"
#include "ui/message_banner.h"

#include "kinematics/design/design.h"
#include "tests/support/file_size_limit.h"

#include "tests/ui/support/read_file.h"

#include "tests/ui/support/four_bar_design.h"

#include "tests/support/catch.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>

using namespace linkwright;
using test::readAll;

namespace {

// A window whose document was saved to `path` and then edited, so a save has work to do.
void saveThenEdit(ui::MainWindow& window, const QString& path) {
  REQUIRE(window.saveTo(path));
  const auto d = testing::withLengths(window.document()->design(), {60.0, 22.0, 70.0, 45.0});
  REQUIRE_FALSE(window.document()->edit(d, "test").has_value());
  REQUIRE(window.document()->isModified());
}

}  // namespace

TEST_CASE("a save to a full disk keeps the previous file and says why", "[ui][window][file][errors]") {
  QTemporaryDir dir;
  const QString path = dir.filePath("crank-rocker.linkwright");
  ui::MainWindow window;
  saveThenEdit(window, path);
  const QByteArray before = readAll(path);
  const QString savedPath = window.document()->filePath();
  {
    // Smaller than any document: the write of the new version fails part-way.
    test::FileSizeLimit full(64);
    CHECK_FALSE(window.saveTo(path));
  }
  CHECK(readAll(path) == before);
  CHECK(QDir(dir.path()).entryList(QDir::Files) == QStringList{"crank-rocker.linkwright"});  // no stray temp file
  CHECK(window.document()->isModified());
  CHECK(window.document()->filePath() == savedPath);
  const QString message = window.banner()->text();
  CHECK(message.contains("Cannot write crank-rocker.linkwright"));
  CHECK(message.contains("previous file"));
  // Once there is room again the same save succeeds.
  CHECK(window.saveTo(path));
  CHECK(readAll(path) != before);
}

TEST_CASE("a save to a read-only file system is refused with the reason", "[ui][window][file][errors]") {
  if (!QFileInfo::exists("/proc/self")) {
    WARN("no /proc here: nothing read-only to write to");
    return;
  }
  ui::MainWindow window;
  const auto d = testing::withLengths(window.document()->design(), {60.0, 23.0, 70.0, 45.0});
  REQUIRE_FALSE(window.document()->edit(d, "test").has_value());
  CHECK_FALSE(window.saveTo("/proc/linkwright-save-test.linkwright"));
  CHECK_FALSE(QFileInfo::exists("/proc/linkwright-save-test.linkwright"));
  CHECK(window.document()->isModified());
  CHECK(window.document()->filePath().isEmpty());
  CHECK(window.banner()->text().startsWith("Cannot write linkwright-save-test.linkwright: "));
}

TEST_CASE("a save into a folder that vanished keeps the document and says why", "[ui][window][file][errors]") {
  QTemporaryDir dir;
  REQUIRE(QDir(dir.path()).mkdir("project"));
  const QString path = dir.filePath("project/arm.linkwright");
  ui::MainWindow window;
  saveThenEdit(window, path);
  REQUIRE(QDir(dir.filePath("project")).removeRecursively());
  CHECK_FALSE(window.saveTo(path));
  CHECK(window.document()->isModified());
  CHECK(window.document()->filePath() == QFileInfo(path).absoluteFilePath());
  CHECK(window.banner()->text().startsWith("Cannot write arm.linkwright: "));
  CHECK_FALSE(QFileInfo::exists(dir.filePath("project")));
}
