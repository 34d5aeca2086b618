#pragma once
// The candidates of a synthesis, one row each: its index ("best", 1, 2, …), the problem's
// error in its unit, the Grashof class, the worst transmission angle (°) and its defects by
// short name, the full reasons in the row's tooltip. A candidate with a defect is listed like
// any other, in the warning colour: the user decides.

#include "ui/synthesis/synthesis_outcome.h"

#include <QTableWidget>

#include <optional>

namespace linkwright::ui {

class CandidateTable : public QTableWidget {
  Q_OBJECT
public:
  enum Column { Index, Error, Grashof, Transmission, Defects };
  static constexpr int kColumnCount = 5;

  explicit CandidateTable(QWidget* parent = nullptr);

  /// Shows `outcome`'s rows and selects the first.
  void showOutcome(const SynthesisOutcome& outcome);
  /// Removes every row.
  void clearRows();
  /// The selected row, if any.
  std::optional<std::size_t> selectedRow() const;
  /// Selects row `row`.
  void selectRow(std::size_t row);
  /// Whether row `row` is drawn marked (it has a defect).
  bool isMarked(std::size_t row) const;

signals:
  /// The selection changed; nullopt when nothing is selected.
  void rowChosen(std::optional<std::size_t> row);
};

}  // namespace linkwright::ui
