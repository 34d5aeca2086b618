// File ▸ Export ▸ Animation as a video, on the whole window, offscreen: the thesis
// crank-rocker's turn as an MP4 (H.264) and a WebM (VP9) reads back (libavformat) with its
// frame count, rate and duration; each decoded frame is, within the codec's loss, the canvas
// at that frame's crank angle (the designer's own screenshot of it, for a WebM at the canvas's
// size); an odd size is made even for H.264; bad settings, a full disk or a cancel keep the
// file that was there and say why.
//
// The loss bound is video_writer_test.cpp's: a mean absolute difference per channel below 1.5
// (of 255). The canvas is mostly white, its thin anti-aliased lines and small labels the hard
// case for 4:2:0 colour: measured here (FFmpeg 5.1) 0.11 to 0.21 for H.264 (480 × 360, the
// canvas centred on white) and 0.23 to 0.30 for VP9 (the canvas's size), while the canvas 90°
// on differs by 2.2 at 480 × 360.

#include "ui/canvas/linkage_view.h"
#include "ui/document/mechanism_document.h"
#include "ui/export/cycle_animation.h"
#include "ui/main_window.h"
#include "ui/message_banner.h"

#include "kinematics/model/units.h"

#include "tests/support/file_size_limit.h"
#include "tests/ui/support/read_file.h"
#include "tests/ui/support/video_readback.h"

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

constexpr double kLoss = 1.5;  // mean absolute difference per channel, see above

void writeOld(const QString& path) {
  QFile old(path);
  REQUIRE(old.open(QIODevice::WriteOnly));
  old.write("old contents");
}

}  // namespace

TEST_CASE("an MP4 of the thesis crank-rocker's turn has its frames, rate and duration, each the canvas at its angle",
          "[ui][export][animation][video]") {
  ui::MainWindow window;
  showSettled(window);
  ui::MechanismDocument& doc = *window.document();
  doc.setCrankAngle(k::degToRad(30.0));
  const ui::CycleFrames cycle = ui::cycleFrames(doc, 36);
  QTemporaryDir dir;
  ui::AnimationSettings settings;
  settings.frames = 36;
  settings.frameRate = 30.0;
  settings.size = QSize(481, 361);  // H.264 makes it 480 × 360
  REQUIRE(window.exportAnimation(dir.filePath("turn.mp4"), settings));

  const auto video = testing::readVideo(dir.filePath("turn.mp4"));
  REQUIRE(video);
  CHECK(video->codec == "h264");
  CHECK(video->width == 480);
  CHECK(video->height == 360);
  CHECK(video->packets == 36);
  REQUIRE(video->frames.size() == 36);
  CHECK(video->framesPerSecond == Approx(30.0).epsilon(1e-12));
  CHECK(video->durationSeconds == Approx(1.2).epsilon(1e-12));
  // Nothing of the document changed.
  CHECK(doc.crankAngle() == Approx(k::degToRad(30.0)).margin(1e-15));
  CHECK(doc.undoStack()->count() == 0);

  for (const std::size_t i : {std::size_t(0), std::size_t(9), std::size_t(23)}) {
    CAPTURE(i);
    doc.setCrankAngle(cycle.inputs[i]);
    const QImage rendered = ui::renderAnimationFrame(*window.canvas(), QSize(480, 360));
    const double loss = testing::meanAbsoluteDifference(video->frames[i], rendered);
    CAPTURE(loss);
    CHECK(loss < kLoss);
  }
  // The bound tells angles apart: frame 9 (90° on) is not the canvas at frame 0's angle.
  doc.setCrankAngle(cycle.inputs[0]);
  CHECK(testing::meanAbsoluteDifference(video->frames[9], ui::renderAnimationFrame(*window.canvas(), QSize(480, 360))) >
        kLoss);
}

