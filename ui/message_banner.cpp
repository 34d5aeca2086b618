#include "ui/message_banner.h"

#include "ui/colors.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QToolButton>

namespace linkwright::ui {

MessageBanner::MessageBanner(QWidget* parent) : QFrame(parent), m_text(new QLabel(this)) {
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(8, 4, 4, 4);
  m_text->setWordWrap(true);
  m_text->setTextInteractionFlags(Qt::TextSelectableByMouse);
  layout->addWidget(m_text, 1);
  auto* close = new QToolButton(this);
  close->setText(QStringLiteral("✕"));
  close->setAutoRaise(true);
  close->setToolTip(tr("Dismiss"));
  layout->addWidget(close);
  connect(close, &QToolButton::clicked, this, &QWidget::hide);
  hide();
}

void MessageBanner::showMessage(const QString& text, Kind kind) {
  const bool error = kind == Kind::Error;
  setStyleSheet(QString("linkwright--ui--MessageBanner { background: %1; border: 1px solid %2; border-radius: 4px; }")
                    .arg((error ? colors().errorBanner : colors().infoBanner).name(),
                         (error ? colors().errorBannerBorder : colors().infoBannerBorder).name()));
  m_text->setText(text);
  show();
}

QString MessageBanner::text() const { return isHidden() ? QString() : m_text->text(); }

}  // namespace linkwright::ui
