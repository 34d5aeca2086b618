// File ▸ Export ▸ Animation on the whole window, offscreen: the thesis crank-rocker at 36
// frames reads back (giflib) with 36 frames of the canvas's size, the delay and the loop; the
// linkage moves between frames; the first frame is the canvas as shown at the start angle;
// the crank angle comes back and the undo stack stays empty. The cycle's inputs follow the
// animator (a turn, a rocking range there and back, a time base). Bad settings, a bad path, a
// full disk or a cancel write nothing and say why.

#include "ui/export/cycle_animation.h"
#include "ui/canvas/linkage_view.h"
#include "ui/document/mechanism_document.h"
#include "ui/main_window.h"
#include "ui/message_banner.h"

#include "kinematics/model/units.h"

#include "tests/support/file_size_limit.h"
#include "tests/ui/support/four_bar_design.h"
#include "tests/ui/support/gif_readback.h"
#include "tests/ui/support/read_file.h"
#include "tests/ui/support/timed_design.h"

#include "tests/support/catch.h"
#include "tests/ui/support/settled_window.h"

#include <QApplication>
#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QUndoStack>

using namespace linkwright;
namespace k = linkwright::kinematics;

using linkwright::test::showSettled;

namespace {

// Non-Grashof (60 + 100 > 70 + 80): the crank rocks between two toggle angles.
const k::FourBarLengths kTripleRocker{100.0, 80.0, 60.0, 70.0};

}  // namespace

TEST_CASE("the thesis crank-rocker's animation has 36 frames of the canvas, its delay and its loop",
          "[ui][export][animation]") {
  ui::MainWindow window;
  showSettled(window);
  window.document()->setCrankAngle(k::degToRad(30.0));
  const QImage shown = window.canvas()->grab().toImage().convertToFormat(QImage::Format_RGB888);
  QTemporaryDir dir;
  ui::AnimationSettings settings;
  settings.frames = 36;
  settings.frameDelayMs = 50;
  REQUIRE(window.exportAnimation(dir.filePath("cycle.gif"), settings));

  const auto gif = testing::readGif(dir.filePath("cycle.gif"));
  REQUIRE(gif);
  const QSize canvas = window.canvas()->viewport()->size();
  CHECK(gif->width == canvas.width());
  CHECK(gif->height == canvas.height());
  REQUIRE(gif->frames.size() == 36);
  CHECK(gif->delayCentiseconds == std::vector<int>(36, 5));
  CHECK(gif->loopsForever);
  // The linkage moves: every frame differs from the one before, and from the first.
  for (std::size_t i = 1; i < gif->frames.size(); ++i) {
    CAPTURE(i);
    CHECK(testing::differingPixels(gif->frames[i], gif->frames[i - 1], 16) > 50);
  }
  // The first frame is the canvas at the start angle; 256 colours blur only anti-aliased edges.
  REQUIRE(shown.size() == gif->frames[0].size());
  const long pixels = long(shown.width()) * shown.height();
  CHECK(testing::differingPixels(gif->frames[0], shown, 24) < pixels / 500);
  CHECK(testing::differingPixels(gif->frames[18], shown, 24) > pixels / 500);
  // Nothing of the document changed.
  CHECK(window.document()->crankAngle() == Approx(k::degToRad(30.0)).margin(1e-15));
  CHECK(window.document()->undoStack()->count() == 0);
  CHECK_FALSE(window.document()->isModified());
}

TEST_CASE("a chosen image size scales the canvas into it", "[ui][export][animation]") {
  ui::MainWindow window;
  showSettled(window);
  QTemporaryDir dir;
  ui::AnimationSettings settings;
  settings.frames = 4;
  settings.size = QSize(320, 200);
  settings.loopForever = false;
  REQUIRE(window.exportAnimation(dir.filePath("small.gif"), settings));
  const auto gif = testing::readGif(dir.filePath("small.gif"));
  REQUIRE(gif);
  CHECK(gif->width == 320);
  CHECK(gif->height == 200);
  CHECK(gif->frames.size() == 4);
  CHECK_FALSE(gif->loopsForever);
}

TEST_CASE("a cycle's inputs follow the animator: a turn, a rocking range, a time base", "[ui][export][animation]") {
  ui::MechanismDocument doc;
  SECTION("a crank that turns fully makes one turn from the angle shown") {
    doc.reset(testing::fourBar());
    doc.setCrankAngle(k::degToRad(30.0));
    const ui::CycleFrames cycle = ui::cycleFrames(doc, 36);
    CHECK_FALSE(cycle.inTime);
    CHECK_FALSE(cycle.rocking);
    REQUIRE(cycle.inputs.size() == 36);
    for (std::size_t i = 0; i < 36; ++i) {
      CAPTURE(i);
      CHECK(std::remainder(cycle.inputs[i] - k::degToRad(30.0 + 10.0 * double(i)), 2.0 * k::kPi) ==
            Approx(0.0).margin(1e-12));
    }
  }
  SECTION("a crank that cannot turn fully goes to each end of its range and back") {
    doc.reset(testing::fourBar(kTripleRocker));
    const k::InputRange& range = doc.analysis().inputRange;
    REQUIRE_FALSE(range.fullRotation);
    REQUIRE(range.ranges.size() == 1);
    const ui::CycleFrames cycle = ui::cycleFrames(doc, 40);
    CHECK(cycle.rocking);
    REQUIRE(cycle.inputs.size() == 40);
    CHECK(cycle.inputs[0] == Approx(doc.crankAngle()).margin(1e-12));
    const auto [low, high] = std::minmax_element(cycle.inputs.begin(), cycle.inputs.end());
    const double span = range.ranges[0].to - range.ranges[0].from;
    const double step = 2.0 * span / 40.0;
    CHECK(*low >= range.ranges[0].from - 1e-12);
    CHECK(*high <= range.ranges[0].to + 1e-12);
    CHECK(*low < range.ranges[0].from + step);
    CHECK(*high > range.ranges[0].to - step);
    for (std::size_t i = 1; i < 40; ++i) CHECK(std::abs(cycle.inputs[i] - cycle.inputs[i - 1]) <= step + 1e-12);
  }
  SECTION("a time base runs from its start to its end") {
    doc.reset(testing::cycloidalFourBar());
    const ui::CycleFrames cycle = ui::cycleFrames(doc, 10);
    CHECK(cycle.inTime);
    REQUIRE(cycle.inputs.size() == 10);
    for (std::size_t i = 0; i < 10; ++i) CHECK(cycle.inputs[i] == Approx(testing::kRiseDuration * double(i) / 10.0));
  }
}

