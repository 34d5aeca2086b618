// `linkwright --example NAME --animation FILE.gif --frames N`, the designer run headless as a
// user runs it: the GIF it writes reads back (giflib) with N frames; bad values exit with the
// option named and write nothing.

#include "tests/ui/support/gif_readback.h"

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
      {{"--frames", "36"}, 2, "--frames and --frame-delay need --animation FILE"},
      {{"--animation", dir.filePath("missing/out.gif"), "--frames", "4"}, 1, "does not exist or is not writable"},
      // A wrong suffix is bad input (it exited 1), and the message names the suffix accepted.
      {{"--animation", dir.filePath("bad.png"), "--frames", "4"}, 2, "the file name must end in .gif"},
  };
  for (const Case& c : cases) {
    CAPTURE(c.arguments.join(' ').toStdString());
    const Run run = designer(c.arguments);
    CHECK(run.exitCode == c.exitCode);
    CHECK(run.err.contains(c.expected));
    CHECK_FALSE(QFile::exists(path));
  }
}
