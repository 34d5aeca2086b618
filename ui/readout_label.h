#pragma once
// A label for values that change on every move of a drag or an animation frame. A QLabel whose
// text changes asks its layout for a new geometry each time, and Qt then re-lays out every
// layout up to the main window (QLayout::activate calls updateGeometry on its widget whatever
// the outcome) and repaints what that touched. This label asks only when the new text does not
// fit the rectangle it has; otherwise it just repaints itself. A text that needs fewer lines
// leaves the label its height until its width changes: rows below do not jump up and down
// while a drag's numbers change length. Plain text, wrapped at word boundaries, in the
// widget's font and foreground role, as QLabel draws it.

#include <QString>
#include <QWidget>

namespace linkwright::ui {

class ReadoutLabel : public QWidget {
  Q_OBJECT
public:
  explicit ReadoutLabel(QWidget* parent = nullptr);

  /// Shows `text` ("\n" breaks lines); a text that fits the current rectangle is only repainted.
  void setText(const QString& text);
  QString text() const { return m_text; }

  /// The text on its own lines, unwrapped.
  QSize sizeHint() const override;
  /// The longest word on one line: narrower than that, words are cut.
  QSize minimumSizeHint() const override;
  bool hasHeightForWidth() const override { return true; }
  /// The text's height wrapped at `width`; at the label's own width, at least the height held.
  int heightForWidth(int width) const override;

protected:
  void paintEvent(QPaintEvent* event) override;
  void changeEvent(QEvent* event) override;
  void resizeEvent(QResizeEvent* event) override;

private:
  static constexpr int kFlags = Qt::AlignLeft | Qt::AlignVCenter | Qt::TextWordWrap;
  /// The size `text` takes wrapped at `width`, one line high at least; wider than `width` when
  /// a word is.
  QRect wrapped(const QString& text, int width) const;
  /// The height `text` takes wrapped at `width`: one line at least.
  int linesHeight(const QString& text, int width) const;
  int widestWord(const QString& text) const;

  QString m_text;
  int m_heldHeight = 0;  // the tallest text's height at the current width
};

}  // namespace linkwright::ui
