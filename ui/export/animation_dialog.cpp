#include "ui/export/animation_dialog.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QSpinBox>
#include <QStandardItemModel>

#include <algorithm>

namespace linkwright::ui {

namespace {

QSpinBox* intBox(int low, int high, int value, const QString& suffix, QWidget* parent) {
  auto* box = new QSpinBox(parent);
  box->setRange(low, high);
  box->setValue(value);
  box->setSuffix(suffix);
  return box;
}

struct FormatEntry {
  AnimationFormat format;
  const char* label;
  const char* filter;
  const char* suffix;
};

// In the combo's order.
const FormatEntry kFormats[] = {
    {AnimationFormat::Gif, QT_TRANSLATE_NOOP("linkwright::ui::AnimationDialog", "Animated GIF"),
     QT_TRANSLATE_NOOP("linkwright::ui::AnimationDialog", "Animated GIF (*.gif)"), "gif"},
    {AnimationFormat::Mp4, QT_TRANSLATE_NOOP("linkwright::ui::AnimationDialog", "MP4 video (H.264)"),
     QT_TRANSLATE_NOOP("linkwright::ui::AnimationDialog", "MP4 video, H.264 (*.mp4)"), "mp4"},
    {AnimationFormat::WebM, QT_TRANSLATE_NOOP("linkwright::ui::AnimationDialog", "WebM video (VP9)"),
     QT_TRANSLATE_NOOP("linkwright::ui::AnimationDialog", "WebM video, VP9 (*.webm)"), "webm"},
};

const FormatEntry& entryOf(AnimationFormat format) {
  return *std::find_if(std::begin(kFormats), std::end(kFormats),
                       [format](const auto& e) { return e.format == format; });
}

}  // namespace

AnimationDialog::AnimationDialog(const QSize& canvasSize, const QString& cycle, QWidget* parent) : QDialog(parent) {
  using S = AnimationSettings;
  const S defaults;
  m_format = new QComboBox(this);
  auto* model = qobject_cast<QStandardItemModel*>(m_format->model());
  for (const FormatEntry& e : kFormats) {
    m_format->addItem(tr(e.label));
    if (const auto missing = animationFormatMissing(e.format)) {
      QStandardItem* item = model->item(m_format->count() - 1);
      item->setEnabled(false);
      item->setToolTip(*missing);
    }
  }
  m_frames = intBox(S::kMinFrames, S::kMaxFrames, defaults.frames, {}, this);
  m_delay = intBox(S::kMinDelayMs, S::kMaxDelayMs, defaults.frameDelayMs, tr(" ms"), this);
  m_delay->setSingleStep(10);  // GIF counts delays in 1/100 s
  m_rate = new QDoubleSpinBox(this);
  m_rate->setRange(S::kMinFrameRate, S::kMaxFrameRate);
  m_rate->setDecimals(3);  // 23.976 and 29.97 as video people type them
  m_rate->setValue(defaults.frameRate);
  m_rate->setSuffix(tr(" fps"));
  m_width = intBox(S::kMinSide, S::kMaxSide, std::clamp(canvasSize.width(), S::kMinSide, S::kMaxSide), tr(" px"), this);
  m_height =
      intBox(S::kMinSide, S::kMaxSide, std::clamp(canvasSize.height(), S::kMinSide, S::kMaxSide), tr(" px"), this);
  m_loop = new QCheckBox(tr("&Loop forever"), this);
  m_loop->setChecked(defaults.loopForever);
  m_duration = new QLabel(this);
  m_sizeNote = new QLabel(this);
  m_sizeNote->setWordWrap(true);

  setWindowTitle(tr("Export animation"));
  m_form = new QFormLayout(this);
  auto* intro = new QLabel(tr("The canvas over %1, as the canvas shows it (paths, arrows, centres): an animated "
                              "GIF for web pages, or an MP4 or WebM video for slides and video players.")
                               .arg(cycle),
                           this);
  intro->setWordWrap(true);
  m_form->addRow(intro);
  m_form->addRow(tr("F&ormat"), m_format);
  m_form->addRow(tr("&Frames per cycle"), m_frames);
  m_form->addRow(tr("Frame &delay"), m_delay);
  m_form->addRow(tr("Frame &rate"), m_rate);
  m_form->addRow(QString(), m_duration);
  auto* size = new QHBoxLayout;
  size->addWidget(m_width);
  size->addWidget(new QLabel(QStringLiteral("×"), this));
  size->addWidget(m_height);
  m_form->addRow(tr("Image size"), size);
  m_form->addRow(QString(), m_sizeNote);
  m_form->addRow(QString(), m_loop);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
  m_form->addRow(buttons);
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  connect(m_format, &QComboBox::currentIndexChanged, this, &AnimationDialog::updateFormat);
  connect(m_frames, &QSpinBox::valueChanged, this, &AnimationDialog::updateDuration);
  connect(m_delay, &QSpinBox::valueChanged, this, &AnimationDialog::updateDuration);
  connect(m_rate, &QDoubleSpinBox::valueChanged, this, &AnimationDialog::updateDuration);
  connect(m_width, &QSpinBox::valueChanged, this, &AnimationDialog::updateFormat);
  connect(m_height, &QSpinBox::valueChanged, this, &AnimationDialog::updateFormat);
  updateFormat();
  setMinimumWidth(sizeHint().width());  // the GIF's rows: a video's do not make it jump narrower
}

AnimationFormat AnimationDialog::format() const { return kFormats[std::max(0, m_format->currentIndex())].format; }

QString AnimationDialog::fileFilter() const { return tr(entryOf(format()).filter); }

QString AnimationDialog::suffix() const { return QString::fromLatin1(entryOf(format()).suffix); }

// A GIF has a delay per frame and may loop; a video has a frame rate and plays once.
void AnimationDialog::updateFormat() {
  const bool gif = format() == AnimationFormat::Gif;
  m_form->setRowVisible(m_delay, gif);
  m_form->setRowVisible(m_rate, !gif);
  m_form->setRowVisible(m_loop, gif);
  const QSize chosen(m_width->value(), m_height->value());
  const QSize made = encodedSize(chosen, format());
  m_form->setRowVisible(m_sizeNote, made != chosen);
  m_sizeNote->setText(tr("H.264 needs even sides: the video is %1 × %2 px.").arg(made.width()).arg(made.height()));
  m_sizeNote->setToolTip(
      tr("H.264 stores colour at half resolution each way (4:2:0), so each side of an MP4 is "
         "even; an odd side is made one pixel less."));
  updateDuration();
  // Rows come and go with the format: the dialog takes the height its rows need, so no wrapped
  // line is cut.
  if (isVisible()) adjustSize();
}

void AnimationDialog::updateDuration() {
  if (format() == AnimationFormat::Gif) {
    const int delayCs = (m_delay->value() + 5) / 10;
    m_duration->setText(tr("%1 frames per second; one cycle lasts %2 s")
                            .arg(100.0 / delayCs, 0, 'g', 3)
                            .arg(m_frames->value() * delayCs / 100.0, 0, 'g', 4));
    return;
  }
  m_duration->setText(tr("One cycle lasts %1 s").arg(m_frames->value() / m_rate->value(), 0, 'g', 4));
}

AnimationSettings AnimationDialog::settings() const {
  AnimationSettings s;
  s.frames = m_frames->value();
  s.frameDelayMs = m_delay->value();
  s.frameRate = m_rate->value();
  s.size = QSize(m_width->value(), m_height->value());
  s.loopForever = m_loop->isChecked();
  return s;
}

}  // namespace linkwright::ui
