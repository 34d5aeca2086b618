#pragma once
// Reads an animated GIF back with giflib's own decoder (DGifSlurp): the screen size, each
// frame as an RGB image, each frame's delay and whether a NETSCAPE2.0 block makes it loop.

#include <gif_lib.h>

#include <QImage>
#include <QString>

#include <cstdlib>
#include <cstring>
#include <optional>
#include <vector>

namespace linkwright::testing {

struct GifReadback {
  int width = 0;
  int height = 0;
  std::vector<QImage> frames;          ///< Format_RGB888, the screen's size
  std::vector<int> delayCentiseconds;  ///< per frame
  bool loopsForever = false;           ///< a NETSCAPE2.0 block with loop count 0
};

// The loop block: the application extension "NETSCAPE2.0" followed by the sub-block {1, 0, 0}.
inline bool loopsForever(const SavedImage& image) {
  for (int i = 0; i + 1 < image.ExtensionBlockCount; ++i) {
    const ExtensionBlock& app = image.ExtensionBlocks[i];
    const ExtensionBlock& data = image.ExtensionBlocks[i + 1];
    if (app.Function == APPLICATION_EXT_FUNC_CODE && app.ByteCount == 11 &&
        std::memcmp(app.Bytes, "NETSCAPE2.0", 11) == 0 && data.ByteCount == 3 && data.Bytes[0] == 1 &&
        data.Bytes[1] == 0 && data.Bytes[2] == 0)
      return true;
  }
  return false;
}

inline std::optional<GifReadback> readGif(const QString& path) {
  int error = 0;
  GifFileType* gif = DGifOpenFileName(path.toLocal8Bit().constData(), &error);
  if (gif == nullptr) return std::nullopt;
  if (DGifSlurp(gif) == GIF_ERROR) {
    DGifCloseFile(gif, &error);
    return std::nullopt;
  }
  GifReadback out;
  out.width = gif->SWidth;
  out.height = gif->SHeight;
  for (int f = 0; f < gif->ImageCount; ++f) {
    const SavedImage& saved = gif->SavedImages[f];
    const GifImageDesc& desc = saved.ImageDesc;
    const ColorMapObject* map = desc.ColorMap != nullptr ? desc.ColorMap : gif->SColorMap;
    QImage image(out.width, out.height, QImage::Format_RGB888);
    image.fill(Qt::black);
    for (int y = 0; y < desc.Height; ++y)
      for (int x = 0; x < desc.Width; ++x) {
        const GifColorType c = map->Colors[saved.RasterBits[y * desc.Width + x]];
        image.setPixel(desc.Left + x, desc.Top + y, qRgb(c.Red, c.Green, c.Blue));
      }
    out.frames.push_back(image);
    GraphicsControlBlock control{};
    DGifSavedExtensionToGCB(gif, f, &control);
    out.delayCentiseconds.push_back(control.DelayTime);
    if (f == 0) out.loopsForever = loopsForever(saved);
  }
  DGifCloseFile(gif, &error);
  return out;
}

/// How many pixels of `a` and `b` (same size) differ by more than `tolerance` in some channel.
inline long differingPixels(const QImage& a, const QImage& b, int tolerance = 0) {
  long count = 0;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x) {
      const QRgb p = a.pixel(x, y);
      const QRgb q = b.pixel(x, y);
      if (std::abs(qRed(p) - qRed(q)) > tolerance || std::abs(qGreen(p) - qGreen(q)) > tolerance ||
          std::abs(qBlue(p) - qBlue(q)) > tolerance)
        ++count;
    }
  return count;
}

}  // namespace linkwright::testing
