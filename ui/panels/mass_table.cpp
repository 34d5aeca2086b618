#include "ui/panels/mass_table.h"

#include "ui/number_text.h"

#include <QEvent>
#include <QHeaderView>
#include <QLineEdit>
#include <QLocale>
#include <QStyledItemDelegate>

#include <algorithm>

namespace linkwright::ui {

namespace {

// Marks a cell that shows a default rather than a value.
constexpr int kUnsetRole = Qt::UserRole + 1;

// Opens a default cell with an empty editor, so typing replaces "midpoint" rather than
// appending to it.
class UnsetAwareDelegate : public QStyledItemDelegate {
public:
  using QStyledItemDelegate::QStyledItemDelegate;
  void setEditorData(QWidget* editor, const QModelIndex& index) const override {
    if (index.data(kUnsetRole).toBool()) {
      if (auto* line = qobject_cast<QLineEdit*>(editor)) {
        line->clear();
        return;
      }
    }
    QStyledItemDelegate::setEditorData(editor, index);
  }
};

std::optional<double> parseNumber(const QString& text, bool& parsed) {
  bool ok = false;
  double value = text.trimmed().toDouble(&ok);  // C locale first: files and the CLI write "0.5"
  if (!ok) value = QLocale().toDouble(text.trimmed(), &ok);
  parsed = ok;
  return ok ? std::optional<double>(value) : std::nullopt;
}

}  // namespace

MassTable::MassTable(const QStringList& headers, QWidget* parent) : QTableWidget(parent) {
  setColumnCount(static_cast<int>(headers.size()));
  setHorizontalHeaderLabels(headers);
  setItemDelegate(new UnsetAwareDelegate(this));
  verticalHeader()->setVisible(false);
  // Names take what they need; the number columns share the rest, so nothing scrolls sideways.
  horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
  horizontalHeader()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
  // A number column as narrow as "00.00", a longer text elided with its whole text in the
  // cell's tooltip: a projector's narrow side column holds all five. Narrower still (presentation
  // mode's large text), the table scrolls sideways rather than cut a column off.
  horizontalHeader()->setMinimumSectionSize(fontMetrics().horizontalAdvance(QStringLiteral("00.00")) + 6);
  setTextElideMode(Qt::ElideRight);
  setHorizontalScrollBarPolicy(Qt::ScrollBarAsNeeded);
  setSelectionMode(QAbstractItemView::SingleSelection);
  setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed |
                  QAbstractItemView::AnyKeyPressed);
  setVerticalScrollBarPolicy(Qt::ScrollBarAsNeeded);
  setSizeAdjustPolicy(QAbstractScrollArea::AdjustToContents);
  connect(this, &QTableWidget::itemChanged, this, &MassTable::onItemChanged);
}

QSize MassTable::minimumSizeHint() const {
  // Never a sliver (presentation mode's larger text squeezed it to its header): the header and
  // the first three rows stay, the rest behind the scroll bar. From the font as well as the
  // sections: after a font change the sections take their new sizes only when next laid out.
  const int line = fontMetrics().height();
  int height = std::max(horizontalHeader()->sizeHint().height(), 2 * line + 8) + 2 * frameWidth();
  for (int row = 0; row < std::min(rowCount(), kRowsAlwaysShown); ++row) height += std::max(rowHeight(row), line + 8);
  return {QTableWidget::minimumSizeHint().width(), height};
}

void MassTable::changeEvent(QEvent* event) {
  QTableWidget::changeEvent(event);
  // A larger font (presentation mode) makes the header and rows taller: the minimum with them.
  if (event->type() == QEvent::FontChange || event->type() == QEvent::StyleChange) keepRowsShown();
}

// As an explicit minimum: a layout caches a widget's minimumSizeHint, and the header's and
// rows' sizes follow a font change only later.
void MassTable::keepRowsShown() {
  setMinimumHeight(minimumSizeHint().height());
  updateGeometry();
}

void MassTable::setHeaderText(int column, const QString& text) {
  if (const QTableWidgetItem* header = horizontalHeaderItem(column); header != nullptr && header->text() == text)
    return;
  setHorizontalHeaderItem(column, new QTableWidgetItem(text));
}

QString MassTable::formatValue(double value) { return numberText(value, 'g', 6); }

void MassTable::setRows(const QStringList& names, const std::vector<std::vector<Cell>>& cells) {
  m_filling = true;
  // A refresh that changes nothing must not re-lay out the panel: only a new row or a new
  // text can change the table's size.
  bool resized = rowCount() != static_cast<int>(names.size());
  setRowCount(static_cast<int>(names.size()));
  QFont unsetFont = font();
  unsetFont.setItalic(true);
  // Items are updated in place, never replaced: a refresh may run inside the itemChanged
  // handler of the very item being edited.
  const auto itemAt = [this](int row, int column) {
    QTableWidgetItem* it = item(row, column);
    if (it == nullptr) {
      it = new QTableWidgetItem;
      setItem(row, column, it);
    }
    return it;
  };
  for (int row = 0; row < rowCount(); ++row) {
    QTableWidgetItem* name = itemAt(row, 0);
    resized = resized || name->text() != names[row];
    name->setText(names[row]);
    if (name->flags() != Qt::ItemIsEnabled) name->setFlags(Qt::ItemIsEnabled);  // setFlags always signals
    const auto& rowCells = cells[static_cast<std::size_t>(row)];
    for (int column = 1; column < columnCount(); ++column) {
      const auto index = static_cast<std::size_t>(column - 1);
      const Cell cell = index < rowCells.size() ? rowCells[index] : Cell{};
      QTableWidgetItem* it = itemAt(row, column);
      it->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
      it->setData(kUnsetRole, !cell.value.has_value());
      const QString text = cell.value ? formatValue(*cell.value) : cell.unsetText;
      resized = resized || it->text() != text;
      it->setText(text);
      it->setFont(cell.value ? font() : unsetFont);
      it->setForeground(palette().color(cell.value ? QPalette::Active : QPalette::Disabled, QPalette::Text));
      it->setToolTip(cell.value ? text : cell.unsetToolTip);
    }
  }
  m_filling = false;
  if (resized) keepRowsShown();
}

void MassTable::onItemChanged(QTableWidgetItem* item) {
  if (m_filling || item->column() == 0) return;
  bool parsed = true;
  const QString text = item->text().trimmed();
  const std::optional<double> value = text.isEmpty() ? std::nullopt : parseNumber(text, parsed);
  emit cellEdited(item->row(), item->column(), value, parsed);
}

}  // namespace linkwright::ui
