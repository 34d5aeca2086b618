// The GIF encoder on frames made here: the file giflib reads back has every frame, the size,
// the delay and the loop block asked for; flat colours come out exact and a ramp of 256 greys
// within a quantizer cell; wrong input is refused with a sentence and no bytes.

#include "ui/export/gif_writer.h"

#include "tests/ui/support/gif_readback.h"

#include "tests/support/catch.h"

#include <QFile>
#include <QTemporaryDir>

using namespace linkwright;

namespace {

constexpr int kWidth = 64;
constexpr int kHeight = 40;

// White, a red block at column `left`, a grey ramp 0..255 across the bottom rows.
std::vector<std::uint8_t> frame(int left) {
  std::vector<std::uint8_t> rgb(3 * kWidth * kHeight, 255);
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      std::uint8_t* p = rgb.data() + 3 * (y * kWidth + x);
      if (y >= 32) p[0] = p[1] = p[2] = static_cast<std::uint8_t>((x + kWidth * (y - 32)) % 256);
      else if (x >= left && x < left + 10 && y >= 5 && y < 20) {
        p[0] = 200;
        p[1] = 30;
        p[2] = 40;
      }
    }
  return rgb;
}

std::optional<testing::GifReadback> writeAndRead(ui::GifWriter& writer, const QString& path) {
  const auto bytes = writer.finish();
  if (!bytes) return std::nullopt;
  QFile file(path);
  if (!file.open(QIODevice::WriteOnly)) return std::nullopt;
  file.write(reinterpret_cast<const char*>(bytes->data()), qint64(bytes->size()));
  file.close();
  return testing::readGif(path);
}

}  // namespace

TEST_CASE("a GIF reads back with its frames, size, delay and loop", "[ui][export][gif]") {
  const bool loop = GENERATE(true, false);
  CAPTURE(loop);
  ui::GifWriter writer({kWidth, kHeight, 7, loop});
  REQUIRE(writer.error().empty());
  for (const int left : {0, 20, 40}) REQUIRE(writer.addFrame(frame(left)));
  QTemporaryDir dir;
  const auto gif = writeAndRead(writer, dir.filePath("t.gif"));
  REQUIRE(gif);
  CHECK(gif->width == kWidth);
  CHECK(gif->height == kHeight);
  REQUIRE(gif->frames.size() == 3);
  CHECK(gif->delayCentiseconds == std::vector<int>{7, 7, 7});
  CHECK(gif->loopsForever == loop);
  // Flat colours exact: each palette entry is the mean of its pixels.
  const QImage& second = gif->frames[1];
  CHECK(second.pixel(0, 0) == qRgb(255, 255, 255));
  CHECK(second.pixel(25, 10) == qRgb(200, 30, 40));
  CHECK(second.pixel(5, 10) == qRgb(255, 255, 255));
  CHECK(gif->frames[0].pixel(5, 10) == qRgb(200, 30, 40));
  // The ramp: giflib's quantizer works on 5-bit cells (8 levels), and a cell's entry is the
  // mean of its pixels, so within 7 levels of each (248 shares white's cell with the background).
  for (int x = 0; x < kWidth; ++x)
    for (int y = 32; y < kHeight; ++y) {
      const int grey = (x + kWidth * (y - 32)) % 256;
      CAPTURE(x, y);
      REQUIRE(std::abs(qRed(second.pixel(x, y)) - grey) <= 7);
      REQUIRE(qRed(second.pixel(x, y)) == qGreen(second.pixel(x, y)));
    }
}

TEST_CASE("the GIF writer refuses a wrong size or frame and gives no bytes", "[ui][export][gif][errors]") {
  ui::GifWriter zero({0, 10, 4, true});
  CHECK(zero.error().find("1 to 65535") != std::string::npos);
  CHECK(zero.error().find("0 × 10") != std::string::npos);
  CHECK_FALSE(zero.addFrame(std::vector<std::uint8_t>(30, 0)));
  CHECK_FALSE(zero.finish());

  ui::GifWriter writer({kWidth, kHeight, 4, true});
  REQUIRE(writer.addFrame(frame(0)));
  CHECK_FALSE(writer.addFrame(std::vector<std::uint8_t>(10, 0)));
  CHECK(writer.error().find("frame 2 has 10 bytes") != std::string::npos);
  CHECK_FALSE(writer.finish());

  ui::GifWriter empty({kWidth, kHeight, 4, true});
  CHECK_FALSE(empty.finish());
  CHECK(empty.error() == "the animation has no frames");
}
