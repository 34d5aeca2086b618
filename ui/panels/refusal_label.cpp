#include "ui/panels/refusal_label.h"

#include "ui/document/mechanism_document.h"

namespace linkwright::ui {

RefusalLabel::RefusalLabel(const MechanismDocument* document, QWidget* parent) : QLabel(parent) {
  setWordWrap(true);
  setStyleSheet("color: #b00020;");
  hide();
  // A refused edit changes nothing, so any new design is one the refusal was not made for.
  connect(document, &MechanismDocument::changed, this, [this](Changes what) {
    if (what & Change::Design) hide();
  });
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
