#include "ui/dialogs/dyad_part_editors.h"

#include "ui/canvas/mechanism_drawing.h"
#include "ui/number_box.h"

#include "kinematics/model/units.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QLabel>
#include <QSignalBlocker>

namespace linkwright::ui {

namespace k = kinematics;

namespace {

QDoubleSpinBox* numberBox(QWidget* parent, double low = -1e9, double high = 1e9) {
  auto* box = new NumberBox(parent);
  box->setRange(low, high);
  box->setDecimals(4);
  box->setKeyboardTracking(false);
  return box;
}

}  // namespace

ParentEditor::ParentEditor(QWidget* parent)
    : QWidget(parent), m_source(new QComboBox(this)), m_link(new QComboBox(this)), m_a(numberBox(this)),
      m_b(numberBox(this)), m_aLabel(new QLabel(this)), m_bLabel(new QLabel(this)),
      m_linkLabel(new QLabel(tr("on link"), this)) {
  auto* grid = new QGridLayout(this);
  grid->setContentsMargins(0, 0, 0, 0);
  grid->addWidget(m_source, 0, 0, 1, 2);
  grid->addWidget(m_linkLabel, 1, 0);
  grid->addWidget(m_link, 1, 1);
  grid->addWidget(m_aLabel, 2, 0);
  grid->addWidget(m_a, 2, 1);
  grid->addWidget(m_bLabel, 3, 0);
  grid->addWidget(m_b, 3, 1);
  connect(m_source, &QComboBox::currentIndexChanged, this, [this] {
    showFields();
    emit changed();
  });
  for (QDoubleSpinBox* box : {m_a, m_b}) connect(box, &QDoubleSpinBox::valueChanged, this, &ParentEditor::changed);
  connect(m_link, &QComboBox::currentIndexChanged, this, &ParentEditor::changed);
}

void ParentEditor::setChoices(const k::Mechanism& m, const kinematics::ParentChoice& choice) {
  const QSignalBlocker blockSource(m_source), blockLink(m_link), blockA(m_a), blockB(m_b);
  m_source->clear();
  for (const k::Point& p : m.points) m_source->addItem(pointDisplayName(p.name));
  m_points = m.points.size();
  m_source->addItem(tr("New point on a link…"));
  m_source->addItem(tr("New ground pivot…"));
  m_link->clear();
  for (const k::Link& l : m.links) m_link->addItem(QString::fromStdString(l.name));
  const QString unit = QStringLiteral(" ") + QString::fromStdString(m.lengthUnit);
  m_a->setSuffix(unit);
  m_b->setSuffix(unit);
  using Source = kinematics::ParentChoice::Source;
  switch (choice.source) {
  case Source::Existing: m_source->setCurrentIndex(static_cast<int>(choice.point.index)); break;
  case Source::OnLink:
    m_source->setCurrentIndex(static_cast<int>(m_points));
    m_link->setCurrentIndex(static_cast<int>(choice.link.index));
    m_a->setValue(choice.along);
    m_b->setValue(choice.across);
    break;
  case Source::NewGround:
    m_source->setCurrentIndex(static_cast<int>(m_points) + 1);
    m_a->setValue(choice.position.x());
    m_b->setValue(choice.position.y());
    break;
  }
  showFields();
}

kinematics::ParentChoice ParentEditor::choice() const {
  kinematics::ParentChoice c;
  const auto index = static_cast<std::size_t>(std::max(0, m_source->currentIndex()));
  if (index < m_points) {
    c.point = k::PointId{index};
  } else if (index == m_points) {
    c.source = kinematics::ParentChoice::Source::OnLink;
    c.link = k::LinkId{static_cast<std::size_t>(std::max(0, m_link->currentIndex()))};
    c.along = m_a->value();
    c.across = m_b->value();
  } else {
    c.source = kinematics::ParentChoice::Source::NewGround;
    c.position = Eigen::Vector2d(m_a->value(), m_b->value());
  }
  return c;
}

void ParentEditor::showFields() {
  const auto index = static_cast<std::size_t>(std::max(0, m_source->currentIndex()));
  const bool onLink = index == m_points;
  const bool ground = index == m_points + 1;
  m_linkLabel->setVisible(onLink);
  m_link->setVisible(onLink);
  for (QWidget* w : std::initializer_list<QWidget*>{m_a, m_b, m_aLabel, m_bLabel}) w->setVisible(onLink || ground);
  m_aLabel->setText(onLink ? tr("along") : tr("x"));
  m_bLabel->setText(onLink ? tr("across") : tr("y"));
}

GuideEditor::GuideEditor(QWidget* parent)
    : QWidget(parent), m_body(new QComboBox(this)), m_a(numberBox(this)), m_b(numberBox(this)),
      m_angle(numberBox(this, -360.0, 360.0)), m_aLabel(new QLabel(this)), m_bLabel(new QLabel(this)) {
  auto* grid = new QGridLayout(this);
  grid->setContentsMargins(0, 0, 0, 0);
  grid->addWidget(new QLabel(tr("fixed to"), this), 0, 0);
  grid->addWidget(m_body, 0, 1);
  grid->addWidget(m_aLabel, 1, 0);
  grid->addWidget(m_a, 1, 1);
  grid->addWidget(m_bLabel, 2, 0);
  grid->addWidget(m_b, 2, 1);
  grid->addWidget(new QLabel(tr("angle"), this), 3, 0);
  grid->addWidget(m_angle, 3, 1);
  m_angle->setSuffix(QStringLiteral("°"));
  connect(m_body, &QComboBox::currentIndexChanged, this, [this] {
    showLabels();
    emit changed();
  });
  for (QDoubleSpinBox* box : {m_a, m_b, m_angle})
    connect(box, &QDoubleSpinBox::valueChanged, this, &GuideEditor::changed);
}

void GuideEditor::setGuide(const k::Mechanism& m, const k::Guide& guide) {
  const QSignalBlocker blockBody(m_body), blockA(m_a), blockB(m_b), blockAngle(m_angle);
  m_body->clear();
  m_body->addItem(tr("the ground"));
  for (const k::Link& l : m.links) m_body->addItem(QString::fromStdString(l.name));
  m_body->setCurrentIndex(guide.link ? static_cast<int>(guide.link->index) + 1 : 0);
  const QString unit = QStringLiteral(" ") + QString::fromStdString(m.lengthUnit);
  m_a->setSuffix(unit);
  m_b->setSuffix(unit);
  m_a->setValue(guide.point.x());
  m_b->setValue(guide.point.y());
  m_angle->setValue(k::radToDeg(guide.angle));
  showLabels();
}

k::Guide GuideEditor::guide() const {
  k::Guide g;
  if (m_body->currentIndex() > 0) g.link = k::LinkId{static_cast<std::size_t>(m_body->currentIndex() - 1)};
  g.point = Eigen::Vector2d(m_a->value(), m_b->value());
  g.angle = k::degToRad(m_angle->value());
  return g;
}

void GuideEditor::showLabels() {
  const bool onLink = m_body->currentIndex() > 0;
  m_aLabel->setText(onLink ? tr("through, along") : tr("through x"));
  m_bLabel->setText(onLink ? tr("through, across") : tr("through y"));
}

}  // namespace linkwright::ui
