#include "ui/panels/dynamics_panel.h"

#include "ui/colors.h"
#include "ui/document/mechanism_document.h"
#include "ui/number_box.h"
#include "ui/panels/link_points.h"
#include "ui/panels/mass_table.h"
#include "ui/panels/springs_editor.h"
#include "ui/quiet_update.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QVBoxLayout>

#include <algorithm>
#include <variant>

namespace linkwright::ui {

namespace k = kinematics;

namespace {

// The slider blocks of a mechanism, as the core names them (mass_properties.h: SliderMass).
std::vector<k::SliderMass> sliderKeys(const k::Mechanism& m) {
  std::vector<k::SliderMass> keys;
  for (const k::Point& p : m.points) {
    if (std::holds_alternative<k::RrpPoint>(p.definition) || std::holds_alternative<k::RprPoint>(p.definition))
      keys.push_back({p.name, 0, 0.0, 0.0});
    else if (std::holds_alternative<k::PrpPoint>(p.definition)) {
      keys.push_back({p.name, 0, 0.0, 0.0});
      keys.push_back({p.name, 1, 0.0, 0.0});
    }
  }
  return keys;
}

QDoubleSpinBox* numberSpin(const QString& suffix, double lo, double hi, QWidget* parent) {
  auto* spin = new NumberBox(parent);
  spin->setRange(lo, hi);
  spin->setDecimals(4);
  spin->setSuffix(suffix);
  spin->setKeyboardTracking(false);
  return spin;
}

}  // namespace

DynamicsPanel::DynamicsPanel(MechanismDocument* document, QWidget* parent)
    : QWidget(parent), m_document(document), m_refusal(new QLabel(this)),
      m_links(new MassTable(
          {tr("Link"), tr("Mass\n[kg]"), tr("Centre\nalong"), tr("Centre\nacross"), tr("Inertia\n[kg·m²]")})),
      m_sliderGroup(new QGroupBox(tr("Slider blocks"), this)),
      m_sliders(new MassTable({tr("Slider"), tr("Mass\n[kg]"), tr("Inertia\n[kg·m²]")})),
      m_gravity(new QCheckBox(tr("Gravity, down (−y)"))), m_g(numberSpin(tr(" m/s²"), 0.0, 1e4, this)),
      m_torqueLink(new QComboBox), m_torque(numberSpin(tr(" N·m"), -1e9, 1e9, this)), m_forceTarget(new QComboBox),
      m_forceX(numberSpin(tr(" N"), -1e9, 1e9, this)), m_forceY(numberSpin(tr(" N"), -1e9, 1e9, this)),
      m_extraLoads(new QLabel),
      m_springs(new SpringsEditor(
          document,
          [this](const QString& description, const std::function<void(k::LinkageDynamics&)>& change) {
            submit(description, change);
          },
          [this](const QString& reason) { refuse(reason); })) {
  auto* layout = new QVBoxLayout(this);
  m_refusal->setWordWrap(true);
  m_refusal->setStyleSheet(QStringLiteral("color: %1").arg(colors().refusal.name()));
  m_refusal->setVisible(false);
  layout->addWidget(m_refusal);

  auto* linkGroup = new QGroupBox(tr("Links"), this);
  auto* linkLayout = new QVBoxLayout(linkGroup);
  linkLayout->addWidget(m_links);
  auto* hint =
      new QLabel(tr("Empty cells use the core's defaults: centre at the midpoint, inertia of a uniform "
                    "bar m·L²/12. Clear a cell to return to its default."));
  hint->setWordWrap(true);
  hint->setEnabled(false);
  linkLayout->addWidget(hint);
  layout->addWidget(linkGroup);

  auto* sliderLayout = new QVBoxLayout(m_sliderGroup);
  sliderLayout->addWidget(m_sliders);
  layout->addWidget(m_sliderGroup);

  auto* loads = new QGroupBox(tr("Loads"), this);
  auto* form = new QFormLayout(loads);
  // One field a row: side by side the rows wanted 476 px, and on a projector's 1024 px the page
  // scrolled sideways.
  m_g->setDecimals(5);
  form->addRow(m_gravity);
  form->addRow(tr("g"), m_g);
  form->addRow(tr("Load torque on"), m_torqueLink);
  form->addRow(tr("torque"), m_torque);
  form->addRow(tr("Force at"), m_forceTarget);
  form->addRow(tr("Fx"), m_forceX);
  form->addRow(tr("Fy"), m_forceY);
  m_extraLoads->setWordWrap(true);
  m_extraLoads->setEnabled(false);
  form->addRow(m_extraLoads);
  layout->addWidget(loads);
  layout->addWidget(m_springs);
  layout->addStretch(1);

  // Sized for a dozen characters, not the longest point's name: the list shows them whole.
  for (QComboBox* box : {m_torqueLink, m_forceTarget}) {
    box->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    box->setMinimumContentsLength(6);
  }
  m_torque->setToolTip(tr("Counter-clockwise positive, the same at every crank angle"));
  m_forceTarget->setToolTip(
      tr("A point of a link, or a slider block (the force acts at its pin); fixed in the world frame"));

  connect(m_links, &MassTable::cellEdited, this, &DynamicsPanel::editLink);
  connect(m_sliders, &MassTable::cellEdited, this, &DynamicsPanel::editSlider);
  connect(m_gravity, &QCheckBox::toggled, this, [this] { editGravity(); });
  connect(m_g, &QDoubleSpinBox::valueChanged, this, [this] { editGravity(); });
  connect(m_torqueLink, &QComboBox::currentIndexChanged, this, [this] { editTorque(); });
  connect(m_torque, &QDoubleSpinBox::valueChanged, this, [this] { editTorque(); });
  connect(m_forceTarget, &QComboBox::currentIndexChanged, this, [this] { editForce(); });
  connect(m_forceX, &QDoubleSpinBox::valueChanged, this, [this] { editForce(); });
  connect(m_forceY, &QDoubleSpinBox::valueChanged, this, [this] { editForce(); });
  connect(document, &MechanismDocument::changed, this, [this](Changes what) {
    if (!(what & Change::Design)) return;
    // A refused edit changes nothing, so a new design is one the refusal was not made for.
    m_refusal->clear();
    m_refusal->setVisible(false);
    refresh();
  });
  refresh();
}

QString DynamicsPanel::refusalMessage() const { return m_refusal->text(); }

void DynamicsPanel::refresh() {
  refreshTables();
  refreshLoads();
  m_springs->refresh();
}

void DynamicsPanel::refreshTables() {
  const k::Mechanism& m = m_document->mechanism();
  const k::LinkageDynamics& d = m_document->design().dynamics;
  const QString unit = QString::fromStdString(m_document->lengthUnit());
  // Three short lines, so that the five columns fit a projector's narrow side column.
  m_links->setHeaderText(2, tr("Centre\nalong\n[%1]").arg(unit));
  m_links->setHeaderText(3, tr("Centre\nacross\n[%1]").arg(unit));
  QStringList names;
  std::vector<std::vector<MassTable::Cell>> cells;
  const QString midpoint = tr("midpoint");
  const QString midpointTip = tr("Not set: the core puts the centre of mass at the link's midpoint");
  for (const k::Link& link : m.links) {
    names << QString::fromStdString(link.name);
    const auto found =
        std::find_if(d.links.begin(), d.links.end(), [&](const k::LinkMass& l) { return l.link == link.name; });
    const k::LinkMass* l = found != d.links.end() ? &*found : nullptr;
    const k::LinkFramePoint* centre = l != nullptr && l->centre ? &*l->centre : nullptr;
    cells.push_back({
        {l ? std::optional<double>(l->mass) : std::nullopt, QStringLiteral("0"), tr("Not set: massless")},
        {centre ? std::optional<double>(centre->along) : std::nullopt, midpoint, midpointTip},
        {centre ? std::optional<double>(centre->across) : std::nullopt, midpoint, midpointTip},
        {l ? l->inertia : std::nullopt, tr("m·L²/12"), tr("Not set: the core uses a uniform slender bar, m·L²/12")},
    });
  }
  m_links->setRows(names, cells);

  m_sliderKeys = sliderKeys(m);
  names.clear();
  cells.clear();
  for (const k::SliderMass& key : m_sliderKeys) {
    const bool prp = key.guide > 0 || std::count_if(m_sliderKeys.begin(), m_sliderKeys.end(),
                                                    [&](const k::SliderMass& s) { return s.point == key.point; }) > 1;
    names << (prp ? tr("%1 (guide %2)").arg(QString::fromStdString(key.point)).arg(key.guide + 1)
                  : QString::fromStdString(key.point));
    const auto found = std::find_if(d.sliders.begin(), d.sliders.end(), [&](const k::SliderMass& s) {
      return s.point == key.point && s.guide == key.guide;
    });
    const bool set = found != d.sliders.end();
    cells.push_back(
        {{set ? std::optional<double>(found->mass) : std::nullopt, QStringLiteral("0"), tr("Not set: massless")},
         {set ? std::optional<double>(found->inertia) : std::nullopt, QStringLiteral("0"), tr("Not set: 0")}});
  }
  m_sliders->setRows(names, cells);
  m_sliderGroup->setVisible(!m_sliderKeys.empty());
}

void DynamicsPanel::refreshLoads() {
  const k::Mechanism& m = m_document->mechanism();
  const k::Loads& loads = m_document->design().dynamics.loads;
  const QSignalBlocker b1(m_gravity), b2(m_g), b3(m_torqueLink), b4(m_torque), b5(m_forceTarget), b6(m_forceX),
      b7(m_forceY);
  m_gravity->setChecked(loads.gravity.has_value());
  setValueQuietly(m_g, loads.gravity ? loads.gravity->norm() : k::kStandardGravity);
  m_g->setEnabled(loads.gravity.has_value());

  QStringList torqueLinks{tr("(none)")};
  for (const k::Link& link : m.links) torqueLinks << QString::fromStdString(link.name);
  setComboItems(m_torqueLink, torqueLinks);
  const k::LinkTorque* torque = loads.torques.empty() ? nullptr : &loads.torques.front();
  m_torqueLink->setCurrentIndex(torque ? std::max(0, m_torqueLink->findText(QString::fromStdString(torque->link))) : 0);
  setValueQuietly(m_torque, torque ? torque->torque : 0.0);
  m_torque->setEnabled(torque != nullptr);

  m_targets.clear();
  QStringList targets{tr("(none)")};
  for (const k::SliderMass& key : m_sliderKeys) {
    m_targets.push_back({{}, key.point, key.guide});
    targets << (tr("slider block at %1").arg(QString::fromStdString(key.point)) +
                (key.guide > 0 ? tr(" (guide %1)").arg(key.guide + 1) : QString()));
  }
  for (const LinkPoint& p : pointsOnLinks(m)) {
    m_targets.push_back({p.link, p.point, 0});
    targets << tr("%1 on %2").arg(QString::fromStdString(p.point), QString::fromStdString(p.link));
  }
  setComboItems(m_forceTarget, targets);
  const k::PointForce* force = loads.forces.empty() ? nullptr : &loads.forces.front();
  int target = 0;
  for (std::size_t i = 0; force != nullptr && i < m_targets.size(); ++i)
    if (m_targets[i].link == force->link && m_targets[i].point == force->point && m_targets[i].guide == force->guide)
      target = static_cast<int>(i) + 1;
  m_forceTarget->setCurrentIndex(target);
  setValueQuietly(m_forceX, force ? force->force.x() : 0.0);
  setValueQuietly(m_forceY, force ? force->force.y() : 0.0);
  m_forceX->setEnabled(force != nullptr);
  m_forceY->setEnabled(force != nullptr);

  const std::size_t extra = (loads.torques.size() > 1 ? loads.torques.size() - 1 : 0) +
                            (loads.forces.size() > 1 ? loads.forces.size() - 1 : 0);
  QStringList notes;
  if (extra > 0)
    notes << tr("%n more load(s) from the file are kept but not shown here.", nullptr, static_cast<int>(extra));
  m_extraLoads->setText(notes.join(QLatin1Char(' ')));
  m_extraLoads->setVisible(!notes.isEmpty());
}

void DynamicsPanel::submit(const QString& description, const std::function<void(k::LinkageDynamics&)>& change) {
  k::Design design = m_document->design();
  change(design.dynamics);
  if (const auto why = m_document->edit(design, description)) {
    refuse(*why);
  } else {
    m_refusal->clear();
    m_refusal->setVisible(false);
  }
  refresh();  // shows what the design now holds (defaults in grey again, refused values gone)
}

void DynamicsPanel::refuse(const QString& reason) {
  m_refusal->setText(reason);
  m_refusal->setVisible(true);
}

void DynamicsPanel::editLink(int row, int column, std::optional<double> value, bool parsed) {
  const k::Mechanism& m = m_document->mechanism();
  if (row < 0 || static_cast<std::size_t>(row) >= m.links.size()) return;
  if (!parsed) {
    refuse(tr("Not a number: type a value, or clear the cell for the default."));
    refreshTables();
    return;
  }
  const std::string name = m.links[static_cast<std::size_t>(row)].name;
  const QString qname = QString::fromStdString(name);
  const QString description = column == 1   ? tr("Change mass of %1").arg(qname)
                              : column == 4 ? tr("Change inertia of %1").arg(qname)
                                            : tr("Move centre of mass of %1").arg(qname);
  const auto& links = m_document->design().dynamics.links;
  const auto existing = std::find_if(links.begin(), links.end(), [&](const k::LinkMass& l) { return l.link == name; });
  if (column == 3 && value && (existing == links.end() || !existing->centre)) {
    // The default centre's position along the link is the core's to compute (the midpoint);
    // the panel does not guess it.
    refuse(tr("Give the centre's position along %1 first; across is measured from that line.").arg(qname));
    refreshTables();
    return;
  }
  submit(description, [&](k::LinkageDynamics& d) {
    auto it = std::find_if(d.links.begin(), d.links.end(), [&](const k::LinkMass& l) { return l.link == name; });
    if (it == d.links.end()) it = d.links.insert(d.links.end(), k::LinkMass{name, 0.0, std::nullopt, std::nullopt});
    switch (column) {
    case 1: it->mass = value.value_or(0.0); break;
    case 2:
      it->centre =
          value ? std::optional<k::LinkFramePoint>({*value, it->centre ? it->centre->across : 0.0}) : std::nullopt;
      break;
    case 3:
      if (it->centre) it->centre->across = value.value_or(0.0);
      break;
    case 4: it->inertia = value; break;
    default: break;
    }
    // An entry with nothing in it is no entry: a design without masses stays "no dynamics".
    if (it->mass == 0.0 && !it->centre && !it->inertia) d.links.erase(it);
  });
}

void DynamicsPanel::editSlider(int row, int column, std::optional<double> value, bool parsed) {
  if (row < 0 || static_cast<std::size_t>(row) >= m_sliderKeys.size()) return;
  if (!parsed) {
    refuse(tr("Not a number: type a value, or clear the cell for the default."));
    refreshTables();
    return;
  }
  const k::SliderMass key = m_sliderKeys[static_cast<std::size_t>(row)];
  submit(tr("Change mass of slider %1").arg(QString::fromStdString(key.point)), [&](k::LinkageDynamics& d) {
    auto it = std::find_if(d.sliders.begin(), d.sliders.end(),
                           [&](const k::SliderMass& s) { return s.point == key.point && s.guide == key.guide; });
    if (it == d.sliders.end()) it = d.sliders.insert(d.sliders.end(), key);
    (column == 1 ? it->mass : it->inertia) = value.value_or(0.0);
    if (it->mass == 0.0 && it->inertia == 0.0) d.sliders.erase(it);
  });
}

void DynamicsPanel::editGravity() {
  const bool on = m_gravity->isChecked();
  const double g = m_g->value();
  submit(on ? tr("Set gravity") : tr("Switch off gravity"), [&](k::LinkageDynamics& d) {
    d.loads.gravity = on ? std::optional<Eigen::Vector2d>(Eigen::Vector2d(0.0, -g)) : std::nullopt;
  });
}

void DynamicsPanel::editTorque() {
  const int index = m_torqueLink->currentIndex();
  const std::string link = index > 0 ? m_torqueLink->currentText().toStdString() : std::string();
  const double torque = m_torque->value();
  submit(tr("Change load torque"), [&](k::LinkageDynamics& d) {
    auto& torques = d.loads.torques;
    if (link.empty()) {
      if (!torques.empty()) torques.erase(torques.begin());
      return;
    }
    if (torques.empty()) torques.push_back({});
    torques.front() = {link, torque};
  });
}

void DynamicsPanel::editForce() {
  const int index = m_forceTarget->currentIndex();
  const std::optional<ForceTarget> target = index > 0 && static_cast<std::size_t>(index) <= m_targets.size()
                                                ? std::optional(m_targets[static_cast<std::size_t>(index) - 1])
                                                : std::nullopt;
  const Eigen::Vector2d force(m_forceX->value(), m_forceY->value());
  submit(tr("Change point force"), [&](k::LinkageDynamics& d) {
    auto& forces = d.loads.forces;
    if (!target) {
      if (!forces.empty()) forces.erase(forces.begin());
      return;
    }
    if (forces.empty()) forces.push_back({});
    forces.front() = {target->link, target->point, target->guide, force};
  });
}

}  // namespace linkwright::ui
