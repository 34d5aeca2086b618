#pragma once
// A video encoder over Debian's FFmpeg libraries (libavcodec, libavformat, libswscale,
// libavutil), Qt-free: frames go in one at a time as 8-bit RGB rows, are converted to 4:2:0
// YUV (BT.709, limited range, tagged so that players convert them back alike), encoded and
// muxed straight into the file at the path given, so a video of hundreds of frames never holds
// more than one raw frame. The caller chooses that path through the one writer
// (kinematics/io/safe_file.h: a temporary file renamed over the target only when finish()
// succeeded).
//
// Two formats: MP4 with H.264 (libx264, CRF 18, which every player and slide program reads;
// H.264 at 4:2:0 needs even sides) and WebM with VP9 (libvpx-vp9 in constant quality, CRF 30,
// which browsers play; odd sides are fine). The encoders are looked up by name at run time, as
// an FFmpeg built without them exists: encoderMissing() says which one is absent.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace linkwright::ui {

enum class VideoCodec {
  H264Mp4,  ///< H.264 in MP4 (FFmpeg's encoder "libx264", muxer "mp4")
  Vp9WebM,  ///< VP9 in WebM (FFmpeg's encoder "libvpx-vp9", muxer "webm")
};

struct VideoOptions {
  VideoCodec codec = VideoCodec::H264Mp4;
  int width = 0;                 ///< pixels, > 0; even for H.264 (needsEvenSides)
  int height = 0;                ///< pixels, > 0; even for H.264
  double framesPerSecond = 25.;  ///< frames per second, > 0 and finite (29.97 is stored as 2997/100)
};

/// The FFmpeg encoder's name for `codec` ("libx264", "libvpx-vp9").
const char* encoderName(VideoCodec codec);

/// Whether `codec` needs even sides (H.264 at 4:2:0 does; VP9 does not).
bool needsEvenSides(VideoCodec codec);

/// Why this FFmpeg cannot encode `codec` (its encoder is absent), as a sentence; else nullopt.
std::optional<std::string> encoderMissing(VideoCodec codec);

class VideoWriter {
public:
  /// Opens `path` for writing and writes the container's header. Check error() before adding frames.
  VideoWriter(const std::string& path, const VideoOptions& options);
  ~VideoWriter();
  VideoWriter(const VideoWriter&) = delete;
  VideoWriter& operator=(const VideoWriter&) = delete;

  /// Encodes a frame: `rgb` holds width × height pixels, row by row from the top, 3 bytes each.
  /// Returns false (and sets error()) if the size is wrong or FFmpeg refuses.
  bool addFrame(const std::vector<std::uint8_t>& rgb);
  /// Flushes the encoder, writes the container's index and closes the file; false (see error())
  /// if anything failed, the disk filling up included.
  bool finish();

  /// The first failure, as a sentence; empty while all is well.
  const std::string& error() const { return m_error; }
  int frameCount() const { return m_frames; }

private:
  bool open(const std::string& path);
  bool fail(const std::string& what, int averror);
  bool send(bool flush);

  struct Handles;
  VideoOptions m_options;
  std::unique_ptr<Handles> m_av;
  std::string m_error;
  int m_frames = 0;
};

}  // namespace linkwright::ui
