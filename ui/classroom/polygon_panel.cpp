#include "ui/classroom/polygon_panel.h"

#include "ui/classroom/polygon_scale.h"
#include "ui/classroom/polygon_view.h"
#include "ui/document/mechanism_document.h"
#include "ui/number_text.h"

#include "kinematics/model/driver.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QRegularExpression>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace linkwright::ui {

namespace k = kinematics;

namespace {

// "A^n_CB" as A<sup>n</sup><sub>CB</sub>, as the textbook prints it.
QString richEquation(QString text) {
  text = text.toHtmlEscaped();
  static const QRegularExpression term(R"(([AV])(?:\^(\w))?_([\w']+))");
  return text.replace(term, R"(\1<sup>\2</sup><sub>\3</sub>)");
}

// Four significant digits, as read off a drawing with a ruler, without an exponent.
QString readOffText(double value) {
  if (value == 0.0 || !std::isfinite(value)) return numberText(value, 'f', 0);
  const int decimals = std::clamp(3 - static_cast<int>(std::floor(std::log10(std::abs(value)))), 0, 6);
  return numberText(value, 'f', decimals);
}

}  // namespace

PolygonPanel::PolygonPanel(MechanismDocument* document, QWidget* parent)
    : QWidget(parent), m_document(document), m_view(new PolygonView(this)), m_kindBox(new QComboBox(this)),
      m_scaleBox(new QComboBox(this)), m_stepButton(new QPushButton(tr("&Step"), this)), m_stepText(new QLabel(this)),
      m_equations(new QLabel(this)), m_reasonLabel(new QLabel(this)), m_content(new QWidget(this)),
      m_table(new QTableWidget(0, 5, this)) {
  setObjectName("PolygonPanel");
  m_kindBox->addItems({tr("Velocity polygon"), tr("Acceleration polygon")});
  m_kindBox->setObjectName("PolygonKind");
  m_scaleBox->setObjectName("PolygonScale");
  m_scaleBox->setToolTip(tr("Drawing scale: how much velocity (acceleration) one centimetre of drawing stands for"));
  auto* all = new QPushButton(tr("&All"), this);
  auto* reset = new QPushButton(tr("&Reset"), this);
  m_stepButton->setObjectName("PolygonStep");
  all->setObjectName("PolygonAll");
  reset->setObjectName("PolygonReset");
  m_stepButton->setToolTip(tr("Draw the next arrow, in the order a student draws them"));
  m_scaleBox->setSizeAdjustPolicy(QComboBox::AdjustToContents);
  auto* choices = new QHBoxLayout;
  choices->addWidget(m_kindBox);
  choices->addWidget(new QLabel(tr("Scale:"), this));
  choices->addWidget(m_scaleBox);
  choices->addStretch();
  auto* steps = new QHBoxLayout;
  steps->addWidget(m_stepButton);
  steps->addWidget(all);
  steps->addWidget(reset);
  steps->addWidget(m_stepText, 1);

  auto* contentLayout = new QVBoxLayout(m_content);
  contentLayout->setContentsMargins(0, 0, 0, 0);
  contentLayout->addLayout(choices);
  contentLayout->addLayout(steps);
  contentLayout->addWidget(buildDrawingAndTable(), 1);

  m_reasonLabel->setObjectName("PolygonReason");
  m_reasonLabel->setWordWrap(true);
  m_reasonLabel->setAlignment(Qt::AlignTop | Qt::AlignLeft);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(m_reasonLabel);
  layout->addWidget(m_content, 1);

  connect(m_kindBox, &QComboBox::currentIndexChanged, this,
          [this](int index) { setKind(index == 0 ? k::PolygonKind::Velocity : k::PolygonKind::Acceleration); });
  connect(m_scaleBox, &QComboBox::activated, this,
          [this](int index) { setChosenScale(m_scaleBox->itemData(index).toDouble()); });
  connect(m_view, &PolygonView::resized, this, [this] {
    fillScales();
    fillTable();
  });
  connect(m_stepButton, &QPushButton::clicked, this, &PolygonPanel::step);
  connect(all, &QPushButton::clicked, this, &PolygonPanel::showAll);
  connect(reset, &QPushButton::clicked, this, &PolygonPanel::reset);
  connect(document, &MechanismDocument::changed, this, [this](Changes what) {
    if (what & (Change::Design | Change::Motion)) refresh();
  });
  refresh();
}

