#include "ui/classroom/atlas_window.h"

#include "ui/classroom/atlas_cell_cache.h"
#include "ui/classroom/atlas_cell_view.h"
#include "ui/document/mechanism_document.h"
#include "ui/number_text.h"

#include "kinematics/model/recognise.h"

#include <QCheckBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QShortcut>
#include <QUndoStack>
#include <QVBoxLayout>

namespace linkwright::ui {

namespace k = kinematics;

namespace {

constexpr int kColumns = 6;
constexpr double kCrankWithoutFourBar = 20.0;  // length units, when the design is no four-bar

QString listText(const std::vector<double>& values) {
  QStringList parts;
  for (const double v : values) parts << numberText(v, 'g', 6);
  return parts.join(QLatin1Char(','));
}

// The comma list typed, or the word that is not a number.
std::optional<std::vector<double>> parseList(const QString& text, QString& bad) {
  std::vector<double> values;
  for (const QString& part : text.split(QLatin1Char(','))) {
    bool ok = false;
    const double v = QLocale::c().toDouble(part.trimmed(), &ok);
    if (!ok) {
      bad = part.trimmed();
      return std::nullopt;
    }
    values.push_back(v);
  }
  return values;
}

}  // namespace

AtlasWindow::AtlasWindow(MechanismDocument* document, QWidget* parent)
    : QWidget(parent, Qt::Window), m_document(document), m_cache(new AtlasCellCache(this)),
      m_show(new QPushButton(tr("Show"))), m_status(new QLabel), m_refusal(new QLabel), m_scroll(new QScrollArea),
      m_grid(new QWidget), m_layout(new QGridLayout(m_grid)) {
  setWindowTitle(tr("Coupler-curve atlas"));
  const std::array<QString, 5> names{tr("Coupler"), tr("Rocker"), tr("Frame"), tr("Along"), tr("Across")};
  const std::array<QString, 5> tips{tr("Coupler lengths over the crank's, separated by commas"),
                                    tr("Rocker lengths over the crank's"), tr("Frame lengths over the crank's"),
                                    tr("P's place along B→C, in coupler lengths"),
                                    tr("P's place 90° counter-clockwise from B→C, in coupler lengths")};
  auto* fields = new QHBoxLayout;
  const std::array<const std::vector<double>*, 5> values{&m_axes.coupler, &m_axes.rocker, &m_axes.frame, &m_axes.along,
                                                         &m_axes.across};
  for (std::size_t i = 0; i < 5; ++i) {
    auto* label = new QLabel(names[i]);
    m_fields[i] = new QLineEdit(listText(*values[i]));
    m_fields[i]->setToolTip(tips[i]);
    m_fields[i]->setObjectName(QStringLiteral("atlasAxis%1").arg(i));
    label->setBuddy(m_fields[i]);
    fields->addWidget(label);
    fields->addWidget(m_fields[i], 1);
    connect(m_fields[i], &QLineEdit::returnPressed, this, &AtlasWindow::showGrid);
  }
  fields->addWidget(m_show);
  connect(m_show, &QPushButton::clicked, this, &AtlasWindow::showGrid);

  auto* filters = new QHBoxLayout;
  filters->addWidget(new QLabel(tr("Only curves with:")));
  const std::array<QString, 5> features{tr("a cusp"), tr("a crunode"), tr("symmetry"), tr("a straight run"),
                                        tr("a circular arc")};
  for (std::size_t i = 0; i < 5; ++i) {
    m_filters[i] = new QCheckBox(features[i]);
    filters->addWidget(m_filters[i]);
    connect(m_filters[i], &QCheckBox::toggled, this, [this] {
      relayout();
      updateStatus();
    });
  }
  filters->addStretch(1);

  m_refusal->setStyleSheet(QStringLiteral("color: #b00020"));
  m_refusal->setWordWrap(true);
  m_refusal->hide();
  auto* key =
      new QLabel(tr("Crank 1; each cell: coupler · rocker · frame, P(along, across). Marks: "
                    "<span style=\"color:#dc1e1e\">&#9679;</span> cusp, "
                    "<span style=\"color:#1e5adc\">&#9675;</span> crunode, dashed line: mirror line, "
                    "<span style=\"color:#00963c\">&#9644;</span> straight, "
                    "<span style=\"color:#e68200\">&#9644;</span> circular. Click a cell to make it the "
                    "design."));
  key->setWordWrap(true);
  m_layout->setSpacing(4);
  m_layout->setAlignment(Qt::AlignTop | Qt::AlignLeft);
  m_scroll->setWidget(m_grid);
  m_scroll->setWidgetResizable(true);

  auto* layout = new QVBoxLayout(this);
  layout->addLayout(fields);
  layout->addLayout(filters);
  layout->addWidget(key);
  layout->addWidget(m_status);
  layout->addWidget(m_refusal);
  layout->addWidget(m_scroll, 1);
  resize(kColumns * (AtlasCellView::kSide + 4) + 60, 760);

  // The designer's Undo and Redo here too: a cell tried and not wanted is one Ctrl+Z away.
  connect(new QShortcut(QKeySequence::Undo, this), &QShortcut::activated, m_document->undoStack(), &QUndoStack::undo);
  connect(new QShortcut(QKeySequence::Redo, this), &QShortcut::activated, m_document->undoStack(), &QUndoStack::redo);
  connect(m_cache, &AtlasCellCache::cellReady, this, &AtlasWindow::onCellReady);
  connect(m_cache, &AtlasCellCache::finished, this, &AtlasWindow::updateStatus);
  showGrid();
}

k::AtlasFilter AtlasWindow::filter() const {
  return {m_filters[0]->isChecked(), m_filters[1]->isChecked(), m_filters[2]->isChecked(), m_filters[3]->isChecked(),
          m_filters[4]->isChecked()};
}

void AtlasWindow::showGrid() {
  k::AtlasAxes axes = m_axes;
  const std::array<std::vector<double>*, 5> targets{&axes.coupler, &axes.rocker, &axes.frame, &axes.along,
                                                    &axes.across};
  const std::array<QString, 5> names{tr("coupler"), tr("rocker"), tr("frame"), tr("along"), tr("across")};
  for (std::size_t i = 0; i < 5; ++i) {
    QString bad;
    const auto list = parseList(m_fields[i]->text(), bad);
    if (!list) {
      m_refusal->setText(tr("Not shown: %1: '%2' is not a number").arg(names[i], bad));
      m_refusal->show();
      return;
    }
    *targets[i] = *list;
  }
  if (const auto e = k::checkAtlasAxes(axes)) {
    m_refusal->setText(tr("Not shown: %1").arg(QString::fromStdString(e->message)));
    m_refusal->show();
    return;
  }
  m_refusal->hide();
  m_axes = axes;
  for (AtlasCellView* cell : m_cells) {
    cell->hide();
    cell->deleteLater();
  }
  m_cells.clear();
  const std::size_t count = k::atlasCellCount(m_axes);
  for (std::size_t i = 0; i < count; ++i) {
    auto* view = new AtlasCellView(i, k::atlasCellKey(m_axes, i), m_grid);
    if (const k::AtlasCell* cached = m_cache->find(view->key())) view->setCell(*cached);
    connect(view, &AtlasCellView::clicked, this, &AtlasWindow::load);
    m_cells.push_back(view);
  }
  relayout();
  requestMissing();
  updateStatus();
}

void AtlasWindow::requestMissing() {
  std::vector<k::AtlasCellKey> keys;
  for (const AtlasCellView* cell : m_cells)
    if (!cell->cell()) keys.push_back(cell->key());
  if (!keys.empty() && isVisible()) m_cache->request(keys);
}

void AtlasWindow::relayout() {
  while (m_layout->count() > 0) delete m_layout->takeAt(0);
  const k::AtlasFilter f = filter();
  int shown = 0;
  for (AtlasCellView* cell : m_cells) {
    // A cell still computing stays in sight until it is known whether it matches.
    const bool keep = !cell->cell() || k::matchesFilter(*cell->cell(), f);
    cell->setVisible(keep);
    if (!keep) continue;
    m_layout->addWidget(cell, shown / kColumns, shown % kColumns);
    ++shown;
  }
}

std::vector<AtlasCellView*> AtlasWindow::shownCells() const {
  std::vector<AtlasCellView*> out;
  for (AtlasCellView* cell : m_cells)
    if (!cell->isHidden()) out.push_back(cell);
  return out;
}

bool AtlasWindow::complete() const {
  return std::all_of(m_cells.begin(), m_cells.end(), [](const AtlasCellView* c) { return c->cell().has_value(); });
}

void AtlasWindow::onCellReady(const k::AtlasCell& cell) {
  bool hides = false;
  for (AtlasCellView* view : m_cells)
    if (view->key() == cell.key) {
      view->setCell(cell);
      hides = hides || !k::matchesFilter(cell, filter());
    }
  if (hides) relayout();
  updateStatus();
}

void AtlasWindow::updateStatus() {
  const auto done = std::count_if(m_cells.begin(), m_cells.end(), [](const AtlasCellView* c) { return c->cell(); });
  const auto shown = shownCells().size();
  m_status->setText(done < static_cast<long>(m_cells.size())
                        ? tr("%1 cells, %2 computed; %3 shown").arg(m_cells.size()).arg(done).arg(shown)
                        : tr("%1 cells; %2 shown").arg(m_cells.size()).arg(shown));
}

QString AtlasWindow::statusText() const { return m_status->text(); }
QString AtlasWindow::refusal() const { return m_refusal->isHidden() ? QString() : m_refusal->text(); }

void AtlasWindow::load(std::size_t index) {
  if (index >= m_cells.size()) return;
  const auto fourBar = k::asFourBar(m_document->mechanism());
  const double crank = fourBar ? fourBar->lengths.crank : kCrankWithoutFourBar;
  // The cell takes the place of the design, at its speed (not the core's 1 rad/s default).
  const k::Design& current = m_document->design();
  const auto design = k::atlasCellDesign(m_cells[index]->key(), crank, current.mechanism.lengthUnit, current.omega);
  if (!design) {
    m_refusal->setText(tr("Not loaded: %1").arg(QString::fromStdString(design.error().message)));
    m_refusal->show();
    return;
  }
  if (const auto why = m_document->replace(*design, tr("Atlas cell %1").arg(index))) {
    m_refusal->setText(tr("Not loaded: %1").arg(*why));
    m_refusal->show();
    return;
  }
  m_refusal->hide();
}

void AtlasWindow::showEvent(QShowEvent* event) {
  QWidget::showEvent(event);
  requestMissing();
}

// Nothing computes for a window no one sees; the cells done so far stay cached.
void AtlasWindow::hideEvent(QHideEvent* event) {
  m_cache->cancel();
  QWidget::hideEvent(event);
}

}  // namespace linkwright::ui