TEST_CASE("a WebM at the canvas's size is the designer's screenshot at each frame's angle, within VP9's loss",
          "[ui][export][animation][video]") {
  ui::MainWindow window;
  showSettled(window);
  ui::MechanismDocument& doc = *window.document();
  const ui::CycleFrames cycle = ui::cycleFrames(doc, 12);
  QTemporaryDir dir;
  ui::AnimationSettings settings;
  settings.frames = 12;
  settings.frameRate = 23.976;
  REQUIRE(window.exportAnimation(dir.filePath("turn.webm"), settings));
  const auto video = testing::readVideo(dir.filePath("turn.webm"));
  REQUIRE(video);
  const QSize canvas = window.canvas()->viewport()->size();
  CHECK(video->codec == "vp9");
  CHECK(video->width == canvas.width());  // VP9 takes odd sides as they are
  CHECK(video->height == canvas.height());
  CHECK(video->packets == 12);
  REQUIRE(video->frames.size() == 12);
  CHECK(video->framesPerSecond == Approx(23.976).epsilon(1e-9));
  // The container keeps milliseconds: 12 frames of 1/23.976 s end at 500.5 ms.
  CHECK(video->durationSeconds == Approx(12 / 23.976).margin(0.001));
  for (const std::size_t i : {std::size_t(0), std::size_t(4), std::size_t(7)}) {
    CAPTURE(i);
    doc.setCrankAngle(cycle.inputs[i]);
    const QImage shown = window.canvas()->grab().toImage();
    const double loss = testing::meanAbsoluteDifference(video->frames[i], shown);
    CAPTURE(loss);
    CHECK(loss < kLoss);
  }
}

TEST_CASE("bad video settings write nothing and say why", "[ui][export][animation][video][errors]") {
  ui::MainWindow window;
  showSettled(window);
  QTemporaryDir dir;
  const QString path = dir.filePath("bad.mp4");
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
      {with([](auto& s) { s.frameRate = 0.0; }), path, "Frame rate must be 1 to 120 fps (got 0)"},
      {with([](auto& s) { s.frameRate = 120.5; }), path, "Frame rate must be 1 to 120 fps (got 120.5)"},
      {with([](auto& s) { s.frameRate = std::nan(""); }), path, "Frame rate must be 1 to 120 fps (got undefined)"},
      {with([](auto& s) { s.size = QSize(4097, 100); }), path, "Image width must be 16 to 4096 px (got 4097)"},
      {ok, dir.filePath("no-such-folder/out.webm"), "does not exist or is not writable"},
      {ok, dir.filePath("out.avi"), "use a .gif, .mp4 or .webm file name"},
  };
  for (const Case& c : cases) {
    CAPTURE(c.expected);
    CHECK_FALSE(window.exportAnimation(c.path, c.settings));
    CHECK(window.banner()->text().contains(c.expected));
    CHECK_FALSE(QFile::exists(c.path));
  }
  CHECK(QDir(dir.path()).entryList(QDir::Files).isEmpty());
}

TEST_CASE("a cancelled or failed video keeps the file that was there", "[ui][export][animation][video][errors]") {
  ui::MainWindow window;
  showSettled(window);
  QTemporaryDir dir;
  const QString path = dir.filePath("keep.mp4");
  writeOld(path);
  ui::AnimationSettings settings;
  settings.frames = 10;
  SECTION("cancelled after 3 frames") {
    const double before = window.document()->crankAngle();
    int calls = 0;
    const auto why =
        ui::exportCycleAnimation(*window.document(), *window.canvas(), path, settings, [&calls](int done, int total) {
          ++calls;
          CHECK(total == 10);
          return done < 3;
        });
    REQUIRE(why);
    CHECK(*why == "Animation export cancelled; the file that was there is unchanged.");
    CHECK(calls == 3);
    CHECK(window.document()->crankAngle() == before);
  }
  SECTION("a full disk") {
    {
      // A full disk as the writer sees it (tests/support/file_size_limit.h): smaller than the video.
      test::FileSizeLimit full(1024);
      CHECK_FALSE(window.exportAnimation(path, settings));
    }
    CAPTURE(window.banner()->text().toStdString());
    CHECK(window.banner()->text() == "Cannot write keep.mp4: File too large. The previous file, if any, is unchanged.");
  }
  CHECK(test::readAll(path) == "old contents");
  CHECK(QDir(dir.path()).entryList(QDir::Files) == QStringList{"keep.mp4"});  // no temporary file left
}
