#include "ui/export/gif_writer.h"

#include <gif_lib.h>

#include <array>
#include <cstring>

namespace linkwright::ui {

namespace {

constexpr int kPaletteSize = 256;

int appendToBytes(GifFileType* gif, const GifByteType* data, int length) {
  auto* bytes = static_cast<std::vector<std::uint8_t>*>(gif->UserData);
  bytes->insert(bytes->end(), data, data + length);
  return length;
}

// The quantizer's entries are the centres of 5-bit cells (white comes out 248): set each to
// the mean of the pixels mapped to it, which is exact for a flat colour.
void refinePalette(const std::vector<std::uint8_t>& rgb, const std::vector<GifByteType>& indices,
                   std::array<GifColorType, kPaletteSize>& palette) {
  std::array<std::array<std::uint64_t, 4>, kPaletteSize> sums{};
  for (std::size_t i = 0; i < indices.size(); ++i) {
    auto& s = sums[indices[i]];
    s[0] += rgb[3 * i];
    s[1] += rgb[3 * i + 1];
    s[2] += rgb[3 * i + 2];
    ++s[3];
  }
  for (int c = 0; c < kPaletteSize; ++c) {
    const auto& s = sums[c];
    if (s[3] == 0) continue;
    const auto mean = [&](std::uint64_t sum) { return static_cast<GifByteType>((sum + s[3] / 2) / s[3]); };
    palette[c] = {mean(s[0]), mean(s[1]), mean(s[2])};
  }
}

}  // namespace

struct GifWriter::Handle {
  GifFileType* gif = nullptr;
};

GifWriter::GifWriter(const GifAnimationOptions& options) : m_options(options), m_gif(std::make_unique<Handle>()) {
  if (options.width <= 0 || options.height <= 0 || options.width > 65535 || options.height > 65535) {
    m_error = "the image size must be 1 to 65535 pixels each way (got " + std::to_string(options.width) + " × " +
              std::to_string(options.height) + ")";
    return;
  }
  int error = 0;
  m_gif->gif = EGifOpen(&m_bytes, appendToBytes, &error);
  if (m_gif->gif == nullptr) {
    fail("cannot start the GIF", error);
    return;
  }
  EGifSetGifVersion(m_gif->gif, true);  // GIF89a: frame delays and the loop extension
  if (EGifPutScreenDesc(m_gif->gif, options.width, options.height, 8, 0, nullptr) == GIF_ERROR) {
    fail("cannot write the GIF header", m_gif->gif->Error);
    return;
  }
  if (options.loopForever) putLoopExtension();
}

GifWriter::~GifWriter() {
  if (m_gif->gif != nullptr) EGifCloseFile(m_gif->gif, nullptr);
}

bool GifWriter::fail(const std::string& what, int gifError) {
  if (m_error.empty()) {
    const char* why = GifErrorString(gifError);
    m_error = what + (why != nullptr ? std::string(": ") + why : std::string());
  }
  return false;
}

// Netscape's application extension, which every browser and presentation program reads: loop
// count 0 means forever.
bool GifWriter::putLoopExtension() {
  static constexpr char kNetscape[] = "NETSCAPE2.0";
  static constexpr GifByteType kLoopForever[] = {1, 0, 0};
  GifFileType* gif = m_gif->gif;
  if (EGifPutExtensionLeader(gif, APPLICATION_EXT_FUNC_CODE) == GIF_ERROR ||
      EGifPutExtensionBlock(gif, 11, kNetscape) == GIF_ERROR ||
      EGifPutExtensionBlock(gif, 3, kLoopForever) == GIF_ERROR || EGifPutExtensionTrailer(gif) == GIF_ERROR)
    return fail("cannot write the loop extension", gif->Error);
  return true;
}

bool GifWriter::addFrame(const std::vector<std::uint8_t>& rgb) {
  if (!m_error.empty() || m_gif->gif == nullptr) return false;
  const auto w = static_cast<std::size_t>(m_options.width);
  const auto h = static_cast<std::size_t>(m_options.height);
  if (rgb.size() != 3 * w * h) {
    m_error = "frame " + std::to_string(m_frames + 1) + " has " + std::to_string(rgb.size()) + " bytes, not " +
              std::to_string(3 * w * h);
    return false;
  }
  std::vector<GifByteType> red(w * h), green(w * h), blue(w * h), indices(w * h);
  for (std::size_t i = 0; i < w * h; ++i) {
    red[i] = rgb[3 * i];
    green[i] = rgb[3 * i + 1];
    blue[i] = rgb[3 * i + 2];
  }
  std::array<GifColorType, kPaletteSize> palette{};
  int colours = kPaletteSize;
  if (GifQuantizeBuffer(static_cast<unsigned>(w), static_cast<unsigned>(h), &colours, red.data(), green.data(),
                        blue.data(), indices.data(), palette.data()) == GIF_ERROR)
    return fail("cannot reduce frame " + std::to_string(m_frames + 1) + " to 256 colours", E_GIF_ERR_NOT_ENOUGH_MEM);
  refinePalette(rgb, indices, palette);

  GifFileType* gif = m_gif->gif;
  GraphicsControlBlock control{};
  control.DisposalMode = DISPOSE_DO_NOT;
  control.UserInputFlag = false;
  control.DelayTime = m_options.delayCentiseconds;
  control.TransparentColor = NO_TRANSPARENT_COLOR;
  GifByteType extension[4];
  const auto length = static_cast<int>(EGifGCBToExtension(&control, extension));
  if (EGifPutExtension(gif, GRAPHICS_EXT_FUNC_CODE, length, extension) == GIF_ERROR)
    return fail("cannot write the delay of frame " + std::to_string(m_frames + 1), gif->Error);
  ColorMapObject* map = GifMakeMapObject(kPaletteSize, palette.data());
  if (map == nullptr) return fail("cannot make a colour table", E_GIF_ERR_NOT_ENOUGH_MEM);
  const int described = EGifPutImageDesc(gif, 0, 0, m_options.width, m_options.height, false, map);
  GifFreeMapObject(map);
  if (described == GIF_ERROR) return fail("cannot write frame " + std::to_string(m_frames + 1), gif->Error);
  for (std::size_t y = 0; y < h; ++y)
    if (EGifPutLine(gif, indices.data() + y * w, m_options.width) == GIF_ERROR)
      return fail("cannot write frame " + std::to_string(m_frames + 1), gif->Error);
  ++m_frames;
  return true;
}

std::optional<std::vector<std::uint8_t>> GifWriter::finish() {
  if (m_gif->gif == nullptr) return std::nullopt;
  int error = 0;
  const int closed = EGifCloseFile(m_gif->gif, &error);
  m_gif->gif = nullptr;  // closed (and freed) whatever the outcome
  if (closed == GIF_ERROR) fail("cannot finish the GIF", error);
  if (!m_error.empty()) return std::nullopt;
  if (m_frames == 0) {
    m_error = "the animation has no frames";
    return std::nullopt;
  }
  return std::move(m_bytes);
}

}  // namespace linkwright::ui