// The drawing above; the equations and the table of lengths below.
QWidget* PolygonPanel::buildDrawingAndTable() {
  m_stepText->setWordWrap(true);
  m_equations->setWordWrap(true);
  m_equations->setTextFormat(Qt::RichText);
  m_equations->setTextInteractionFlags(Qt::TextSelectableByMouse);
  m_table->setObjectName("PolygonTable");
  m_table->verticalHeader()->hide();
  m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
  m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  m_table->horizontalHeader()->setSectionResizeMode(VectorColumn, QHeaderView::Stretch);
  auto* lower = new QWidget(this);
  auto* lowerLayout = new QVBoxLayout(lower);
  lowerLayout->setContentsMargins(0, 0, 0, 0);
  lowerLayout->addWidget(m_equations);
  lowerLayout->addWidget(m_table, 1);
  auto* splitter = new QSplitter(Qt::Vertical, this);
  splitter->addWidget(m_view);
  splitter->addWidget(lower);
  splitter->setStretchFactor(0, 3);
  splitter->setStretchFactor(1, 2);
  splitter->setChildrenCollapsible(false);
  return splitter;
}

void PolygonPanel::setOnScreen(bool on) {
  m_onScreen = on;
  if (on && m_stale) refresh();
}

QString PolygonPanel::reason() const { return m_reason; }

// The polygons of the pose the document solved (every point, with rates): only the polygons
// are computed here. Where the core draws none, its reason is shown instead.
void PolygonPanel::refresh() {
  if (!m_onScreen) {
    m_stale = true;
    return;
  }
  m_stale = false;
  const k::Mechanism& m = m_document->mechanism();
  m_polygons.reset();
  m_reason.clear();
  if (k::inputKind(m) != k::InputKind::Angle) {
    m_reason = tr("Velocity and acceleration polygons are drawn for a crank-driven linkage; this one is driven by "
                  "its %1.")
                   .arg(QString::fromStdString(k::inputName(m)));
  } else if (m_document->poseStatus() != k::PoseStatus::Ok) {
    // Asked again at the same crank state, the core says why (a toggle: no rates exist).
    const k::DriverState driver{m_document->crankAngle(), m_document->design().omega, m_document->design().alpha};
    const auto solved = k::polygonsAt(m, driver);
    m_reason = tr("No polygons at this crank angle: %1")
                   .arg(solved ? tr("the pose is not solved") : QString::fromStdString(solved.error().message));
  } else {
    const k::Pose& pose = m_document->pose();
    m_polygons = k::ClassroomPolygons{pose, k::velocityPolygon(m, pose), k::accelerationPolygon(m, pose)};
  }
  m_reasonLabel->setText(m_reason);
  m_reasonLabel->setVisible(!m_polygons);
  m_content->setVisible(m_polygons.has_value());
  showPolygon();
}

void PolygonPanel::showPolygon() {
  const bool velocity = m_kind == k::PolygonKind::Velocity;
  m_view->setPolygon(m_polygons ? (velocity ? m_polygons->velocity : m_polygons->acceleration) : k::VectorPolygon{});
  m_view->setChosenScale(m_chosenScale[velocity ? 0 : 1]);
  fillScales();
  fillTable();
}

void PolygonPanel::setKind(k::PolygonKind kind) {
  m_kind = kind;
  const int index = kind == k::PolygonKind::Velocity ? 0 : 1;
  if (m_kindBox->currentIndex() != index) m_kindBox->setCurrentIndex(index);
  showPolygon();
}

void PolygonPanel::setChosenScale(double unitsPerCm) {
  m_chosenScale[m_kind == k::PolygonKind::Velocity ? 0 : 1] =
      std::isfinite(unitsPerCm) ? std::max(unitsPerCm, 0.0) : 0.0;
  showPolygon();
}

// "Fit" and round scales around the fitting one; the chosen scale stays listed.
void PolygonPanel::fillScales() {
  const QString unit = QString::fromStdString(m_view->polygon().unit);
  const double chosen = m_view->chosenScale();
  std::vector<double> scales = roundScalesAround(m_view->fitScale());
  if (chosen > 0.0 && std::find(scales.begin(), scales.end(), chosen) == scales.end()) {
    scales.push_back(chosen);
    std::sort(scales.begin(), scales.end());
  }
  QStringList texts{tr("Fit: %1").arg(scaleText(m_view->fitScale(), unit))};
  int current = 0;
  for (const double s : scales) {
    texts << scaleText(s, unit);
    if (s == chosen) current = static_cast<int>(texts.size()) - 1;
  }
  // While the crank turns the list mostly stays the same: an open list is left alone then.
  QStringList shown;
  for (int i = 0; i < m_scaleBox->count(); ++i) shown << m_scaleBox->itemText(i);
  const QSignalBlocker block(m_scaleBox);
  if (shown != texts) {
    m_scaleBox->clear();
    m_scaleBox->addItem(texts.front(), 0.0);
    for (std::size_t i = 0; i < scales.size(); ++i) m_scaleBox->addItem(texts[static_cast<int>(i) + 1], scales[i]);
  }
  m_scaleBox->setCurrentIndex(current);
}

