#include "ui/plots/quantity_selector.h"

#include "ui/plots/flow_layout.h"

#include <QCheckBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPixmap>

namespace linkwright::ui {
namespace {

QString groupLabel(QuantityKind kind) {
  switch (kind) {
  case QuantityKind::Angle: return QuantitySelector::tr("Angles:");
  case QuantityKind::Omega: return QuantitySelector::tr("ω:");
  case QuantityKind::Alpha: return QuantitySelector::tr("α:");
  case QuantityKind::Position: return QuantitySelector::tr("Position:");
  case QuantityKind::Velocity: return QuantitySelector::tr("v:");
  case QuantityKind::Acceleration: return QuantitySelector::tr("a:");
  case QuantityKind::VelocityRatio:
  case QuantityKind::Advantage: return QuantitySelector::tr("Ratios:");
  }
  return {};
}

}  // namespace

QuantitySelector::QuantitySelector(QWidget* parent) : QWidget(parent), m_flow(new FlowLayout(this, 10, 0)) {
  // One group per chart (a label and its boxes); groups wrap as wholes when the panel is narrow.
  m_flow->setContentsMargins(4, 2, 4, 2);
}

void QuantitySelector::setCurves(const std::vector<PlotCurve>& curves, const QuantitySelection& selection) {
  for (QWidget* group : m_groups) delete group;
  m_groups.clear();
  m_boxes.clear();
  m_curves = curves;
  m_selection = selection;
  QString group;  // the label of the group being filled; the ratios' two charts share one
  for (std::size_t i = 0; i < curves.size(); ++i) {
    const PlotCurve& curve = curves[i];
    // A chart's label stays on one line with its first box; the other boxes wrap one by one,
    // so a six-bar's many angles fit a narrow panel.
    auto* item = new QWidget(this);
    auto* row = new QHBoxLayout(item);
    row->setContentsMargins(0, 0, 0, 0);
    row->setSpacing(4);
    if (const QString label = groupLabel(quantityKind(curve.quantity)); label != group) {
      group = label;
      row->addWidget(new QLabel(label, item));
    }
    m_flow->addWidget(item);
    m_groups.push_back(item);
    auto* box = new QCheckBox(curve.name, item);
    box->setObjectName(QStringLiteral("show_") + curve.key);
    box->setChecked(selection.contains(curve.quantity));
    // A swatch of the curve's colour ties the box to its line.
    QPixmap swatch(10, 10);
    swatch.fill(curve.color);
    box->setIcon(QIcon(swatch));
    box->setIconSize(QSize(10, 10));
    connect(box, &QCheckBox::toggled, this, [this, q = curve.quantity](bool on) {
      m_selection.set(q, on);
      if (!m_applying) emit selectionChanged();
    });
    m_boxes.push_back(box);
    row->addWidget(box);
  }
  updateGeometry();
}

void QuantitySelector::setSelection(const QuantitySelection& selection) {
  if (selection == m_selection) return;
  m_applying = true;
  m_selection = selection;
  for (std::size_t i = 0; i < m_curves.size(); ++i) m_boxes[i]->setChecked(selection.contains(m_curves[i].quantity));
  m_selection = selection;
  m_applying = false;
  emit selectionChanged();
}

QCheckBox* QuantitySelector::checkBox(PlotQuantity quantity) const {
  for (std::size_t i = 0; i < m_curves.size(); ++i)
    if (m_curves[i].quantity == quantity) return m_boxes[i];
  return nullptr;
}

}  // namespace linkwright::ui
