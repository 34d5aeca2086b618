#include "ui/export/cycle_animation.h"

#include "ui/document/document_file.h"
#include "ui/document/mechanism_document.h"
#include "ui/export/gif_writer.h"

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

// The view as it is on screen, scaled to `size` (proportions kept, centred): the device pixel
// ratio, not a painter scale, keeps pins, labels and cosmetic pens in proportion.
QImage renderView(QGraphicsView& view, const QSize& size) {
  const QSize shown = view.viewport()->size();
  const double scale = std::min(double(size.width()) / shown.width(), double(size.height()) / shown.height());
  QImage image(size, QImage::Format_ARGB32_Premultiplied);
  image.setDevicePixelRatio(scale);
  image.fill(Qt::white);
  QPainter painter(&image);
  painter.setRenderHint(QPainter::Antialiasing);
  view.render(&painter, QRectF(QPointF(0, 0), QSizeF(size) / scale), view.viewport()->rect(), Qt::KeepAspectRatio);
  painter.end();
  return image.convertToFormat(QImage::Format_RGB888);
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
  if (file.suffix().toLower() != "gif")
    return QObject::tr("Cannot export %1: use a .gif file name.").arg(file.fileName());
  // Said before rendering, so nobody waits for frames that cannot be saved; the atomic write
  // at the end checks again.
  const QFileInfo folder(file.absolutePath());
  if (!folder.isDir() || !folder.isWritable())
    return QObject::tr("Cannot write %1: the folder %2 does not exist or is not writable.")
        .arg(file.fileName(), QDir::toNativeSeparators(folder.absoluteFilePath()));
  return std::nullopt;
}

}  // namespace

std::optional<QString> checkAnimationSettings(const AnimationSettings& s) {
  using S = AnimationSettings;
  if (auto why = outOfRange(QObject::tr("Frames per cycle"), s.frames, S::kMinFrames, S::kMaxFrames)) return why;
  if (auto why = outOfRange(QObject::tr("Frame delay"), s.frameDelayMs, S::kMinDelayMs, S::kMaxDelayMs, " ms"))
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
  const QSize size = settings.size.isEmpty() ? view.viewport()->size() : settings.size;
  if (size.isEmpty()) return QObject::tr("The canvas has no size to render.");
  GifWriter gif({size.width(), size.height(), (settings.frameDelayMs + 5) / 10, settings.loopForever});
  const CycleFrames cycle = cycleFrames(document, settings.frames);
  {
    const MotionRestorer restore(document);
    for (std::size_t i = 0; i < cycle.inputs.size(); ++i) {
      if (cycle.inTime) document.setTime(cycle.inputs[i]);
      else document.setCrankAngle(cycle.inputs[i]);
      if (!gif.addFrame(rgbBytes(renderView(view, size))))
        return QObject::tr("GIF not written: %1").arg(QString::fromStdString(gif.error()));
      if (progress && !progress(static_cast<int>(i) + 1, settings.frames))
        return QObject::tr("Animation export cancelled; nothing was written.");
    }
  }
  const auto bytes = gif.finish();
  if (!bytes) return QObject::tr("GIF not written: %1").arg(QString::fromStdString(gif.error()));
  return saveFileAtomically(path, QByteArray(reinterpret_cast<const char*>(bytes->data()), qsizetype(bytes->size())));
}

}  // namespace linkwright::ui
