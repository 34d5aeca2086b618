#include "ui/synthesis/candidate_table.h"

#include "ui/colors.h"
#include "ui/number_text.h"

#include "kinematics/model/units.h"

#include <QHeaderView>
#include <QSignalBlocker>

namespace linkwright::ui {

namespace k = kinematics;

namespace {

QTableWidgetItem* cell(const QString& text, Qt::Alignment alignment = Qt::AlignRight | Qt::AlignVCenter) {
  auto* item = new QTableWidgetItem(text);
  item->setFlags(Qt::ItemIsSelectable | Qt::ItemIsEnabled);
  item->setTextAlignment(alignment);
  return item;
}

QString grashofText(const k::SynthesisCandidate& c) {
  if (!c.grashof) return QStringLiteral("—");
  return QString::fromUtf8(k::toString(c.grashof->category).data(),
                           static_cast<int>(k::toString(c.grashof->category).size()));
}

}  // namespace

CandidateTable::CandidateTable(QWidget* parent) : QTableWidget(0, kColumnCount, parent) {
  setHorizontalHeaderLabels({tr("#"), tr("Error"), tr("Grashof"), tr("Min μ (°)"), tr("Defects")});
  setSelectionBehavior(SelectRows);
  setSelectionMode(SingleSelection);
  setEditTriggers(NoEditTriggers);
  verticalHeader()->hide();
  horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  horizontalHeader()->setSectionResizeMode(Defects, QHeaderView::Stretch);
  setWordWrap(false);
  connect(this, &QTableWidget::itemSelectionChanged, this, [this] { emit rowChosen(selectedRow()); });
}

void CandidateTable::clearRows() {
  setRowCount(0);
  emit rowChosen(std::nullopt);
}

void CandidateTable::showOutcome(const SynthesisOutcome& outcome) {
  {
    const QSignalBlocker quiet(this);
    setRowCount(0);
    setHorizontalHeaderItem(
        Error, new QTableWidgetItem(outcome.exact ? tr("Error") : tr("Error (%1)").arg(outcome.errorUnit)));
    setRowCount(static_cast<int>(outcome.rows.size()));
    for (std::size_t i = 0; i < outcome.rows.size(); ++i) {
      const SynthesisRow& row = outcome.rows[i];
      const k::SynthesisCandidate& c = row.candidate;
      const int r = static_cast<int>(i);
      QStringList names, reasons;
      for (const k::Defect& d : c.defects) {
        names << QString::fromUtf8(k::toString(d.kind).data(), static_cast<int>(k::toString(d.kind).size()));
        reasons << QString::fromStdString(d.message);
      }
      const bool marked = !c.defects.empty();
      setItem(r, Index, cell(marked ? QStringLiteral("⚠ ") + row.label : row.label, Qt::AlignLeft | Qt::AlignVCenter));
      setItem(r, Error, cell(outcome.exact ? tr("exact") : numberText(c.error * outcome.errorScale, 'g', 4)));
      setItem(r, Grashof, cell(grashofText(c), Qt::AlignLeft | Qt::AlignVCenter));
      setItem(r, Transmission, cell(numberText(k::radToDeg(c.minTransmission), 'f', 1)));
      setItem(r, Defects,
              cell(marked ? names.join(QStringLiteral(", ")) : tr("none"), Qt::AlignLeft | Qt::AlignVCenter));
      const QString tip = marked ? reasons.join(QLatin1Char('\n')) : tr("No defect found");
      for (int col = 0; col < kColumnCount; ++col) {
        item(r, col)->setToolTip(tip);
        // The colour the panels already warn with (a crank that cannot turn fully).
        if (marked) item(r, col)->setForeground(colors().grashofRockerBadge);
        item(r, col)->setData(Qt::UserRole, marked);
      }
    }
  }
  if (rowCount() > 0) selectRow(0);
  else emit rowChosen(std::nullopt);
}

std::optional<std::size_t> CandidateTable::selectedRow() const {
  const QModelIndexList rows = selectionModel()->selectedRows();
  if (rows.isEmpty()) return std::nullopt;
  return static_cast<std::size_t>(rows.front().row());
}

void CandidateTable::selectRow(std::size_t row) {
  if (static_cast<int>(row) >= rowCount()) return;
  QTableWidget::selectRow(static_cast<int>(row));
}

bool CandidateTable::isMarked(std::size_t row) const {
  const QTableWidgetItem* it = item(static_cast<int>(row), Index);
  return it != nullptr && it->data(Qt::UserRole).toBool();
}

}  // namespace linkwright::ui
