#include "ui/classroom/inversions_window.h"

#include "ui/animation/crank_animator.h"
#include "ui/classroom/inversion_cell_panel.h"
#include "ui/classroom/inversion_cells.h"
#include "ui/document/mechanism_document.h"

#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace linkwright::ui {

InversionsWindow::InversionsWindow(MechanismDocument* source, QWidget* parent)
    : QWidget(parent, Qt::Window), m_source(source), m_heading(new QLabel(this)), m_grid(new QWidget(this)),
      m_play(new QPushButton(tr("Play"), this)), m_step(new QPushButton(tr("Step"), this)) {
  setObjectName("InversionsWindow");
  setWindowTitle(tr("Inversions — Linkwright"));
  m_heading->setWordWrap(true);
  m_heading->setTextFormat(Qt::PlainText);
  m_play->setObjectName("InversionsPlay");
  m_step->setObjectName("InversionsStep");
  m_step->setToolTip(tr("Turn every driven link on by 30°; one that cannot turn fully turns back at an end"));
  auto* grid = new QGridLayout(m_grid);
  grid->setContentsMargins(0, 0, 0, 0);
  for (int i = 0; i < kCells; ++i) {
    m_cells[static_cast<std::size_t>(i)] = new InversionCellPanel(m_grid);
    grid->addWidget(m_cells[static_cast<std::size_t>(i)], i / 2, i % 2);
  }
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(m_play);
  buttons->addWidget(m_step);
  buttons->addStretch();
  auto* hint = new QLabel(tr("Each cell holds a different link fixed; the fixed link is drawn grey, as the frame. "
                             "Every moving link keeps its colour in all four: crank orange, coupler (rod) blue, "
                             "rocker green, and the original frame, once it moves, brown."),
                          this);
  hint->setWordWrap(true);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(m_heading);
  layout->addWidget(hint);
  layout->addWidget(m_grid, 1);
  layout->addLayout(buttons);
  connect(m_play, &QPushButton::clicked, this, &InversionsWindow::togglePlay);
  connect(m_step, &QPushButton::clicked, this, &InversionsWindow::step);
  connect(m_source, &MechanismDocument::changed, this, [this](Changes what) {
    if (what & Change::Design) rebuild();
  });
  resize(1000, 820);
  rebuild();
}

QString InversionsWindow::headingText() const { return m_heading->text(); }

void InversionsWindow::rebuild() {
  ++m_rebuilds;
  const InversionSet set = inversionSet(m_source->design());
  const bool any = set.unavailable.isEmpty();
  m_heading->setText(any ? set.heading : set.unavailable);
  m_grid->setVisible(any);
  m_play->setEnabled(any);
  m_step->setEnabled(any);
  if (!any) {
    pause();
    return;
  }
  for (std::size_t i = 0; i < m_cells.size() && i < set.cells.size(); ++i) m_cells[i]->setCell(set.cells[i]);
  if (m_playing)
    for (InversionCellPanel* cell : m_cells)
      if (cell->hasLinkage()) cell->animator()->play();
}

void InversionsWindow::play() {
  m_playing = true;
  for (InversionCellPanel* cell : m_cells)
    if (cell->hasLinkage()) cell->animator()->play();
  m_play->setText(tr("Pause"));
}

void InversionsWindow::pause() {
  m_playing = false;
  for (InversionCellPanel* cell : m_cells) cell->animator()->pause();
  m_play->setText(tr("Play"));
}

void InversionsWindow::togglePlay() { m_playing ? pause() : play(); }

void InversionsWindow::step() {
  for (InversionCellPanel* cell : m_cells)
    if (cell->hasLinkage()) cell->animator()->stepForward();
}

// Nobody watches a hidden window: it stops, and plays again when asked.
void InversionsWindow::hideEvent(QHideEvent* event) {
  pause();
  QWidget::hideEvent(event);
}

}  // namespace linkwright::ui
