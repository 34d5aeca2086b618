#pragma once
// View ▸ Inversions… (issue 21, the classroom): the designer's four-bar or slider-crank with
// each of its links grounded in turn, side by side in a 2×2 grid (InversionCellPanel): each
// cell names the grounded link and the inversion's textbook class (from the core,
// kinematics/analysis/inversions.h) and animates it; one Play / Pause button and one Step
// button drive the four together. A physical link keeps its colour in every cell. The window
// follows the designer's document: when its design changes, the cells are rebuilt; a linkage
// that has no inversions to show leaves the window saying why. Not modal.

#include <QWidget>

#include <array>

class QLabel;
class QPushButton;

namespace linkwright::ui {

class InversionCellPanel;
class MechanismDocument;

class InversionsWindow : public QWidget {
  Q_OBJECT
public:
  explicit InversionsWindow(MechanismDocument* source, QWidget* parent = nullptr);

  static constexpr int kCells = 4;
  InversionCellPanel* cell(int index) const { return m_cells[static_cast<std::size_t>(index)]; }
  /// The chain and its lengths, or why there are no inversions.
  QString headingText() const;
  /// How many times the cells were rebuilt from the source document (tests read it).
  int rebuilds() const { return m_rebuilds; }
  bool isPlaying() const { return m_playing; }

public slots:
  void play();
  void pause();
  void togglePlay();
  /// Every cell's crank one step (30°) on; a rocking crank turns back at an end.
  void step();

protected:
  void hideEvent(QHideEvent* event) override;

private:
  void rebuild();

  MechanismDocument* m_source;
  std::array<InversionCellPanel*, kCells> m_cells{};
  QLabel* m_heading;
  QWidget* m_grid;
  QPushButton* m_play;
  QPushButton* m_step;
  bool m_playing = false;
  int m_rebuilds = 0;
};

}  // namespace linkwright::ui
