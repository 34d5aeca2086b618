// File ▸ Export ▸ Animation…'s dialog: the format chooses the timing asked (a GIF's delay, a
// video's frame rate), whether looping is offered, the file dialog's filter and suffix; an odd
// side is said to be made even for H.264 only; the settings carry what was typed.

#include "ui/export/animation_dialog.h"

#include "tests/support/catch.h"

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QSpinBox>

using namespace linkwright;

TEST_CASE("the animation dialog asks a GIF's delay or a video's frame rate, and says when H.264 evens a side",
          "[ui][export][animation][dialog]") {
  ui::AnimationDialog dialog(QSize(801, 600), QStringLiteral("one turn of the crank"));
  dialog.show();
  CHECK(dialog.format() == ui::AnimationFormat::Gif);
  CHECK(dialog.formatBox()->count() == 3);
  CHECK(dialog.delayBox()->isVisible());
  CHECK_FALSE(dialog.rateBox()->isVisible());
  CHECK_FALSE(dialog.sizeNote()->isVisible());
  CHECK(dialog.suffix() == "gif");

  dialog.formatBox()->setCurrentIndex(1);
  CHECK(dialog.format() == ui::AnimationFormat::Mp4);
  CHECK_FALSE(dialog.delayBox()->isVisible());
  CHECK(dialog.rateBox()->isVisible());
  CHECK(dialog.sizeNote()->isVisible());
  CHECK(dialog.sizeNote()->text() == "H.264 needs even sides: the video is 800 × 600 px.");
  // The dialog grew to hold the note: every label has at least the height it asks for.
  QApplication::processEvents();
  for (QWidget* w : dialog.findChildren<QLabel*>()) {
    if (!w->isVisible()) continue;
    CAPTURE(qobject_cast<QLabel*>(w)->text().toStdString());
    CHECK(w->height() >= (w->hasHeightForWidth() ? w->heightForWidth(w->width()) : w->sizeHint().height()));
  }
  CHECK(dialog.fileFilter() == "MP4 video, H.264 (*.mp4)");
  CHECK(dialog.suffix() == "mp4");
  dialog.widthBox()->setValue(800);
  CHECK_FALSE(dialog.sizeNote()->isVisible());
  dialog.widthBox()->setValue(801);

  dialog.formatBox()->setCurrentIndex(2);
  CHECK(dialog.format() == ui::AnimationFormat::WebM);
  CHECK_FALSE(dialog.sizeNote()->isVisible());  // VP9 takes odd sides
  CHECK(dialog.suffix() == "webm");
  dialog.rateBox()->setValue(29.97);
  const ui::AnimationSettings s = dialog.settings();
  CHECK(s.frameRate == Approx(29.97));
  CHECK(s.size == QSize(801, 600));
  // The box's range is the settings' range.
  CHECK(dialog.rateBox()->minimum() == ui::AnimationSettings::kMinFrameRate);
  CHECK(dialog.rateBox()->maximum() == ui::AnimationSettings::kMaxFrameRate);
}
