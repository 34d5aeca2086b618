#pragma once
// File ▸ Compare…'s column mapping: one row per column of the other tool's table, with its
// header and first value, what it holds (not compared, the x as crank angle or time, or a
// quantity of the core's list, kinematics/compare/compare_quantity.h), its unit (the units the
// core accepts for that quantity), and whether the tool negates it, writes its magnitude or
// measures the angle from the link's other end. The choices come from the core; mapping()
// turns them into the core's ColumnMapping.

#include "kinematics/compare/column_mapping.h"

#include <QTableWidget>

namespace linkwright::ui {

class ColumnMapEditor : public QTableWidget {
  Q_OBJECT
public:
  explicit ColumnMapEditor(QWidget* parent = nullptr);

  /// One row per column of `table`, each offered the quantities of `mechanism`, showing the
  /// mapping its headers propose (kinematics/compare/header_mapping.h).
  void setTable(const kinematics::io::NumericTable& table, const kinematics::Mechanism& mechanism);

  /// Shows `mapping` (columns it does not name are not compared).
  void setMapping(const kinematics::compare::ColumnMapping& mapping);

  /// The mapping shown; the x column is absent when none is chosen, and an Error names a second one.
  kinematics::Result<kinematics::compare::ColumnMapping> mapping() const;

signals:
  void mappingChanged();

private:
  void fillUnits(int row);
  int roleIndex(int row) const;

  kinematics::Mechanism m_mechanism;
  std::vector<kinematics::compare::CompareQuantity> m_quantities;
};

}  // namespace linkwright::ui
