#pragma once
// A row of checkboxes choosing which quantities the plots show (and so which ones the sweep
// computes), grouped by chart: angles, ω, α.

#include "ui/plots/plot_quantity.h"

#include <QWidget>

#include <array>

class QCheckBox;

namespace linkwright::ui {

class QuantitySelector : public QWidget {
  Q_OBJECT
public:
  /// Starts with everything selected. Each box is named "show_<key>" ("show_rocker_omega").
  explicit QuantitySelector(QWidget* parent = nullptr);

  QuantitySelection selection() const;
  /// Ticks the boxes to match; emits selectionChanged once if anything changed.
  void setSelection(const QuantitySelection& selection);
  QCheckBox* checkBox(PlotQuantity quantity) const;

signals:
  void selectionChanged();

private:
  std::array<QCheckBox*, kPlotQuantityCount> m_boxes{};
  bool m_applying = false;
};

} // namespace linkwright::ui
