// `linkwright --example NAME --animation FILE.gif --frames N` (and FILE.mp4, FILE.webm with
// --frame-rate and --animation-size), the designer run headless as a user runs it: the GIF it
// writes reads back (giflib) with N frames, the video (libavformat) with N frames at its rate;
// bad values exit with the option named and write nothing. `linkwright --image FILE.pdf` writes
// the canvas, or one plot, as a PDF.

#include "tests/ui/support/gif_readback.h"
#include "tests/ui/support/video_readback.h"

#include "tests/support/catch.h"

#include <QFile>
#include <QProcess>
#include <QProcessEnvironment>
#include <QTemporaryDir>

using namespace linkwright;

namespace {

struct Run {
  int exitCode = -1;
  QString err;
};

Run designer(const QStringList& arguments) {
  QProcess process;
  QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
  env.insert("QT_QPA_PLATFORM", "offscreen");
  process.setProcessEnvironment(env);
  process.start(LINKWRIGHT_DESIGNER, arguments);
  process.waitForFinished(-1);
  return {process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1,
          QString::fromUtf8(process.readAllStandardError())};
}

}  // namespace

TEST_CASE("linkwright --animation writes the thesis crank-rocker's turn in 36 frames", "[ui][export][animation][app]") {
  QTemporaryDir dir;
  const QString path = dir.filePath("thesis.gif");
  const Run run = designer({"--example", "thesis-crank-rocker", "--animation", path, "--frames", "36", "--frame-delay",
                            "60", "--crank-angle", "45"});
  INFO(run.err.toStdString());
  REQUIRE(run.exitCode == 0);
  const auto gif = testing::readGif(path);
  REQUIRE(gif);
  CHECK(gif->frames.size() == 36);
  CHECK(gif->delayCentiseconds == std::vector<int>(36, 6));
  CHECK(gif->loopsForever);
  CHECK(gif->width > 100);
  CHECK(testing::differingPixels(gif->frames[0], gif->frames[9], 16) > 50);
}

TEST_CASE("linkwright --animation writes an MP4 and a WebM at the rate and size asked", "[ui][export][video][app]") {
  QTemporaryDir dir;
  const QString mp4 = dir.filePath("thesis.mp4");
  Run run = designer({"--example", "thesis-crank-rocker", "--animation", mp4, "--frames", "24", "--frame-rate", "12",
                      "--animation-size", "641x361"});
  INFO(run.err.toStdString());
  REQUIRE(run.exitCode == 0);
  CHECK_FALSE(run.err.contains("libx264"));  // its statistics stay off the terminal
  auto video = testing::readVideo(mp4);
  REQUIRE(video);
  CHECK(video->codec == "h264");
  CHECK(video->width == 640);  // H.264's even sides
  CHECK(video->height == 360);
  CHECK(video->packets == 24);
  CHECK(video->framesPerSecond == Approx(12.0));
  CHECK(video->durationSeconds == Approx(2.0));

  const QString webm = dir.filePath("thesis.webm");
  run = designer(
      {"--example", "thesis-crank-rocker", "--animation", webm, "--frames", "6", "--animation-size", "321x241"});
  REQUIRE(run.exitCode == 0);
  video = testing::readVideo(webm);
  REQUIRE(video);
  CHECK(video->codec == "vp9");
  CHECK(video->width == 321);
  CHECK(video->height == 241);
  CHECK(video->packets == 6);
  CHECK(video->framesPerSecond == Approx(25.0));
}

TEST_CASE("linkwright --image writes the canvas or a plot as a PDF", "[ui][export][pdf][app]") {
  QTemporaryDir dir;
  for (const QString& what : {QStringLiteral("canvas"), QStringLiteral("plot1")}) {
    const QString path = dir.filePath(what + ".pdf");
    const Run run = designer({"--example", "thesis-crank-rocker", "--image", path, "--image-of", what});
    INFO(run.err.toStdString());
    REQUIRE(run.exitCode == 0);
    QFile file(path);
    REQUIRE(file.open(QIODevice::ReadOnly));
    CHECK(file.read(5) == "%PDF-");
  }
  const Run hidden =
      designer({"--example", "thesis-crank-rocker", "--image", dir.filePath("x.pdf"), "--image-of", "plot9"});
  CHECK(hidden.exitCode == 2);
  CHECK(hidden.err.contains("--image-of: plot9 is not shown (shown: plot1"));
  CHECK_FALSE(QFile::exists(dir.filePath("x.pdf")));
}

TEST_CASE("linkwright --animation refuses bad values, names them and writes nothing",
          "[ui][export][animation][app][errors]") {
  QTemporaryDir dir;
  const QString path = dir.filePath("bad.gif");
  struct Case {
    QStringList arguments;
    int exitCode;
    QString expected;
  };
  const std::vector<Case> cases{
      {{"--animation", path, "--frames", "0"}, 2, "--frames: must be a whole number from 2 to 720 (got '0')"},
      {{"--animation", path, "--frames", "721"}, 2, "--frames: must be a whole number from 2 to 720 (got '721')"},
      {{"--animation", path, "--frame-delay", "5"}, 2, "--frame-delay: must be a whole number from 20 to 5000"},
      {{"--frames", "36"}, 2, "--frames, --frame-delay, --frame-rate and --animation-size need --animation FILE"},
      {{"--animation", dir.filePath("missing/out.gif"), "--frames", "4"}, 1, "does not exist or is not writable"},
      // A wrong suffix is bad input (it exited 1), and the message names the suffix accepted.
      {{"--animation", dir.filePath("bad.png"), "--frames", "4"}, 2, "the file name must end in .gif, .mp4 or .webm"},
      {{"--animation", dir.filePath("bad.mp4"), "--frame-rate", "0"}, 2, "--frame-rate: must be a number of frames"},
      {{"--animation", dir.filePath("missing/out.mp4"), "--frames", "4"}, 1, "does not exist or is not writable"},
  };
  for (const Case& c : cases) {
    CAPTURE(c.arguments.join(' ').toStdString());
    const Run run = designer(c.arguments);
    CHECK(run.exitCode == c.exitCode);
    CHECK(run.err.contains(c.expected));
    CHECK_FALSE(QFile::exists(path));
  }
}
