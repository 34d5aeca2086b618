#include "ui/compare/column_map_editor.h"

#include "kinematics/compare/header_mapping.h"
#include "kinematics/model/number_text.h"

#include <QCheckBox>
#include <QComboBox>
#include <QHeaderView>

namespace linkwright::ui {
namespace {

namespace k = kinematics;
namespace kc = kinematics::compare;

enum Column { kName, kFirst, kRole, kUnit, kNegated, kMagnitude, kReversed, kColumnCount };
constexpr int kNotCompared = 0, kCrankAngle = 1, kTime = 2, kFirstQuantity = 3;

QComboBox* comboAt(const QTableWidget* table, int row, int column) {
  return qobject_cast<QComboBox*>(table->cellWidget(row, column));
}

QCheckBox* checkAt(const QTableWidget* table, int row, int column) {
  return qobject_cast<QCheckBox*>(table->cellWidget(row, column));
}

std::vector<kc::UnitChoice> unitsOfRole(int role, const std::vector<kc::CompareQuantity>& quantities,
                                        const std::string& lengthUnit) {
  if (role == kCrankAngle) return kc::unitsFor(kc::Dimension::Angle, lengthUnit);
  if (role == kTime) return kc::unitsFor(kc::Dimension::Time, lengthUnit);
  if (role >= kFirstQuantity) return kc::unitsFor(quantities[role - kFirstQuantity].dimension, lengthUnit);
  return {};
}

}  // namespace

ColumnMapEditor::ColumnMapEditor(QWidget* parent) : QTableWidget(parent) {
  setColumnCount(kColumnCount);
  setHorizontalHeaderLabels(
      {tr("Column"), tr("First value"), tr("Holds"), tr("Unit"), tr("Negated"), tr("Magnitude"), tr("From other end")});
  horizontalHeader()->setSectionResizeMode(kName, QHeaderView::Stretch);
  for (int c = kFirst; c < kColumnCount; ++c)
    horizontalHeader()->setSectionResizeMode(c, QHeaderView::ResizeToContents);
  verticalHeader()->hide();
  setSelectionMode(QAbstractItemView::NoSelection);
}

void ColumnMapEditor::setTable(const k::io::NumericTable& table, const k::Mechanism& mechanism) {
  m_mechanism = mechanism;
  m_quantities = kc::compareQuantities(mechanism);
  setRowCount(static_cast<int>(table.columns()));
  for (int row = 0; row < rowCount(); ++row) {
    const auto c = static_cast<std::size_t>(row);
    const QString header = QString::fromStdString(table.labels[c]);
    auto* name =
        new QTableWidgetItem(QString("%1: %2").arg(row + 1).arg(header.isEmpty() ? tr("(no header)") : header));
    name->setFlags(Qt::ItemIsEnabled);
    setItem(row, kName, name);
    std::string first;
    for (const k::io::NumericRow& r : table.rows)
      if (r.cells[c]) {
        first = k::formatShort(*r.cells[c]);
        break;
      }
    auto* value = new QTableWidgetItem(QString::fromStdString(first));
    value->setFlags(Qt::ItemIsEnabled);
    setItem(row, kFirst, value);
    auto* role = new QComboBox(this);
    role->addItems({tr("not compared"), tr("x: crank angle"), tr("x: time")});
    for (const kc::CompareQuantity& q : m_quantities) role->addItem(QString::fromStdString(q.key));
    setCellWidget(row, kRole, role);
    setCellWidget(row, kUnit, new QComboBox(this));
    for (int flag : {kNegated, kMagnitude, kReversed}) {
      auto* box = new QCheckBox(this);
      setCellWidget(row, flag, box);
      connect(box, &QCheckBox::toggled, this, &ColumnMapEditor::mappingChanged);
    }
    connect(role, &QComboBox::currentIndexChanged, this, [this, row] {
      fillUnits(row);
      emit mappingChanged();
    });
    connect(comboAt(this, row, kUnit), &QComboBox::currentIndexChanged, this, &ColumnMapEditor::mappingChanged);
    fillUnits(row);
  }
  // Clear headers ("Theta4 (deg)", analyze's own names) propose the mapping to start from.
  setMapping(kc::proposeColumnMapping(table, mechanism));
}

int ColumnMapEditor::roleIndex(int row) const { return comboAt(this, row, kRole)->currentIndex(); }

void ColumnMapEditor::fillUnits(int row) {
  QComboBox* units = comboAt(this, row, kUnit);
  const QSignalBlocker block(units);
  units->clear();
  for (const kc::UnitChoice& unit : unitsOfRole(roleIndex(row), m_quantities, m_mechanism.lengthUnit))
    units->addItem(QString::fromStdString(unit.name));
  units->setEnabled(units->count() > 0);
  const bool quantity = roleIndex(row) >= kFirstQuantity;
  const bool angle = quantity && m_quantities[roleIndex(row) - kFirstQuantity].dimension == kc::Dimension::Angle;
  checkAt(this, row, kNegated)->setEnabled(quantity);
  checkAt(this, row, kMagnitude)->setEnabled(quantity);
  checkAt(this, row, kReversed)->setEnabled(angle);
  if (!angle) checkAt(this, row, kReversed)->setChecked(false);
}

void ColumnMapEditor::setMapping(const kc::ColumnMapping& mapping) {
  const auto show = [this](std::size_t column, int role, const std::string& unit) {
    const int row = static_cast<int>(column);
    if (row >= rowCount()) return;
    comboAt(this, row, kRole)->setCurrentIndex(role);
    fillUnits(row);
    comboAt(this, row, kUnit)->setCurrentText(QString::fromStdString(unit));
  };
  for (int row = 0; row < rowCount(); ++row) comboAt(this, row, kRole)->setCurrentIndex(kNotCompared);
  if (mapping.axis)
    show(mapping.axis->column, mapping.axis->kind == kc::AxisKind::CrankAngle ? kCrankAngle : kTime,
         mapping.axis->unit.name);
  for (const kc::MappedColumn& c : mapping.columns) {
    for (std::size_t i = 0; i < m_quantities.size(); ++i)
      if (m_quantities[i].key == c.quantity.key) show(c.column, kFirstQuantity + static_cast<int>(i), c.unit.name);
    const int row = static_cast<int>(c.column);
    if (row >= rowCount()) continue;
    checkAt(this, row, kNegated)->setChecked(c.negated);
    checkAt(this, row, kMagnitude)->setChecked(c.magnitude);
    checkAt(this, row, kReversed)->setChecked(c.reversed);
  }
}

k::Result<kc::ColumnMapping> ColumnMapEditor::mapping() const {
  kc::ColumnMapping mapping;
  for (int row = 0; row < rowCount(); ++row) {
    const int role = roleIndex(row);
    if (role == kNotCompared) continue;
    const auto units = unitsOfRole(role, m_quantities, m_mechanism.lengthUnit);
    const kc::UnitChoice unit =
        units.at(static_cast<std::size_t>(std::max(0, comboAt(this, row, kUnit)->currentIndex())));
    const auto column = static_cast<std::size_t>(row);
    if (role == kCrankAngle || role == kTime) {
      if (mapping.axis)
        return k::Error{k::ErrorCode::InvalidValue, "map",
                        "columns " + std::to_string(mapping.axis->column + 1) + " and " + std::to_string(row + 1) +
                            " are both the x: choose one crank angle or time column"};
      mapping.axis = kc::AxisColumn{column, role == kCrankAngle ? kc::AxisKind::CrankAngle : kc::AxisKind::Time, unit};
      continue;
    }
    kc::MappedColumn mapped{column, m_quantities[static_cast<std::size_t>(role - kFirstQuantity)], unit};
    mapped.negated = checkAt(this, row, kNegated)->isChecked();
    mapped.magnitude = checkAt(this, row, kMagnitude)->isChecked();
    mapped.reversed = checkAt(this, row, kReversed)->isChecked();
    mapping.columns.push_back(mapped);
  }
  return mapping;
}

}  // namespace linkwright::ui
