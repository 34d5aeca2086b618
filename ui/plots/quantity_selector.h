#pragma once
// A row of checkboxes choosing which quantities the plots show (and so which ones the sweep
// computes), grouped by chart: angles, ω, α, then slider positions, velocities and
// accelerations. The boxes follow the mechanism's quantities (setCurves).

#include "ui/plots/plot_quantity.h"

#include <QWidget>

#include <vector>

class QCheckBox;

namespace linkwright::ui {

class FlowLayout;

class QuantitySelector : public QWidget {
  Q_OBJECT
public:
  explicit QuantitySelector(QWidget* parent = nullptr);

  /// One box per curve, named "show_<key>" ("show_rocker_omega"), ticked as `selection` says.
  void setCurves(const std::vector<PlotCurve>& curves, const QuantitySelection& selection);
  const std::vector<PlotCurve>& curves() const { return m_curves; }

  /// What is ticked; quantities without a box keep the state they had.
  QuantitySelection selection() const { return m_selection; }
  /// Ticks the boxes to match; emits selectionChanged once if anything changed.
  void setSelection(const QuantitySelection& selection);
  /// The box of `quantity`, or null if the mechanism has no such quantity.
  QCheckBox* checkBox(PlotQuantity quantity) const;

signals:
  void selectionChanged();

private:
  FlowLayout* m_flow;
  std::vector<PlotCurve> m_curves;
  std::vector<QCheckBox*> m_boxes;  // per curve
  std::vector<QWidget*> m_groups;   // one per box (the first of a chart with its label)
  QuantitySelection m_selection;
  bool m_applying = false;
};

}  // namespace linkwright::ui
