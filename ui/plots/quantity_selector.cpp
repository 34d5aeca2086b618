#include "ui/plots/quantity_selector.h"

#include "ui/plots/flow_layout.h"

#include <QCheckBox>
#include <QGridLayout>
#include <QLabel>
#include <QPixmap>

#include <optional>

namespace linkwright::ui {
namespace {

QString groupLabel(QuantityKind kind) {
  switch (kind) {
  case QuantityKind::Angle: return QuantitySelector::tr("Angles:");
  case QuantityKind::Omega: return QuantitySelector::tr("ω:");
  case QuantityKind::Alpha: return QuantitySelector::tr("α:");
  }
  return {};
}

} // namespace

QuantitySelector::QuantitySelector(QWidget* parent) : QWidget(parent) {
  // One group per chart (a label and its boxes); groups wrap as wholes when the panel is narrow.
  auto* flow = new FlowLayout(this, 14, 0);
  flow->setContentsMargins(4, 2, 4, 2);
  QHBoxLayout* group = nullptr;
  std::optional<QuantityKind> groupKind;
  for (const PlotQuantity q : allPlotQuantities()) {
    if (quantityKind(q) != groupKind) {
      groupKind = quantityKind(q);
      auto* groupWidget = new QWidget(this);
      group = new QHBoxLayout(groupWidget);
      group->setContentsMargins(0, 0, 0, 0);
      group->setSpacing(4);
      group->addWidget(new QLabel(groupLabel(*groupKind), groupWidget));
      flow->addWidget(groupWidget);
    }
    auto* box = new QCheckBox(quantityName(q), this);
    box->setObjectName(QStringLiteral("show_") + quantityKey(q));
    box->setChecked(true);
    // A swatch of the curve's colour ties the box to its line.
    QPixmap swatch(10, 10);
    swatch.fill(quantityColor(q));
    box->setIcon(QIcon(swatch));
    box->setIconSize(QSize(10, 10));
    connect(box, &QCheckBox::toggled, this, [this] {
      if (!m_applying) emit selectionChanged();
    });
    m_boxes[static_cast<std::size_t>(q)] = box;
    group->addWidget(box);
  }
}

QuantitySelection QuantitySelector::selection() const {
  QuantitySelection s;
  for (const PlotQuantity q : allPlotQuantities()) s.set(q, checkBox(q)->isChecked());
  return s;
}

void QuantitySelector::setSelection(const QuantitySelection& selection) {
  if (selection == this->selection()) return;
  m_applying = true;
  for (const PlotQuantity q : allPlotQuantities()) checkBox(q)->setChecked(selection.contains(q));
  m_applying = false;
  emit selectionChanged();
}

QCheckBox* QuantitySelector::checkBox(PlotQuantity quantity) const { return m_boxes[static_cast<std::size_t>(quantity)]; }

} // namespace linkwright::ui
