#include "ui/synthesis/target_table.h"

#include "kinematics/design/synthesis_ranges.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QLocale>
#include <QPushButton>
#include <QSignalBlocker>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <functional>

namespace linkwright::ui {

namespace k = kinematics;

TargetTable::TargetTable(const QStringList& headers, const QString& rowName, int minRows, int maxRows, QWidget* parent)
    : QWidget(parent), m_table(new QTableWidget(0, static_cast<int>(headers.size()), this)),
      m_add(new QPushButton(tr("Add"), this)), m_remove(new QPushButton(tr("Remove"), this)),
      m_pick(new QPushButton(tr("Pick on canvas"), this)), m_rowName(rowName), m_minRows(minRows), m_maxRows(maxRows) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  m_table->setHorizontalHeaderLabels(headers);
  m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
  m_table->verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
  layout->addWidget(m_table);
  auto* buttons = new QHBoxLayout;
  m_add->setToolTip(tr("Append a row: a copy of the last one"));
  m_remove->setToolTip(tr("Remove the selected rows (or the last one)"));
  m_pick->setCheckable(true);
  m_pick->setObjectName(QStringLiteral("pick"));
  buttons->addWidget(m_add);
  buttons->addWidget(m_remove);
  buttons->addStretch();
  buttons->addWidget(m_pick);
  layout->addLayout(buttons);

  connect(m_table, &QTableWidget::itemChanged, this, [this] {
    if (!m_filling) emit edited();
  });
  connect(m_add, &QPushButton::clicked, this, [this] {
    const int last = m_table->rowCount() - 1;
    std::vector<double> copy(static_cast<std::size_t>(m_table->columnCount()), 0.0);
    for (int c = 0; last >= 0 && c < m_table->columnCount(); ++c)
      if (const QTableWidgetItem* item = m_table->item(last, c))
        copy[static_cast<std::size_t>(c)] = item->text().toDouble();
    appendRow(copy);
  });
  connect(m_remove, &QPushButton::clicked, this, [this] {
    QList<int> rows;
    for (const QModelIndex& index : m_table->selectionModel()->selectedRows()) rows << index.row();
    if (rows.isEmpty() && m_table->rowCount() > 0) rows << m_table->rowCount() - 1;
    std::sort(rows.begin(), rows.end(), std::greater<>());
    for (const int r : rows) m_table->removeRow(r);
    updateButtons();
    emit edited();
  });
  connect(m_pick, &QPushButton::toggled, this, &TargetTable::pickToggled);
  updateButtons();
}

int TargetTable::rowCount() const { return m_table->rowCount(); }

void TargetTable::setRows(const std::vector<std::vector<double>>& rows) {
  m_filling = true;
  m_table->setRowCount(0);
  for (std::size_t r = 0; r < rows.size(); ++r) {
    m_table->insertRow(static_cast<int>(r));
    setRow(static_cast<int>(r), rows[r]);
  }
  m_filling = false;
  updateButtons();
  emit edited();
}

bool TargetTable::appendRow(const std::vector<double>& values) {
  if (m_table->rowCount() >= m_maxRows) return false;
  m_filling = true;
  const int row = m_table->rowCount();
  m_table->insertRow(row);
  setRow(row, values);
  m_filling = false;
  updateButtons();
  emit edited();
  return true;
}

void TargetTable::setRow(int row, const std::vector<double>& values) {
  for (int c = 0; c < m_table->columnCount(); ++c) {
    const double v = static_cast<std::size_t>(c) < values.size() ? values[static_cast<std::size_t>(c)] : 0.0;
    m_table->setItem(row, c, new QTableWidgetItem(QString::number(v, 'g', 6)));
  }
}

void TargetTable::updateButtons() {
  m_add->setEnabled(m_table->rowCount() < m_maxRows);
  m_remove->setEnabled(m_table->rowCount() > 0);
}

k::Result<std::vector<std::vector<double>>> TargetTable::values(int skipColumn) const {
  const int rows = m_table->rowCount();
  if (rows < m_minRows || rows > m_maxRows)
    return k::Error{
        k::ErrorCode::InvalidValue, "points",
        tr("Targets: %1 to %2 rows are needed (got %3)").arg(m_minRows).arg(m_maxRows).arg(rows).toStdString()};
  std::vector<std::vector<double>> out;
  for (int r = 0; r < rows; ++r) {
    std::vector<double> row;
    for (int c = 0; c < m_table->columnCount(); ++c) {
      if (c == skipColumn) {
        row.push_back(0.0);
        continue;
      }
      const QTableWidgetItem* item = m_table->item(r, c);
      const QString text = item ? item->text().trimmed() : QString();
      bool ok = false;
      double v = QLocale::c().toDouble(text, &ok);
      if (!ok) v = QLocale().toDouble(text, &ok);
      if (!ok || !std::isfinite(v))
        return k::Error{k::ErrorCode::InvalidValue, "points",
                        tr("%1, %2: “%3” is not a number")
                            .arg(rowLabel(r), m_table->horizontalHeaderItem(c)->text(), text)
                            .toStdString()};
      // The range of the forms' fields, which a document keeps (synthesis_ranges.h).
      if (std::abs(v) > k::kMaxTargetValue)
        return k::Error{k::ErrorCode::InvalidValue, "points",
                        tr("%1, %2: must be within ±1e9 (got %3)")
                            .arg(rowLabel(r), m_table->horizontalHeaderItem(c)->text(), text)
                            .toStdString()};
      row.push_back(v);
    }
    out.push_back(std::move(row));
  }
  return out;
}

}  // namespace linkwright::ui
