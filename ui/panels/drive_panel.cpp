#include "ui/panels/drive_panel.h"

#include "ui/document/edit_design_command.h"
#include "ui/number_box.h"
#include "ui/number_text.h"
#include "ui/panels/law_table_file.h"
#include "ui/plots/plot_x_axis.h"
#include "ui/quiet_update.h"
#include "ui/settings.h"

#include "kinematics/design/redrive.h"
#include "kinematics/model/driver.h"
#include "kinematics/model/units.h"
#include "kinematics/model/validate.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QStandardItemModel>
#include <QVBoxLayout>

#include <cmath>
#include <type_traits>
#include <variant>

namespace linkwright::ui {
namespace {

namespace k = kinematics;
using Drive = DrivePanel::Drive;
using Field = DrivePanel::Field;

// Times and durations, s: the core's bound (checkTimeBase, checkMotionLaw).
constexpr double kMaxTime = 1e6;

// A bound as the messages write it: "1e6", "9.549e6", "360".
QString boundText(double value) {
  QString text = QString::number(value, 'g', 4);
  return text.replace(QLatin1String("e+0"), QLatin1String("e")).replace(QLatin1String("e+"), QLatin1String("e"));
}

// The number behind `field` in a law, in SI units (rad, rad/s, s): the members several laws
// share, by field; null where the law has none. One table for reading and writing.
template <typename Law>
std::conditional_t<std::is_const_v<Law>, const double*, double*> lawNumber(Law& l, Field field) {
  if constexpr (requires { l.start; })
    if (field == Field::Start) return &l.start;
  if constexpr (requires { l.velocity; })
    if (field == Field::Speed) return &l.velocity;
  if constexpr (requires { l.rise; })
    if (field == Field::Rise) return &l.rise;
  if constexpr (requires { l.duration; })
    if (field == Field::Duration) return &l.duration;
  if constexpr (requires { l.rampTime; })
    if (field == Field::RampTime) return &l.rampTime;
  return nullptr;
}

std::optional<double> lawMember(const k::MotionLaw& law, Field field) {
  const double* number = std::visit([&](const auto& l) { return lawNumber(l, field); }, law);
  return number != nullptr ? std::optional<double>(*number) : std::nullopt;
}

// Sets a law's member; a law without it is left alone.
void setLawMember(k::MotionLaw& law, Field field, double value) {
  if (double* number = std::visit([&](auto& l) { return lawNumber(l, field); }, law)) *number = value;
}

// `design` driven as `drive`, its numbers carried over where the old drive had them, else
// the CLI's defaults: from the grid's start at the design's rate, a rise over the grid's span
// in 1 s, a ramp of 1 s; analysed from 0 to the rise's end, or the ramp's end and the grid's
// span at speed (a turn, for a crank), or that span.
k::Design withDrive(k::Design d, Drive drive) {
  const std::optional<k::MotionLaw> old = d.time ? std::optional(d.time->law) : std::nullopt;
  const auto keep = [&](Field field, double fallback) {
    return old ? lawMember(*old, field).value_or(fallback) : fallback;
  };
  // The grid is in the input's display unit (degrees for a crank); laws are in its own (rad).
  const double gridFrom = k::inputFromDisplay(d.mechanism, d.fromDeg);
  const double gridSpan = k::inputFromDisplay(d.mechanism, d.toDeg) - gridFrom;
  const double start = keep(Field::Start, gridFrom);
  const double speed = keep(Field::Speed, d.omega);
  if (drive == Drive::AngleGrid) {
    d.omega = speed;
    d.time.reset();
    return d;
  }
  const double rise = keep(Field::Rise, gridSpan);
  const double duration = keep(Field::Duration, 1.0);
  const double rampTime = keep(Field::RampTime, 1.0);
  const double turn = speed != 0.0 && gridSpan != 0.0 ? std::abs(gridSpan / speed) : 1.0;
  switch (drive) {
  case Drive::ConstantSpeed: d.time = k::TimeBase{k::ConstantVelocity{start, speed}, 0.0, turn}; break;
  case Drive::RampToSpeed: d.time = k::TimeBase{k::RampToSpeed{start, speed, rampTime}, 0.0, rampTime + turn}; break;
  case Drive::CycloidalRise: d.time = k::TimeBase{k::CycloidalRise{start, rise, duration}, 0.0, duration}; break;
  case Drive::PolynomialRise: d.time = k::TimeBase{k::PolynomialRise{start, rise, duration}, 0.0, duration}; break;
  case Drive::AngleGrid:
  case Drive::Table: break;  // the grid above; a table comes from a file (loadTable)
  }
  return d;
}

}  // namespace

DrivePanel::DrivePanel(MechanismDocument* document, Settings* settings, QWidget* parent)
    : QWidget(parent), m_document(document), m_settings(settings), m_driver(new QComboBox(this)),
      m_law(new QComboBox(this)), m_speedUnit(new QComboBox(this)), m_samples(new QSpinBox(this)),
      m_tableName(new QLabel(this)), m_loadTable(new QPushButton(tr("Load CSV…"), this)), m_axis(new QComboBox(this)),
      m_form(nullptr), m_message(new RefusalLabel(document, this)) {
  auto* layout = new QVBoxLayout(this);
  auto* box = new QGroupBox(tr("Drive"), this);
  m_form = new QFormLayout(box);
  m_driver->setObjectName(QStringLiteral("driver"));
  m_form->addRow(tr("Driven from"), m_driver);
  m_law->addItems({tr("Constant speed on a grid"), tr("Constant speed in time"), tr("Ramp to speed"),
                   tr("Cycloidal rise"), tr("3-4-5 polynomial rise"), tr("Table from CSV…")});
  m_law->setToolTip(
      tr("Constant speed on a grid has one rate and acceleration at every input value; the others move the input "
         "in time by a motion law and analyse it on a time base"));
  m_form->addRow(tr("Motion law"), m_law);

  for (std::size_t i = 0; i < m_fields.size(); ++i) {
    auto* spin = new NumberBox(this);
    spin->setDecimals(4);
    spin->setKeyboardTracking(false);  // typed numbers apply on Enter or focus out
    spin->setAccelerated(true);
    // Wider than what is accepted, so that a wrong value can be typed and be told why.
    spin->setRange(-1e7, 1e7);
    m_fields[i] = spin;
    const auto field = static_cast<Field>(i);
    connect(spin, &QDoubleSpinBox::valueChanged, this, [this, field] { editField(field); });
  }
  fieldBox(Field::Acceleration)->setRange(-1e13, 1e13);
  fieldBox(Field::Acceleration)->setSuffix(tr(" rad/s²"));
  for (const Field f : {Field::Start, Field::Rise}) fieldBox(f)->setSuffix(tr("°"));
  for (const Field f : {Field::RampTime, Field::Duration, Field::FromTime, Field::ToTime})
    fieldBox(f)->setSuffix(tr(" s"));

  m_speedRow = new QWidget(this);
  auto* speedLayout = new QHBoxLayout(m_speedRow);
  speedLayout->setContentsMargins(0, 0, 0, 0);
  m_speedUnit->addItems({tr("rpm"), tr("rad/s")});
  m_speedUnit->setCurrentIndex(settings->speedInRpm() ? 0 : 1);
  speedLayout->addWidget(fieldBox(Field::Speed), 1);
  speedLayout->addWidget(m_speedUnit);
  m_form->addRow(fieldLabel(Field::Speed), m_speedRow);
  m_form->addRow(fieldLabel(Field::Acceleration), fieldBox(Field::Acceleration));
  for (const Field f : {Field::Start, Field::RampTime, Field::Rise, Field::Duration})
    m_form->addRow(fieldLabel(f), fieldBox(f));
  m_tableRow = new QWidget(this);
  auto* tableLayout = new QHBoxLayout(m_tableRow);
  tableLayout->setContentsMargins(0, 0, 0, 0);
  m_tableName->setWordWrap(true);
  tableLayout->addWidget(m_tableName, 1);
  tableLayout->addWidget(m_loadTable);
  m_loadTable->setToolTip(
      tr("A CSV file: a header time_s,crank_angle_deg (or _rad), then one time,angle row per instant"));
  m_form->addRow(tr("Table"), m_tableRow);
  for (const Field f : {Field::FromTime, Field::ToTime}) m_form->addRow(fieldLabel(f), fieldBox(f));
  m_samples->setRange(0, 1'000'000'000);
  m_samples->setKeyboardTracking(false);
  m_samples->setToolTip(tr("Samples of the analysis grid or time base, ends included (the CSV export's rows)"));
  m_form->addRow(tr("Samples"), m_samples);
  m_axis->addItems({timeAxisTitle(), inputDisplayName(document->mechanism())});
  m_axis->setToolTip(tr("What the plots run against: the time (with a motion law) or the input"));
  m_form->addRow(tr("Plot x axis"), m_axis);
  layout->addWidget(box);
  m_message->setObjectName(QStringLiteral("drive_message"));
  layout->addWidget(m_message);

  connect(m_driver, &QComboBox::currentIndexChanged, this, [this](int index) {
    if (!m_refreshing) editDriver(index);
  });
  connect(m_law, &QComboBox::currentIndexChanged, this, [this](int index) {
    if (!m_refreshing) editDrive(index);
  });
  connect(m_speedUnit, &QComboBox::currentIndexChanged, this, [this](int index) {
    if (m_refreshing) return;
    m_settings->setSpeedInRpm(index == 0);
    refresh();
  });
  connect(m_samples, &QSpinBox::valueChanged, this, [this] { editSamples(); });
  connect(m_loadTable, &QPushButton::clicked, this, &DrivePanel::chooseTable);
  connect(m_axis, &QComboBox::currentIndexChanged, this, [this](int index) {
    if (!m_refreshing) m_document->setPlotAxis(index == 0 ? PlotAxis::Time : PlotAxis::Input);
  });
  connect(document, &MechanismDocument::changed, this, [this](Changes what) {
    if (what & (Changes(Change::Design) | Change::PlotAxis)) refresh();
  });
  refresh();
}

QString DrivePanel::refusalMessage() const { return m_message->refusal(); }

DrivePanel::Drive DrivePanel::driveOf(const k::Design& design) {
  if (!design.time) return Drive::AngleGrid;
  return std::visit(
      [](const auto& law) {
        using Law = std::decay_t<decltype(law)>;
        if constexpr (std::is_same_v<Law, k::ConstantVelocity>) return Drive::ConstantSpeed;
        else if constexpr (std::is_same_v<Law, k::RampToSpeed>) return Drive::RampToSpeed;
        else if constexpr (std::is_same_v<Law, k::CycloidalRise>) return Drive::CycloidalRise;
        else if constexpr (std::is_same_v<Law, k::PolynomialRise>) return Drive::PolynomialRise;
        else return Drive::Table;
      },
      design.time->law);
}

bool DrivePanel::crankInput() const { return k::inputKind(m_document->mechanism()) == k::InputKind::Angle; }

QString DrivePanel::fieldLabel(Field field) const {
  const bool grid = !m_document->onTimeBase();
  const bool crank = crankInput();
  switch (field) {
  case Field::Speed:
    if (grid) return crank ? tr("Crank speed ω₂") : tr("Input speed");
    return driveOf(m_document->design()) == Drive::RampToSpeed ? tr("Final speed") : tr("Speed");
  case Field::Acceleration: return crank ? tr("Crank accel. α₂") : tr("Input accel.");
  case Field::Start: return crank ? tr("Start angle") : tr("Start position");
  case Field::RampTime: return tr("Ramp time");
  case Field::Rise: return tr("Rise");
  case Field::Duration: return tr("Duration");
  case Field::FromTime: return tr("From time");
  case Field::ToTime: return tr("To time");
  }
  return {};
}

// A crank's speed in rpm or rad/s as the unit box says; a linear input's in its length unit per s.
double DrivePanel::speedToShown(double rate) const {
  return crankInput() && m_speedUnit->currentIndex() == 0 ? k::radPerSecToRpm(rate) : rate;
}

double DrivePanel::speedFromShown(double shown) const {
  return crankInput() && m_speedUnit->currentIndex() == 0 ? k::rpmToRadPerSec(shown) : shown;
}

QString DrivePanel::speedUnit() const {
  if (!crankInput()) return QString::fromStdString(m_document->lengthUnit()) + tr("/s");
  return m_speedUnit->currentIndex() == 0 ? tr("rpm") : tr("rad/s");
}

QString DrivePanel::positionUnit() const {
  return crankInput() ? tr("°") : QString::fromStdString(m_document->lengthUnit());
}

void DrivePanel::refresh() {
  m_refreshing = true;
  const k::Design& d = m_document->design();
  const Drive drive = driveOf(d);
  QStringList drivers;
  for (const k::DriverChoice& choice : k::driverChoices(d.mechanism))
    drivers << QString::fromStdString(choice.description);
  setComboItems(m_driver, drivers);
  m_driver->setCurrentIndex(0);  // the first choice is the joint that drives now
  m_driver->setEnabled(m_driver->count() > 1);
  m_driver->setToolTip(m_driver->count() > 1
                           ? tr("Drive the linkage from another joint: the joint next to the driver takes the input, "
                                "the linkage stays where it is")
                           : tr("This linkage has no other joint it can be driven from"));
  m_law->setCurrentIndex(static_cast<int>(drive));
  const bool grid = drive == Drive::AngleGrid;
  const bool rise = drive == Drive::CycloidalRise || drive == Drive::PolynomialRise;
  m_form->setRowVisible(m_speedRow, grid || drive == Drive::ConstantSpeed || drive == Drive::RampToSpeed);
  m_form->setRowVisible(fieldBox(Field::Acceleration), grid);
  m_form->setRowVisible(fieldBox(Field::Start), !grid && drive != Drive::Table);
  m_form->setRowVisible(fieldBox(Field::RampTime), drive == Drive::RampToSpeed);
  m_form->setRowVisible(fieldBox(Field::Rise), rise);
  m_form->setRowVisible(fieldBox(Field::Duration), rise);
  m_form->setRowVisible(m_tableRow, drive == Drive::Table);
  m_form->setRowVisible(fieldBox(Field::FromTime), !grid);
  m_form->setRowVisible(fieldBox(Field::ToTime), !grid);
  for (const Field f : {Field::Speed, Field::Acceleration, Field::Start})
    if (auto* label = qobject_cast<QLabel*>(m_form->labelForField(f == Field::Speed ? m_speedRow : fieldBox(f))))
      label->setText(fieldLabel(f));

  // A crank's angles in degrees and its speed in rpm or rad/s; a linear input's in its length unit.
  const bool crank = crankInput();
  m_speedUnit->setVisible(crank);
  const auto suffix = [](const QString& unit) {
    return unit == QStringLiteral("°") ? unit : QStringLiteral(" ") + unit;
  };
  setSuffixQuietly(fieldBox(Field::Speed), suffix(speedUnit()));
  setSuffixQuietly(fieldBox(Field::Acceleration),
                   crank ? tr(" rad/s²") : suffix(QString::fromStdString(m_document->lengthUnit()) + tr("/s²")));
  for (const Field f : {Field::Start, Field::Rise}) setSuffixQuietly(fieldBox(f), suffix(positionUnit()));
  const auto show = [this](Field f, std::optional<double> value) {
    if (value) setValueQuietly(fieldBox(f), *value);
  };
  if (d.time) {
    const k::MotionLaw& law = d.time->law;
    const auto shown = [&d](std::optional<double> q) {
      return q ? std::optional(k::inputDisplayValue(d.mechanism, *q)) : q;
    };
    const std::optional<double> velocity = lawMember(law, Field::Speed);
    show(Field::Speed, velocity ? std::optional(speedToShown(*velocity)) : std::nullopt);
    show(Field::Start, shown(lawMember(law, Field::Start)));
    show(Field::Rise, shown(lawMember(law, Field::Rise)));
    show(Field::Duration, lawMember(law, Field::Duration));
    show(Field::RampTime, lawMember(law, Field::RampTime));
    show(Field::FromTime, d.time->fromTime);
    show(Field::ToTime, d.time->toTime);
    if (const auto* table = std::get_if<k::TableLaw>(&law)) {
      const QString rows = tr("%1 rows, %2 to %3 s")
                               .arg(table->time.size())
                               .arg(numberText(table->time.front()), numberText(table->time.back()));
      m_tableName->setText(m_tablePath.isEmpty() ? rows
                                                 : QFileInfo(m_tablePath).fileName() + QStringLiteral(": ") + rows);
    }
  } else {
    show(Field::Speed, speedToShown(d.omega));
    show(Field::Acceleration, d.alpha);
  }
  setValueQuietly(m_samples, static_cast<int>(std::min<std::size_t>(d.samples, 1'000'000'000)));

  // The time axis needs a time base; without one the plots run against the input.
  if (auto* model = qobject_cast<QStandardItemModel*>(m_axis->model())) {
    model->item(0)->setEnabled(d.time.has_value());
    model->item(1)->setText(inputDisplayName(d.mechanism));
  }
  m_axis->setCurrentIndex(m_document->plotAxis() == PlotAxis::Time ? 0 : 1);
  m_refreshing = false;
}

std::optional<QString> DrivePanel::checkField(Field field, double value) const {
  const QString name = fieldLabel(field);
  const QString got = numberText(value);
  const auto within = [&](double bound, const QString& unit) -> std::optional<QString> {
    if (std::isfinite(value) && std::abs(value) <= bound) return std::nullopt;
    return tr("%1 must lie within ±%2 %3 (got %4 %3)").arg(name, boundText(bound), unit, got);
  };
  switch (field) {
  case Field::Speed: return within(speedToShown(k::kMaxOmega), speedUnit());
  case Field::Acceleration:
    return within(k::kMaxAlpha,
                  crankInput() ? tr("rad/s²") : QString::fromStdString(m_document->lengthUnit()) + tr("/s²"));
  case Field::Start:
  case Field::Rise:
    // The core's bound on a law's positions: ±1e6 degrees for a crank, the same number of
    // radians as a length.
    return within(k::inputDisplayValue(m_document->mechanism(), k::degToRad(k::kMaxAngleDeg)), positionUnit());
  case Field::RampTime:
  case Field::Duration:
    if (value > 0.0 && value <= kMaxTime) return std::nullopt;
    return tr("%1 must be positive and at most %2 s (got %3 s)").arg(name, boundText(kMaxTime), got);
  case Field::FromTime:
  case Field::ToTime: {
    if (auto why = within(kMaxTime, tr("s"))) return why;
    const k::TimeBase& time = *m_document->design().time;
    if (field == Field::FromTime && !(value < time.toTime))
      return tr("%1 must be before the to time, %2 s (got %3 s)").arg(name, numberText(time.toTime), got);
    if (field == Field::ToTime && !(value > time.fromTime))
      return tr("%1 must be after the from time, %2 s (got %3 s)").arg(name, numberText(time.fromTime), got);
    return std::nullopt;
  }
  }
  return std::nullopt;
}

void DrivePanel::editField(Field field) {
  if (m_refreshing) return;
  const double value = fieldBox(field)->value();
  if (auto why = checkField(field, value)) {
    showOutcome(why);
    return;
  }
  k::Design d = m_document->design();
  std::optional<MergeKey> key;
  switch (field) {
  case Field::Speed:
    if (d.time) {
      setLawMember(d.time->law, field, speedFromShown(value));
    } else {
      d.omega = speedFromShown(value);
      key = MergeKey{ContinuousEdit::Speed, 0, m_editSerial++};
    }
    break;
  case Field::Acceleration:
    d.alpha = value;
    key = MergeKey{ContinuousEdit::Acceleration, 0, m_editSerial++};
    break;
  case Field::Start:
  case Field::Rise:
    if (d.time) setLawMember(d.time->law, field, k::inputFromDisplay(d.mechanism, value));
    break;
  case Field::RampTime:
  case Field::Duration:
    if (d.time) setLawMember(d.time->law, field, value);
    break;
  case Field::FromTime:
    if (d.time) d.time->fromTime = value;
    break;
  case Field::ToTime:
    if (d.time) d.time->toTime = value;
    break;
  }
  showOutcome(m_document->edit(d, tr("Change %1").arg(fieldLabel(field).toLower()), key));
}

void DrivePanel::editSamples() {
  if (m_refreshing) return;
  const int value = m_samples->value();
  if (value < 2 || value > kMostSamples) {
    showOutcome(tr("Samples must be between 2 and %1 (got %2)").arg(kMostSamples).arg(value));
    return;
  }
  k::Design d = m_document->design();
  d.samples = static_cast<std::size_t>(value);
  showOutcome(m_document->edit(d, tr("Change samples")));
}

void DrivePanel::editDriver(int index) {
  const k::Design& design = m_document->design();
  const std::vector<k::DriverChoice> choices = k::driverChoices(design.mechanism);
  if (index <= 0 || static_cast<std::size_t>(index) >= choices.size()) return;
  const auto next = k::driveFrom(design, choices[static_cast<std::size_t>(index)].point, m_document->crankAngle());
  if (!next) {
    showOutcome(tr("driving from %1: %2")
                    .arg(QString::fromStdString(choices[static_cast<std::size_t>(index)].description),
                         QString::fromStdString(next.error().message)));
    return;
  }
  // A motion law keeps its kind, its numbers now in the new input's coordinate and range; a
  // table of the old input's positions means nothing for the new one.
  const Drive drive = driveOf(design);
  const k::Design d =
      drive == Drive::AngleGrid || drive == Drive::Table ? next->design : withDrive(next->design, drive);
  showOutcome(m_document->edit(d, tr("Drive from %1").arg(m_driver->itemText(index)), std::nullopt, next->input));
}

void DrivePanel::editDrive(int index) {
  const auto drive = static_cast<Drive>(index);
  if (drive == driveOf(m_document->design())) return;
  if (drive == Drive::Table) {
    chooseTable();
    return;
  }
  showOutcome(m_document->edit(withDrive(m_document->design(), drive), tr("Drive: %1").arg(m_law->itemText(index))));
}

void DrivePanel::chooseTable() {
  const QString path =
      QFileDialog::getOpenFileName(this, tr("Load a q(t) table: a crank's angle or a linear driver's position in time"),
                                   QString(), tr("CSV tables (*.csv);;All files (*)"));
  if (path.isEmpty()) {
    refresh();  // the law box goes back to the drive the design has
    return;
  }
  loadTable(path);
}

std::optional<QString> DrivePanel::loadTable(const QString& path) {
  auto read = readLawTableFile(path, m_document->mechanism());
  if (auto* why = std::get_if<QString>(&read)) {
    showOutcome(*why);
    return *why;
  }
  auto& table = std::get<k::TableLaw>(read);
  k::Design d = m_document->design();
  const double from = table.time.front();
  const double to = table.time.back();
  d.time = k::TimeBase{std::move(table), from, to};
  const std::optional<QString> refusal =
      m_document->edit(d, tr("Drive by the table %1").arg(QFileInfo(path).fileName()));
  if (!refusal) m_tablePath = path;
  showOutcome(refusal);
  return refusal;
}

void DrivePanel::showOutcome(const std::optional<QString>& refusal) {
  m_message->showOutcome(refusal);
  refresh();  // a refused value snaps back to the document's
}

}  // namespace linkwright::ui
