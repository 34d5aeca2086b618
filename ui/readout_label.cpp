#include "ui/readout_label.h"

#include <QEvent>
#include <QFontMetrics>
#include <QPainter>
#include <QRegularExpression>
#include <QResizeEvent>
#include <QStyle>

#include <algorithm>
#include <limits>

namespace linkwright::ui {

ReadoutLabel::ReadoutLabel(QWidget* parent) : QWidget(parent) {}

void ReadoutLabel::setText(const QString& text) {
  if (text == m_text) return;
  m_text = text;
  // Laid out already, the new text needs no more lines than the label holds at this width and
  // has no word wider than it: nothing around the label moves. One wrapped layout tells both:
  // a word that cannot be wrapped makes its line, and so the text, wider than the label.
  if (width() <= 0) {
    updateGeometry();
  } else if (const QRect needed = wrapped(text, width()); needed.height() > m_heldHeight || needed.width() > width()) {
    m_heldHeight = std::max(m_heldHeight, needed.height());
    updateGeometry();
  }
  update();
}

void ReadoutLabel::resizeEvent(QResizeEvent* event) {
  QWidget::resizeEvent(event);
  if (event->size().width() != event->oldSize().width()) m_heldHeight = linesHeight(m_text, width());
}

QRect ReadoutLabel::wrapped(const QString& text, int width) const {
  const int oneLine = fontMetrics().height();
  if (text.isEmpty()) return {0, 0, 0, oneLine};
  const QRect room(0, 0, std::max(1, width), std::numeric_limits<int>::max() / 2);
  const QRect used = fontMetrics().boundingRect(room, kFlags, text);
  return {0, 0, used.width(), std::max(oneLine, used.height())};
}

int ReadoutLabel::linesHeight(const QString& text, int width) const { return wrapped(text, width).height(); }

int ReadoutLabel::widestWord(const QString& text) const {
  static const QRegularExpression space(QStringLiteral("\\s+"));
  int widest = 0;
  for (const QString& word : text.split(space, Qt::SkipEmptyParts))
    widest = std::max(widest, fontMetrics().horizontalAdvance(word));
  return widest;
}

QSize ReadoutLabel::sizeHint() const {
  if (m_text.isEmpty()) return {0, fontMetrics().height()};
  return fontMetrics().boundingRect(QRect(), Qt::AlignLeft, m_text).size();
}

QSize ReadoutLabel::minimumSizeHint() const { return {widestWord(m_text), fontMetrics().height()}; }

int ReadoutLabel::heightForWidth(int width) const {
  const int need = linesHeight(m_text, width);
  return width == this->width() ? std::max(need, m_heldHeight) : need;
}

void ReadoutLabel::paintEvent(QPaintEvent*) {
  QPainter painter(this);
  style()->drawItemText(&painter, rect(), kFlags, palette(), isEnabled(), m_text, foregroundRole());
}

void ReadoutLabel::changeEvent(QEvent* event) {
  QWidget::changeEvent(event);
  if (event->type() != QEvent::FontChange && event->type() != QEvent::StyleChange) return;
  m_heldHeight = linesHeight(m_text, width());  // other lines: what was held means nothing now
  updateGeometry();
}

}  // namespace linkwright::ui
