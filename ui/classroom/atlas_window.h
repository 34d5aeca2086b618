#pragma once
// View ▸ Atlas… (issue 46): a coupler-curve atlas in the spirit of Hrones and Nelson
// (kinematics/explore/coupler_atlas.h). The link ratios and coupler-point places are typed as
// comma lists; Show lays out one small drawing per cell, in the core's order, each computed on
// a worker thread and kept by its key (atlas_cell_cache.h), so typing the same ratios back or
// changing the filter draws at once. The filter's boxes keep the cells whose curve has every
// feature ticked (kinematics/explore/atlas_filter.h). A click on a cell makes its four-bar the
// design, with its coupler point P, one undoable edit, the crank as long as the design's own
// four-bar's (or 20 length units); Ctrl+Z and Ctrl+Shift+Z here are the designer's Undo and
// Redo. Closing the window, or a new grid, stops what is computing.
// Not modal.

#include "kinematics/explore/atlas_filter.h"
#include "kinematics/explore/coupler_atlas.h"

#include <QWidget>

#include <array>
#include <vector>

class QCheckBox;
class QGridLayout;
class QLabel;
class QLineEdit;
class QPushButton;
class QScrollArea;

namespace linkwright::ui {

class AtlasCellCache;
class AtlasCellView;
class MechanismDocument;

class AtlasWindow : public QWidget {
  Q_OBJECT
public:
  explicit AtlasWindow(MechanismDocument* document, QWidget* parent = nullptr);

  /// The grid's axes' fields: coupler, rocker, frame, along, across.
  QLineEdit* axisField(int axis) const { return m_fields[static_cast<std::size_t>(axis)]; }
  QPushButton* showButton() const { return m_show; }
  /// The filter's boxes: cusp, crunode, symmetric, straight, circular.
  QCheckBox* filterBox(int feature) const { return m_filters[static_cast<std::size_t>(feature)]; }
  /// Every cell of the grid shown, in the core's order (those the filter hides too).
  const std::vector<AtlasCellView*>& cells() const { return m_cells; }
  /// The cells the filter keeps, in order.
  std::vector<AtlasCellView*> shownCells() const;
  const kinematics::AtlasAxes& axes() const { return m_axes; }
  kinematics::AtlasFilter filter() const;
  /// True when every cell of the grid is computed.
  bool complete() const;
  QString statusText() const;
  QString refusal() const;
  AtlasCellCache* cache() const { return m_cache; }

public slots:
  /// Reads the fields and lays out their grid (or says why not, keeping the grid shown).
  void showGrid();
  /// Makes cell `index` the design (one undoable edit).
  void load(std::size_t index);

protected:
  void hideEvent(QHideEvent* event) override;
  void showEvent(QShowEvent* event) override;

private:
  void relayout();
  void updateStatus();
  void onCellReady(const kinematics::AtlasCell& cell);
  void requestMissing();

  MechanismDocument* m_document;
  AtlasCellCache* m_cache;
  std::array<QLineEdit*, 5> m_fields{};
  std::array<QCheckBox*, 5> m_filters{};
  QPushButton* m_show;
  QLabel* m_status;
  QLabel* m_refusal;
  QScrollArea* m_scroll;
  QWidget* m_grid;
  QGridLayout* m_layout;
  kinematics::AtlasAxes m_axes;
  std::vector<AtlasCellView*> m_cells;
};

}  // namespace linkwright::ui
