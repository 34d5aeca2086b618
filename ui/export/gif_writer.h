#pragma once
// An animated GIF encoder over giflib (Debian: libgif-dev), Qt-free: frames go in one at a
// time as 8-bit RGB rows and come out LZW-compressed into memory, so an animation of hundreds of
// frames never holds more than one raw frame. The caller writes the bytes to disk (atomically).
//
// Colours: each frame gets its own 256-colour table from giflib's median-cut quantizer
// (GifQuantizeBuffer), and each table entry is then set to the mean of the pixels it stands
// for, so that flat colours (the white background, a link's fill) come out exact rather than
// rounded to the quantizer's 5-bit cells. A canvas of a few flat colours with anti-aliased
// edges needs no dithering: the 256 entries cover each colour's blends with the background.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace linkwright::ui {

struct GifAnimationOptions {
  int width = 0;              ///< pixels, > 0
  int height = 0;             ///< pixels, > 0
  int delayCentiseconds = 4;  ///< per frame, 1/100 s (GIF's unit)
  bool loopForever = true;    ///< NETSCAPE2.0 loop extension; false plays once
};

class GifWriter {
public:
  /// Starts an animation in memory. Check error() before adding frames.
  explicit GifWriter(const GifAnimationOptions& options);
  ~GifWriter();
  GifWriter(const GifWriter&) = delete;
  GifWriter& operator=(const GifWriter&) = delete;

  /// Appends a frame: `rgb` holds width × height pixels, row by row from the top, 3 bytes each.
  /// Returns false (and sets error()) if giflib refuses or the size is wrong.
  bool addFrame(const std::vector<std::uint8_t>& rgb);
  /// Ends the file and returns its bytes; nullopt (see error()) if anything failed.
  std::optional<std::vector<std::uint8_t>> finish();

  /// The first failure, as a sentence; empty while all is well.
  const std::string& error() const { return m_error; }
  int frameCount() const { return m_frames; }

private:
  bool fail(const std::string& what, int gifError);
  bool putLoopExtension();

  struct Handle;
  GifAnimationOptions m_options;
  std::unique_ptr<Handle> m_gif;
  std::vector<std::uint8_t> m_bytes;
  std::string m_error;
  int m_frames = 0;
};

}  // namespace linkwright::ui
