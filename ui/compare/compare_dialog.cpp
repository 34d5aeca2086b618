#include "ui/compare/compare_dialog.h"

#include "ui/colors.h"

#include "ui/compare/column_map_editor.h"
#include "ui/number_box.h"

#include "kinematics/model/number_text.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>

namespace linkwright::ui {
namespace {

namespace k = kinematics;
namespace kc = kinematics::compare;

QString number(double value, int significant = 6) { return QString::fromStdString(k::formatShort(value, significant)); }

QTableWidget* resultTable(const QStringList& headers, QWidget* parent) {
  auto* table = new QTableWidget(0, static_cast<int>(headers.size()), parent);
  table->setHorizontalHeaderLabels(headers);
  table->verticalHeader()->hide();
  table->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table->setSelectionBehavior(QAbstractItemView::SelectRows);
  table->setSelectionMode(QAbstractItemView::SingleSelection);
  table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  table->horizontalHeader()->setStretchLastSection(true);
  return table;
}

void setRow(QTableWidget* table, int row, const QStringList& cells, bool flagged) {
  for (int c = 0; c < cells.size(); ++c) {
    auto* item = new QTableWidgetItem(cells[c]);
    if (c > 0) item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
    if (flagged) item->setBackground(colors().flaggedRowBackground);
    table->setItem(row, c, item);
  }
}

QString layoutText(const k::io::NumericTable& t) {
  const QString delimiter = t.delimiter == '\t'  ? QObject::tr("tab-separated")
                            : t.delimiter == ';' ? QObject::tr("';'-separated")
                                                 : QObject::tr("comma-separated");
  return delimiter + (t.decimalComma ? QObject::tr(", decimal comma") : QString());
}

}  // namespace

CompareDialog::CompareDialog(const k::Design& design, const k::io::NumericTable& table, const QString& path,
                             QWidget* parent)
    : QDialog(parent), m_design(design), m_table(table), m_editor(new ColumnMapEditor(this)),
      m_offsetMode(new QComboBox(this)), m_offset(new NumberBox(this)), m_tolerance(new NumberBox(this)),
      m_message(new QLabel(this)), m_result(new QLabel(this)),
      m_summary(resultTable({tr("Column"), tr("Compared with"), tr("Rows"), tr("Worst"), tr("At x"), tr("RMS"),
                             tr("Tolerance"), tr("Flagged")},
                            this)),
      m_rows(resultTable(
          {tr("Line"), tr("x"), tr("Crank (°)"), tr("Value"), tr("Exact"), tr("Deviation"), tr("Offset fit")}, this)),
      m_drawOnPlots(new QCheckBox(tr("&Draw the rows on the plots"), this)) {
  setWindowTitle(tr("Compare with %1").arg(QFileInfo(path).fileName()));
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(new QLabel(tr("%1: %2 rows, %3 columns, %4. Map the x column (crank angle or time) and the columns "
                                  "to compare; each row is compared with the exact solution at its own input.")
                                   .arg(QFileInfo(path).fileName())
                                   .arg(table.rows.size())
                                   .arg(table.columns())
                                   .arg(layoutText(table)),
                               this));
  layout->itemAt(0)->widget()->setProperty("wordWrap", true);
  m_editor->setTable(table, design.mechanism);
  layout->addWidget(m_editor, 2);

  m_offsetMode->addItems({tr("Fitted (robust, ±5°)"), tr("None"), tr("Given")});
  m_offset->setRange(-5.0, 5.0);
  m_offset->setDecimals(4);
  m_offset->setSuffix(QStringLiteral("°"));
  m_offset->setEnabled(false);
  connect(m_offsetMode, &QComboBox::currentIndexChanged, this, [this](int i) { m_offset->setEnabled(i == 2); });
  m_tolerance->setRange(0.0, 100.0);
  m_tolerance->setDecimals(3);
  m_tolerance->setValue(kc::CompareOptions{}.relativeTolerance * 100.0);
  m_tolerance->setSuffix(tr(" % of span"));
  auto* compareButton = new QPushButton(tr("&Compare"), this);
  connect(compareButton, &QPushButton::clicked, this, &CompareDialog::compare);
  auto* options = new QHBoxLayout;
  options->addWidget(new QLabel(tr("Crank-angle offset:"), this));
  options->addWidget(m_offsetMode);
  options->addWidget(m_offset);
  options->addSpacing(16);
  options->addWidget(new QLabel(tr("Tolerance: rounding +"), this));
  options->addWidget(m_tolerance);
  options->addStretch();
  options->addWidget(compareButton);
  layout->addLayout(options);

  m_message->setStyleSheet("color: #b00020");
  m_message->setWordWrap(true);
  m_message->hide();
  layout->addWidget(m_message);
  m_result->setWordWrap(true);
  layout->addWidget(m_result);
  auto* splitter = new QSplitter(Qt::Vertical, this);
  splitter->addWidget(m_summary);
  splitter->addWidget(m_rows);
  layout->addWidget(splitter, 3);
  connect(m_summary, &QTableWidget::currentCellChanged, this, [this](int row) { showRows(row); });
  m_drawOnPlots->setChecked(true);
  m_drawOnPlots->setToolTip(
      tr("Each row as a marker over its quantity's curve, filled red where it is beyond the "
         "tolerance; it stays after this dialog closes, until unticked or another linkage "
         "is opened."));
  connect(m_drawOnPlots, &QCheckBox::toggled, this, &CompareDialog::emitPlotOverlay);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  auto* bottom = new QHBoxLayout;
  bottom->addWidget(m_drawOnPlots);
  bottom->addWidget(buttons);
  layout->addLayout(bottom);
  resize(900, 760);
}

kc::CompareOptions CompareDialog::options() const {
  kc::CompareOptions o;
  o.offset = m_offsetMode->currentIndex() == 0   ? kc::OffsetMode::Auto
             : m_offsetMode->currentIndex() == 1 ? kc::OffsetMode::None
                                                 : kc::OffsetMode::Given;
  o.offsetDeg = m_offset->value();
  o.relativeTolerance = m_tolerance->value() / 100.0;
  return o;
}

bool CompareDialog::compare() {
  const auto refuse = [this](const std::string& message) {
    m_message->setText(QString::fromStdString(message));
    m_message->show();
    return false;
  };
  const auto mapping = m_editor->mapping();
  if (!mapping) return refuse(mapping.error().message);
  const auto result = kc::compareTable(m_design.mechanism, kc::compareDriveFor(m_design), m_table, *mapping, options());
  if (!result) return refuse(result.error().message);
  m_message->hide();
  m_comparison = *result;
  showSummary();
  emitPlotOverlay();
  return true;
}

void CompareDialog::emitPlotOverlay() {
  emit plotOverlayChanged(m_drawOnPlots->isChecked() ? m_comparison : std::nullopt);
}

void CompareDialog::showSummary() {
  const kc::Comparison& c = *m_comparison;
  QString offset =
      c.offsetMode == kc::OffsetMode::None
          ? tr("no crank-angle offset")
          : tr("crank-angle offset %1°%2")
                .arg(number(c.offsetDeg, 4))
                .arg(c.offsetMode == kc::OffsetMode::Auto
                         ? tr(" (fitted to the %1)").arg(c.offsetFromPositions ? tr("position columns") : tr("columns"))
                         : QString());
  if (c.offsetKeptZero) offset += tr(", zero kept: no offset halves the misfit of the rows that agree");
  if (c.offsetAtBound) offset += tr(", at the bound: the table may be shifted further or mapped wrong");
  int leftOut = 0;
  for (const kc::ColumnComparison& column : c.columns)
    for (const kc::RowComparison& row : column.rows) leftOut += row.outsideFit ? 1 : 0;
  if (leftOut > 0) offset += tr(", %n value(s) left out of the fit", nullptr, leftOut);
  m_result->setText(c.flaggedRows() == 0
                        ? tr("%1. Every row agrees within the tolerance.").arg(offset)
                        : tr("%1. %2 values beyond the tolerance, highlighted.").arg(offset).arg(c.flaggedRows()));
  m_summary->setRowCount(static_cast<int>(c.columns.size()));
  for (int i = 0; i < m_summary->rowCount(); ++i) {
    const kc::ColumnComparison& col = c.columns[static_cast<std::size_t>(i)];
    setRow(m_summary, i,
           {QString("%1: %2").arg(col.mapped.column + 1).arg(QString::fromStdString(col.label)),
            QString::fromStdString(col.mapped.describe()), QString::number(col.compared), number(col.worst, 4),
            number(col.worstX), number(col.rms, 4), number(col.tolerance, 3), QString::number(col.flagged)},
           col.flagged > 0);
  }
  int first = 0;  // the first column with flagged rows, else the first
  for (int i = 0; i < m_summary->rowCount(); ++i)
    if (c.columns[static_cast<std::size_t>(i)].flagged > 0) {
      first = i;
      break;
    }
  m_summary->setCurrentCell(first, 0);
  showRows(first);
}

void CompareDialog::showRows(int column) {
  if (!m_comparison || column < 0 || column >= static_cast<int>(m_comparison->columns.size())) return;
  const kc::ColumnComparison& col = m_comparison->columns[static_cast<std::size_t>(column)];
  m_rows->setRowCount(static_cast<int>(col.rows.size()));
  for (int i = 0; i < m_rows->rowCount(); ++i) {
    const kc::RowComparison& r = col.rows[static_cast<std::size_t>(i)];
    setRow(m_rows, i,
           {QString::number(r.line), number(r.x), number(r.inputDeg, 7), number(r.value),
            r.exact ? number(*r.exact) : tr("none"), r.exact ? number(r.deviation, 4) : QString::fromStdString(r.note),
            r.outsideFit ? tr("left out") : QString()},
           r.flagged);
  }
}

}  // namespace linkwright::ui
