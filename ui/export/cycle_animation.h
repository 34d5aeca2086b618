#pragma once
// File ▸ Export ▸ Animation… and `linkwright --animation`: the canvas over one cycle as an
// animated GIF, an MP4 video (H.264) or a WebM video (VP9), by the file's suffix, following what the designer's animator plays (crank_animator.h). A crank that turns
// fully makes one turn from the angle shown, in the sense of its ω; a crank (or a linear input)
// that cannot turn fully goes from the angle shown to one end of the range it is in, back to
// the other end and back again; on a time base the instant runs once from the time base's start
// to its end. Each frame is the view as it shows the document (grid, coupler paths, arrows),
// rendered at that input; the document's motion is restored afterwards and the undo stack is
// never touched. The file goes through the one writer (kinematics/io/safe_file.h): a failed or
// cancelled export writes nothing and leaves the file that was there.

#include <QImage>
#include <QSize>
#include <QString>

#include <functional>
#include <optional>
#include <vector>

class QGraphicsView;

namespace linkwright::ui {

class MechanismDocument;

enum class AnimationFormat {
  Gif,   ///< .gif: giflib (gif_writer.h), 256 colours a frame, delays in 1/100 s
  Mp4,   ///< .mp4: H.264 through FFmpeg (video_writer.h); even sides
  WebM,  ///< .webm: VP9 through FFmpeg (video_writer.h)
};

/// The format a file name asks for by its suffix (any case), or nullopt.
std::optional<AnimationFormat> animationFormatOf(const QString& path);

/// Why this system cannot write `format` (FFmpeg built without its encoder), or nullopt.
std::optional<QString> animationFormatMissing(AnimationFormat format);

/// The size frames of `format` are made at: `size` itself, or one pixel less each way that is
/// odd for a codec that needs even sides (H.264 at 4:2:0 colour: 801 × 601 becomes 800 × 600).
QSize encodedSize(const QSize& size, AnimationFormat format);

struct AnimationSettings {
  static constexpr int kMinFrames = 2;
  static constexpr int kMaxFrames = 720;
  static constexpr int kMinDelayMs = 20;  // browsers slow anything shorter to 100 ms
  static constexpr int kMaxDelayMs = 5000;
  static constexpr int kMinSide = 16;
  static constexpr int kMaxSide = 4096;
  static constexpr double kMinFrameRate = 1.0;  // a video's frames per second
  static constexpr double kMaxFrameRate = 120.0;

  int frames = 72;          ///< frames per cycle (one turn, one rocking period, one time base)
  int frameDelayMs = 40;    ///< a GIF's ms per frame; GIF stores 1/100 s, so it is rounded to 10 ms
  double frameRate = 25.0;  ///< a video's (MP4, WebM) frames per second, any value in range (29.97)
  QSize size;               ///< pixels; empty: the view's size
  bool loopForever = true;
};

/// Why `settings` cannot be used (naming the field, the value and the accepted range), or nullopt.
std::optional<QString> checkAnimationSettings(const AnimationSettings& settings);

/// The inputs of a cycle's frames: crank angles (rad; a linear input's value) or, on a time
/// base, instants (s).
struct CycleFrames {
  bool inTime = false;
  bool rocking = false;  ///< the input goes back and forth across its assemblable range
  std::vector<double> inputs;
};

/// The `frames` inputs of one cycle starting at the document's present motion.
CycleFrames cycleFrames(const MechanismDocument& document, int frames);

/// Called after each frame with the number done and the total; returning false cancels.
using AnimationProgress = std::function<bool(int done, int total)>;

/// The frame an export of `size` pixels makes of `view` as it shows the document now: the view
/// scaled to fit `size`, proportions kept, centred on white.
QImage renderAnimationFrame(QGraphicsView& view, const QSize& size);

/// Renders `view` over one cycle of `document` into `path` (.gif, .mp4 or .webm). Returns why
/// not (bad settings, another suffix, a missing encoder, a path that cannot be written,
/// cancelled), and then leaves the file that was at `path`.
std::optional<QString> exportCycleAnimation(MechanismDocument& document, QGraphicsView& view, const QString& path,
                                            const AnimationSettings& settings, const AnimationProgress& progress = {});

}  // namespace linkwright::ui