TEST_CASE("a rocking crank's animation writes its frames and puts the crank back", "[ui][export][animation]") {
  ui::MainWindow window;
  window.newDocument(testing::fourBar(kTripleRocker));
  showSettled(window);
  const double before = window.document()->crankAngle();
  QTemporaryDir dir;
  ui::AnimationSettings settings;
  settings.frames = 12;
  REQUIRE(window.exportAnimation(dir.filePath("rocking.gif"), settings));
  const auto gif = testing::readGif(dir.filePath("rocking.gif"));
  REQUIRE(gif);
  CHECK(gif->frames.size() == 12);
  CHECK(window.document()->crankAngle() == before);
}

TEST_CASE("bad animation settings or paths write nothing and say why", "[ui][export][animation][errors]") {
  ui::MainWindow window;
  showSettled(window);
  QTemporaryDir dir;
  const QString path = dir.filePath("bad.gif");
  struct Case {
    ui::AnimationSettings settings;
    QString path;
    QString expected;
  };
  ui::AnimationSettings ok;
  ok.frames = 3;
  auto with = [ok](auto change) {
    ui::AnimationSettings s = ok;
    change(s);
    return s;
  };
  const std::vector<Case> cases{
      {with([](auto& s) { s.frames = 0; }), path, "Frames per cycle must be 2 to 720 (got 0)"},
      {with([](auto& s) { s.frames = 721; }), path, "Frames per cycle must be 2 to 720 (got 721)"},
      {with([](auto& s) { s.frameDelayMs = 10; }), path, "Frame delay must be 20 to 5000 ms (got 10)"},
      {with([](auto& s) { s.size = QSize(8, 100); }), path, "Image width must be 16 to 4096 px (got 8)"},
      {ok, dir.filePath("no-such-folder/out.gif"), "does not exist or is not writable"},
      {ok, dir.filePath("out.png"), "use a .gif, .mp4 or .webm file name"},
  };
  for (const Case& c : cases) {
    CAPTURE(c.expected);
    CHECK_FALSE(window.exportAnimation(c.path, c.settings));
    CHECK(window.banner()->text().contains(c.expected));
    CHECK_FALSE(QFile::exists(c.path));
  }
  CHECK(QDir(dir.path()).entryList(QDir::Files).isEmpty());
}

TEST_CASE("a cancelled animation leaves the file that was there", "[ui][export][animation][errors]") {
  ui::MainWindow window;
  showSettled(window);
  QTemporaryDir dir;
  const QString path = dir.filePath("keep.gif");
  {
    QFile old(path);
    REQUIRE(old.open(QIODevice::WriteOnly));
    old.write("old contents");
  }
  const double before = window.document()->crankAngle();
  ui::AnimationSettings settings;
  settings.frames = 10;
  int calls = 0;
  const auto why =
      ui::exportCycleAnimation(*window.document(), *window.canvas(), path, settings, [&calls](int done, int total) {
        ++calls;
        CHECK(total == 10);
        return done < 3;
      });
  REQUIRE(why);
  CHECK(why->contains("cancelled"));
  CHECK(calls == 3);
  CHECK(test::readAll(path) == "old contents");
  CHECK(window.document()->crankAngle() == before);
}

TEST_CASE("an animation on a full disk keeps the file that was there and says why", "[ui][export][animation][errors]") {
  ui::MainWindow window;
  showSettled(window);
  QTemporaryDir dir;
  const QString path = dir.filePath("full.gif");
  {
    QFile old(path);
    REQUIRE(old.open(QIODevice::WriteOnly));
    old.write("old contents");
  }
  ui::AnimationSettings settings;
  settings.frames = 4;
  {
    // A full disk as the writer sees it (tests/support/file_size_limit.h): smaller than any GIF.
    test::FileSizeLimit full(1024);
    CHECK_FALSE(window.exportAnimation(path, settings));
  }
  // It said "Unknown error".
  CHECK(window.banner()->text() == "Cannot write full.gif: File too large. The previous file, if any, is unchanged.");
  CHECK(test::readAll(path) == "old contents");
  CHECK(QDir(dir.path()).entryList(QDir::Files) == QStringList{"full.gif"});  // no temporary file left
}
