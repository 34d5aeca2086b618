#pragma once
// The live plots: link angles and transmission angle, ω and α of coupler and rocker against
// crank angle, one chart each, stacked so they read together. A row of checkboxes picks the
// quantities; the document is asked to compute only what is shown. Curves are re-read from
// the document's sweep when the design or request changes; a crank move only moves the
// cursor on each chart. Hovering a curve reads its value out; the rocker's limit positions
// are marked on the angle chart.

#include "ui/plots/angle_unit.h"
#include "ui/plots/plot_quantity.h"

#include "ui/document/mechanism_document.h"

#include <QList>
#include <QWidget>

#include <array>
#include <memory>

class QChartView;

class QGraphicsView;

namespace linkwright::ui {

class HoverReadout;
class LimitMarkers;
class QuantityChartView;
class QuantitySelector;

class PlotPanel : public QWidget {
  Q_OBJECT
public:
  explicit PlotPanel(MechanismDocument* document, QWidget* parent = nullptr);
  ~PlotPanel() override;

  /// Unit of every angular quantity shown (x axis included). Degrees by default.
  void setAngleUnit(AngleUnit unit);
  AngleUnit angleUnit() const { return m_unit; }

  /// The charts in display order (angles, ω, α), for image export. A chart with nothing
  /// selected isHidden().
  QList<QChartView*> chartViews() const;
  /// The same views as plain QGraphicsViews, so code outside ui/plots can export them
  /// without depending on Qt Charts.
  QList<QGraphicsView*> graphicsViews() const;
  /// The title of chartViews()[index] ("Link angles", ...); empty for an index out of range.
  QString chartTitle(int index) const;

  /// The quantities shown; setting it ticks the boxes (and emits selectionChanged if it differs).
  QuantitySelection selection() const;
  void setSelection(const QuantitySelection& selection);

  /// The chart for one kind of quantity.
  QuantityChartView* chartView(QuantityKind kind) const;
  LimitMarkers* limitMarkers() const { return m_limits.get(); }
  HoverReadout* hoverReadout() const { return m_readout; }
  QuantitySelector* selector() const { return m_selector; }

signals:
  /// The user (or setSelection) changed which quantities are shown.
  void selectionChanged();

private:
  void onDocumentChanged(Changes what);
  void onSelectionChanged();
  void applySelection();
  void refreshData();
  void refreshCursor();
  void alignCharts();

  MechanismDocument* m_document;
  AngleUnit m_unit = AngleUnit::Degrees;
  QuantitySelector* m_selector;
  std::array<QuantityChartView*, kQuantityKindCount> m_views{};
  std::unique_ptr<LimitMarkers> m_limits;
  HoverReadout* m_readout;
};

} // namespace linkwright::ui