void PolygonPanel::addRow(const QString& stepText, const QString& vector, double magnitude, const QString& tip) {
  const double scale = m_view->scale();
  const double drawnCm = magnitude / scale;
  const double readOff = drawnCm * scale;
  const int row = m_table->rowCount();
  m_table->insertRow(row);
  const auto cell = [&](int column, const QString& text, std::optional<double> value) {
    auto* item = new QTableWidgetItem(text);
    if (value) item->setData(Qt::UserRole, *value);
    if (column >= DrawnColumn) item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
    item->setToolTip(tip);
    m_table->setItem(row, column, item);
  };
  cell(StepColumn, stepText, std::nullopt);
  cell(VectorColumn, vector, std::nullopt);
  cell(DrawnColumn, numberText(drawnCm, 'f', 2), drawnCm);
  cell(ReadOffColumn, readOffText(readOff), readOff);
  cell(ExactColumn, numberText(magnitude, 'g', 7), magnitude);
}

// Each arrow drawn, then each point's image (o to its image) against the solver's value.
void PolygonPanel::fillTable() {
  const k::VectorPolygon& polygon = m_view->polygon();
  const QString unit = QString::fromStdString(polygon.unit);
  m_table->setRowCount(0);
  m_table->setHorizontalHeaderLabels(
      {tr("Step"), tr("Vector"), tr("Drawing (cm)"), tr("Read off (%1)").arg(unit), tr("Exact (%1)").arg(unit)});
  const std::vector<k::PolygonVector> drawn = m_view->drawnVectors();
  for (const k::PolygonVector& v : drawn)
    addRow(QString::number(v.step), QString::fromStdString(v.label), v.value().norm(),
           QString::fromStdString(v.meaning));
  m_arrowRows = m_table->rowCount();
  const QString symbol = polygon.kind == k::PolygonKind::Velocity ? "V" : "A";
  std::vector<k::PointId> checked;  // two equations may end on one point (a slotted link's block)
  for (const k::PolygonEquation& e : polygon.equations) {
    if (std::find(checked.begin(), checked.end(), e.subject) != checked.end()) continue;
    checked.push_back(e.subject);
    for (const k::PolygonImage& im : m_view->drawnImages()) {
      if (im.point != e.subject || im.coincident || im.label == "o") continue;
      const QString name = QString::fromStdString(im.label).toUpper();
      addRow(tr("check"), QStringLiteral("|%1_%2| = o%3").arg(symbol, name, QString::fromStdString(im.label)),
             im.position.norm(),
             tr("The image's distance from the pole, read off the drawing, against the solver's |%1_%2| = %3 %4")
                 .arg(symbol, name, numberText(e.solver.norm(), 'g', 9), unit));
      // The exact column holds the solver's own value, not the drawing's.
      m_table->item(m_table->rowCount() - 1, ExactColumn)->setData(Qt::UserRole, e.solver.norm());
      m_table->item(m_table->rowCount() - 1, ExactColumn)->setText(numberText(e.solver.norm(), 'g', 7));
      break;
    }
  }
  QStringList lines;
  for (const k::PolygonEquation& e : polygon.equations) lines << richEquation(QString::fromStdString(e.text));
  m_equations->setText(lines.join("<br>"));
  const int total = static_cast<int>(polygon.vectors.size());
  const int shown = static_cast<int>(drawn.size());
  if (shown == total) m_stepText->setText(tr("All %1 arrows drawn. Step draws them again one at a time.").arg(total));
  else if (shown == 0) m_stepText->setText(tr("Nothing drawn yet: Step draws the first arrow."));
  else
    m_stepText->setText(
        tr("Step %1 of %2: %3 — %4")
            .arg(shown)
            .arg(total)
            .arg(QString::fromStdString(drawn.back().label), QString::fromStdString(drawn.back().meaning)));
}

void PolygonPanel::step() {
  const int current = m_view->revealedStep();
  const k::VectorPolygon& polygon = m_view->polygon();
  int next = PolygonView::kAllSteps;
  for (const k::PolygonVector& v : polygon.vectors)
    if (v.step > (current == PolygonView::kAllSteps ? 0 : current)) next = std::min(next, v.step);
  m_view->setRevealedStep(next);
  fillTable();
}

void PolygonPanel::showAll() {
  m_view->setRevealedStep(PolygonView::kAllSteps);
  fillTable();
}

void PolygonPanel::reset() {
  m_view->setRevealedStep(0);
  fillTable();
}

void PolygonPanel::setPresentationScale(double scale) { m_view->setPresentationScale(scale); }

}  // namespace linkwright::ui
