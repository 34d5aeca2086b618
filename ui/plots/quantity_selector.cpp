#include "ui/plots/quantity_selector.h"

#include <QCheckBox>
#include <QGridLayout>
#include <QLabel>

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
  // One row per kind of quantity, so the panel stays narrow enough to share the window.
  auto* layout = new QGridLayout(this);
  layout->setContentsMargins(4, 2, 4, 2);
  layout->setHorizontalSpacing(10);
  layout->setVerticalSpacing(0);
  std::optional<QuantityKind> group;
  int row = -1;
  int column = 0;
  for (const PlotQuantity q : allPlotQuantities()) {
    if (quantityKind(q) != group) {
      group = quantityKind(q);
      ++row;
      column = 0;
      layout->addWidget(new QLabel(groupLabel(*group), this), row, column++);
    }
    auto* box = new QCheckBox(quantityName(q), this);
    box->setObjectName(QStringLiteral("show_") + quantityKey(q));
    box->setChecked(true);
    // A swatch of the curve's colour ties the box to its line.
    QPixmap swatch(12, 12);
    swatch.fill(quantityColor(q));
    box->setIcon(QIcon(swatch));
    connect(box, &QCheckBox::toggled, this, [this] {
      if (!m_applying) emit selectionChanged();
    });
    m_boxes[static_cast<std::size_t>(q)] = box;
    layout->addWidget(box, row, column++);
  }
  layout->setColumnStretch(4, 1);
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
