#pragma once
// A small properties table for the dynamics panel: a name column, then number cells that may
// be unset, shown as the core's default in grey ("midpoint", "m·L²/12") and edited as empty.
// It only shows and reads text; the panel turns each committed cell into a design edit.

#include <QString>
#include <QStringList>
#include <QTableWidget>

#include <optional>
#include <vector>

namespace linkwright::ui {

class MassTable : public QTableWidget {
  Q_OBJECT
public:
  /// One number cell: its value, or unset (then `unsetText` is shown in grey).
  struct Cell {
    std::optional<double> value;
    QString unsetText;
    QString unsetToolTip;
  };

  /// Columns titled `headers` (the first holds the row names, read-only).
  explicit MassTable(const QStringList& headers, QWidget* parent = nullptr);

  /// Replaces the rows: one per name, with `cells[row]` in columns 1… . Emits nothing.
  void setRows(const QStringList& names, const std::vector<std::vector<Cell>>& cells);

  /// Retitles `column`; an unchanged title is left alone (a new header item re-lays out the panel).
  void setHeaderText(int column, const QString& text);

  /// The header and the first kRowsAlwaysShown rows, however the panel is squeezed.
  QSize minimumSizeHint() const override;
  static constexpr int kRowsAlwaysShown = 3;

  /// Text for a value in a cell: up to 6 significant digits, C locale ("0.0004", "17.5").
  static QString formatValue(double value);

protected:
  void changeEvent(QEvent* event) override;

signals:
  /// The user committed `text` in (row, column ≥ 1): `value` is its number, or unset for an
  /// empty cell. `parsed` is false when the text is not a number (value is then unset).
  void cellEdited(int row, int column, std::optional<double> value, bool parsed);

private:
  void onItemChanged(QTableWidgetItem* item);
  void keepRowsShown();
  bool m_filling = false;
};

}  // namespace linkwright::ui
