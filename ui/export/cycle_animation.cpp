#include "ui/export/cycle_animation.h"

#include "ui/document/document_file.h"
#include "ui/document/mechanism_document.h"
#include "ui/export/gif_writer.h"
#include "ui/export/video_writer.h"

#include "kinematics/model/units.h"

#include <QDir>
#include <QFileInfo>
#include <QGraphicsView>
#include <QImage>
#include <QPainter>

#include <cmath>

namespace linkwright::ui {

namespace k = kinematics;

namespace {

std::optional<QString> outOfRange(const QString& field, int value, int low, int high, const QString& unit = {}) {
  if (value >= low && value <= high) return std::nullopt;
  return QObject::tr("%1 must be %2 to %3%4 (got %5)").arg(field).arg(low).arg(high).arg(unit).arg(value);
}

std::optional<QString> outOfRange(const QString& field, double value, double low, double high, const QString& unit) {
  if (value >= low && value <= high) return std::nullopt;  // false for nan
  return QObject::tr("%1 must be %2 to %3%4 (got %5)")
      .arg(field)
      .arg(low)
      .arg(high)
      .arg(unit)
      .arg(std::isfinite(value) ? QString::number(value, 'g', 6) : QObject::tr("undefined"));
}

VideoCodec codecOf(AnimationFormat format) {
  return format == AnimationFormat::Mp4 ? VideoCodec::H264Mp4 : VideoCodec::Vp9WebM;
}

// A crank that turns fully: one turn from `start` in the sense of ω, as the animator turns it.
std::vector<double> fullTurn(double start, double omega, int frames) {
  const double sense = omega < 0.0 ? -1.0 : 1.0;
  std::vector<double> inputs(static_cast<std::size_t>(frames));
  for (int i = 0; i < frames; ++i)
    inputs[static_cast<std::size_t>(i)] = std::remainder(start + sense * 2.0 * k::kPi * i / frames, 2.0 * k::kPi);
  return inputs;
}

// The assemblable range the input `value` lies in (any turn of a crank), with `value` moved
// into that range's turn; the first range if none holds it (the document keeps it in one).
std::pair<k::AngleRange, double> rangeHolding(const k::InputRange& range, double value) {
  for (const k::AngleRange& r : range.ranges) {
    const double v = range.period > 0.0
                         ? r.from + std::fmod(std::fmod(value - r.from, range.period) + range.period, range.period)
                         : value;
    if (v >= r.from - 1e-12 && v <= r.to + 1e-12) return {r, std::min(v, r.to)};
  }
  return {range.ranges.front(), range.ranges.front().from};
}

// An input that cannot turn fully rocks: from `start` on to the range's upper end, back to
// its lower end and back to `start`, at a constant rate, as the animator rocks it.
std::vector<double> rocking(const k::AngleRange& r, double start, int frames) {
  const double span = r.to - r.from;
  std::vector<double> inputs(static_cast<std::size_t>(frames));
  for (int i = 0; i < frames; ++i) {
    const double u = std::fmod(start - r.from + 2.0 * span * i / frames, 2.0 * span);
    inputs[static_cast<std::size_t>(i)] = span > 0.0 ? r.from + (u <= span ? u : 2.0 * span - u) : r.from;
  }
  return inputs;
}

std::vector<std::uint8_t> rgbBytes(const QImage& image) {
  const auto rowBytes = static_cast<std::size_t>(3 * image.width());
  std::vector<std::uint8_t> rgb(rowBytes * static_cast<std::size_t>(image.height()));
  for (int y = 0; y < image.height(); ++y)
    std::copy_n(image.constScanLine(y), rowBytes, rgb.data() + rowBytes * static_cast<std::size_t>(y));
  return rgb;
}

// Puts the document's motion back as it was, however the export ends.
class MotionRestorer {
public:
  explicit MotionRestorer(MechanismDocument& document)
      : m_document(document), m_angle(document.crankAngle()), m_time(document.time()) {}
  ~MotionRestorer() {
    if (m_document.onTimeBase()) m_document.setTime(m_time);
    else m_document.setCrankAngle(m_angle);
  }
  MotionRestorer(const MotionRestorer&) = delete;
  MotionRestorer& operator=(const MotionRestorer&) = delete;

private:
  MechanismDocument& m_document;
  double m_angle;
  double m_time;
};

std::optional<QString> checkPath(const QString& path) {
  const QFileInfo file(path);
  if (!animationFormatOf(path))
    return QObject::tr("Cannot export %1: use a .gif, .mp4 or .webm file name.").arg(file.fileName());
  // Said before rendering, so nobody waits for frames that cannot be saved; the atomic write
  // at the end checks again.
  const QFileInfo folder(file.absolutePath());
  if (!folder.isDir() || !folder.isWritable())
    return QObject::tr("Cannot write %1: the folder %2 does not exist or is not writable.")
        .arg(file.fileName(), QDir::toNativeSeparators(folder.absoluteFilePath()));
  return std::nullopt;
}

// Sets the document to each input of `cycle` in turn, renders the view at `size` and hands the
// frame's RGB bytes to `add`, which says why it could not take it; returns why the cycle stopped.
std::optional<QString> renderCycle(MechanismDocument& document, QGraphicsView& view, const QSize& size,
                                   const CycleFrames& cycle, const AnimationProgress& progress,
                                   const std::function<std::optional<QString>(const std::vector<std::uint8_t>&)>& add) {
  const MotionRestorer restore(document);
  const int total = static_cast<int>(cycle.inputs.size());
  for (int i = 0; i < total; ++i) {
    if (cycle.inTime) document.setTime(cycle.inputs[static_cast<std::size_t>(i)]);
    else document.setCrankAngle(cycle.inputs[static_cast<std::size_t>(i)]);
    if (auto why = add(rgbBytes(renderAnimationFrame(view, size)))) return why;
    if (progress && !progress(i + 1, total)) return QObject::tr("Animation export cancelled; nothing was written.");
  }
  return std::nullopt;
}

std::optional<QString> exportGif(MechanismDocument& document, QGraphicsView& view, const QString& path,
                                 const AnimationSettings& settings, const QSize& size,
                                 const AnimationProgress& progress) {
  GifWriter gif({size.width(), size.height(), (settings.frameDelayMs + 5) / 10, settings.loopForever});
  const auto add = [&gif](const std::vector<std::uint8_t>& rgb) -> std::optional<QString> {
    if (gif.addFrame(rgb)) return std::nullopt;
    return QObject::tr("GIF not written: %1").arg(QString::fromStdString(gif.error()));
  };
  if (auto why = renderCycle(document, view, size, cycleFrames(document, settings.frames), progress, add)) return why;
  const auto bytes = gif.finish();
  if (!bytes) return QObject::tr("GIF not written: %1").arg(QString::fromStdString(gif.error()));
  return saveFileAtomically(path, QByteArray(reinterpret_cast<const char*>(bytes->data()), qsizetype(bytes->size())));
}

// FFmpeg's muxers write the file by its name and seek back in it (an MP4's index goes first),
// so the encoder writes the one writer's temporary file itself, which is renamed over `path`
// only when the whole video is in it.
std::optional<QString> exportVideo(MechanismDocument& document, QGraphicsView& view, const QString& path,
                                   const AnimationSettings& settings, AnimationFormat format, const QSize& size,
                                   const AnimationProgress& progress) {
  const CycleFrames cycle = cycleFrames(document, settings.frames);
  bool cancelled = false;  // said as a cancel, not as a file that could not be written
  const AnimationProgress counted = [&progress, &cancelled](int done, int total) {
    cancelled = progress && !progress(done, total);
    return !cancelled;
  };
  const auto encode = [&](const std::string& file) -> std::optional<std::string> {
    VideoWriter video(file, {codecOf(format), size.width(), size.height(), settings.frameRate});
    if (!video.error().empty()) return video.error();
    const auto add = [&video](const std::vector<std::uint8_t>& rgb) -> std::optional<QString> {
      if (video.addFrame(rgb)) return std::nullopt;
      return QString::fromStdString(video.error());
    };
    if (auto why = renderCycle(document, view, size, cycle, counted, add)) return why->toStdString();
    if (!video.finish()) return video.error();
    return std::nullopt;
  };
  auto why = saveFileThrough(path, encode);
  if (why && cancelled) return QObject::tr("Animation export cancelled; the file that was there is unchanged.");
  return why;
}

}  // namespace

std::optional<AnimationFormat> animationFormatOf(const QString& path) {
  const QString suffix = QFileInfo(path).suffix().toLower();
  if (suffix == QLatin1String("gif")) return AnimationFormat::Gif;
  if (suffix == QLatin1String("mp4")) return AnimationFormat::Mp4;
  if (suffix == QLatin1String("webm")) return AnimationFormat::WebM;
  return std::nullopt;
}

std::optional<QString> animationFormatMissing(AnimationFormat format) {
  if (format == AnimationFormat::Gif) return std::nullopt;
  if (auto missing = encoderMissing(codecOf(format))) return QString::fromStdString(*missing);
  return std::nullopt;
}

QSize encodedSize(const QSize& size, AnimationFormat format) {
  if (format == AnimationFormat::Gif || !needsEvenSides(codecOf(format))) return size;
  return QSize(size.width() - size.width() % 2, size.height() - size.height() % 2);
}

// The view as it is on screen, scaled to fit `size` and centred in it (white either side when
// the shapes differ): the device pixel ratio, not a painter scale, keeps pins, labels and
// cosmetic pens in proportion.
QImage renderAnimationFrame(QGraphicsView& view, const QSize& size) {
  const QSizeF shown = view.viewport()->size();
  const double scale = std::min(size.width() / shown.width(), size.height() / shown.height());
  const QSizeF logical = QSizeF(size) / scale;
  const QPointF corner((logical.width() - shown.width()) / 2.0, (logical.height() - shown.height()) / 2.0);
  QImage image(size, QImage::Format_ARGB32_Premultiplied);
  image.setDevicePixelRatio(scale);
  image.fill(Qt::white);
  QPainter painter(&image);
  painter.setRenderHint(QPainter::Antialiasing);
  view.render(&painter, QRectF(corner, shown), view.viewport()->rect(), Qt::KeepAspectRatio);
  painter.end();
  return image.convertToFormat(QImage::Format_RGB888);
}

std::optional<QString> checkAnimationSettings(const AnimationSettings& s) {
  using S = AnimationSettings;
  if (auto why = outOfRange(QObject::tr("Frames per cycle"), s.frames, S::kMinFrames, S::kMaxFrames)) return why;
  if (auto why = outOfRange(QObject::tr("Frame delay"), s.frameDelayMs, S::kMinDelayMs, S::kMaxDelayMs, " ms"))
    return why;
  if (auto why = outOfRange(QObject::tr("Frame rate"), s.frameRate, S::kMinFrameRate, S::kMaxFrameRate, " fps"))
    return why;
  if (s.size.isEmpty()) return std::nullopt;  // the view's own size
  if (auto why = outOfRange(QObject::tr("Image width"), s.size.width(), S::kMinSide, S::kMaxSide, " px")) return why;
  return outOfRange(QObject::tr("Image height"), s.size.height(), S::kMinSide, S::kMaxSide, " px");
}

CycleFrames cycleFrames(const MechanismDocument& document, int frames) {
  CycleFrames out;
  if (const auto& time = document.design().time) {
    out.inTime = true;
    out.inputs.resize(static_cast<std::size_t>(frames));
    for (int i = 0; i < frames; ++i)
      out.inputs[static_cast<std::size_t>(i)] = time->fromTime + (time->toTime - time->fromTime) * i / frames;
    return out;
  }
  const k::InputRange& range = document.analysis().inputRange;
  if (range.fullRotation) {
    out.inputs = fullTurn(document.crankAngle(), document.design().omega, frames);
    return out;
  }
  out.rocking = true;
  const auto [r, start] = rangeHolding(range, document.crankAngle());
  out.inputs = rocking(r, start, frames);
  return out;
}

std::optional<QString> exportCycleAnimation(MechanismDocument& document, QGraphicsView& view, const QString& path,
                                            const AnimationSettings& settings, const AnimationProgress& progress) {
  if (auto why = checkAnimationSettings(settings)) return why;
  if (auto why = checkPath(path)) return why;
  const AnimationFormat format = *animationFormatOf(path);
  if (auto missing = animationFormatMissing(format))
    return QObject::tr("Cannot export %1: %2.").arg(QFileInfo(path).fileName(), *missing);
  const QSize size = encodedSize(settings.size.isEmpty() ? view.viewport()->size() : settings.size, format);
  if (size.isEmpty()) return QObject::tr("The canvas has no size to render.");
  if (format == AnimationFormat::Gif) return exportGif(document, view, path, settings, size, progress);
  return exportVideo(document, view, path, settings, format, size, progress);
}

}  // namespace linkwright::ui
