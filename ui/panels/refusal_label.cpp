#include "ui/panels/refusal_label.h"

namespace linkwright::ui {

RefusalLabel::RefusalLabel(QWidget* parent) : QLabel(parent) {
  setWordWrap(true);
  setStyleSheet("color: #b00020;");
  hide();
}

void RefusalLabel::showOutcome(const std::optional<QString>& refusal) {
  if (!refusal) {
    hide();
    return;
  }
  setText(tr("Not applied: %1").arg(*refusal));
  show();
}

QString RefusalLabel::refusal() const { return isHidden() ? QString() : text(); }

}  // namespace linkwright::ui
