#pragma once
// File ▸ Export ▸ Animation… and `linkwright --animation`: the canvas as an animated GIF over one
// cycle, following what the designer's animator plays (crank_animator.h). A crank that turns
// fully makes one turn from the angle shown, in the sense of its ω; a crank (or a linear input)
// that cannot turn fully goes from the angle shown to one end of the range it is in, back to
// the other end and back again; on a time base the instant runs once from the time base's start
// to its end. Each frame is the view as it shows the document (grid, coupler paths, arrows),
// rendered at that input; the document's motion is restored afterwards and the undo stack is
// never touched. The file is written atomically: a failed or cancelled export writes nothing.

#include <QSize>
#include <QString>

#include <functional>
#include <optional>
#include <vector>

class QGraphicsView;

namespace linkwright::ui {

class MechanismDocument;

struct AnimationSettings {
  static constexpr int kMinFrames = 2;
  static constexpr int kMaxFrames = 720;
  static constexpr int kMinDelayMs = 20;  // browsers slow anything shorter to 100 ms
  static constexpr int kMaxDelayMs = 5000;
  static constexpr int kMinSide = 16;
  static constexpr int kMaxSide = 4096;

  int frames = 72;        ///< frames per cycle (one turn, one rocking period, one time base)
  int frameDelayMs = 40;  ///< ms per frame; GIF stores 1/100 s, so it is rounded to 10 ms
  QSize size;             ///< pixels; empty: the view's size
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

/// Renders `view` over one cycle of `document` into the GIF `path`. Returns why not (bad
/// settings, a path that is not a .gif or cannot be written, cancelled), and then writes nothing.
std::optional<QString> exportCycleAnimation(MechanismDocument& document, QGraphicsView& view, const QString& path,
                                            const AnimationSettings& settings, const AnimationProgress& progress = {});

}  // namespace linkwright::ui
