#include "ui/plots/machine_page.h"

#include "ui/colors.h"
#include "ui/document/mechanism_document.h"
#include "ui/number_text.h"
#include "ui/plots/force_chart_view.h"
#include "ui/plots/plot_x_axis.h"

#include "kinematics/design/design.h"
#include "kinematics/dynamics/machine_duty.h"
#include "kinematics/model/units.h"

#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QLabel>
#include <QScrollArea>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace linkwright::ui {

namespace k = kinematics;

namespace {

constexpr int kSettleMs = 150;

QDoubleSpinBox* field(double low, double high, double value, int decimals, const QString& suffix, const QString& name) {
  auto* box = new QDoubleSpinBox;
  box->setRange(low, high);
  box->setDecimals(decimals);
  box->setValue(value);
  box->setSuffix(suffix);
  box->setObjectName(name);
  box->setKeyboardTracking(false);       // a value counts once typed, not at each keystroke
  box->setFocusPolicy(Qt::StrongFocus);  // the wheel scrolls the page until the field is clicked
  return box;
}

QString n(double value) { return numberText(value, 'g', 5); }

QString figures(const k::MachineDuty& d, const k::DutyOptions& o, std::size_t samples) {
  QStringList lines;
  lines << MachinePage::tr("One crank turn at %1 rad/s (%2 rpm), %3 samples.")
               .arg(n(d.omega), n(k::radPerSecToRpm(d.omega)))
               .arg(samples);
  lines << MachinePage::tr(
               "Driving torque: mean %1 N·m, RMS %2 N·m, peak %3 N·m. Power at the crank: mean %4 W, "
               "peak %5 W.")
               .arg(n(d.meanTorque), n(d.rmsTorque), n(d.peakTorque), n(d.meanPower), n(d.peakPower));
  lines << MachinePage::tr("Energy fluctuation ΔE %1 J (the turn's surplus above the mean torque).")
               .arg(n(d.energyFluctuation));
  if (d.flywheelInertia && d.flywheelRun)
    lines << MachinePage::tr(
                 "Flywheel for Cs %1: %2 kg·m² on the crank shaft, the linkage's own inertia counted (the "
                 "textbook ΔE/(Cs ω²) gives %3 kg·m²). Run in time with it, the speed varies by Cs %4, "
                 "from %5 to %6 rad/s.")
                 .arg(n(*o.speedFluctuation), n(*d.flywheelInertia), n(*d.textbookFlywheelInertia),
                      n(d.flywheelRun->speedFluctuation), n(d.flywheelRun->slowest()), n(d.flywheelRun->fastest()));
  lines << MachinePage::tr("Frame: shaking force peak %1 N, shaking moment peak %2 N·m; bearing load peak %3 N.")
               .arg(n(d.shakingForcePeak), n(d.shakingMomentPeak), n(d.bearingLoadPeak));
  lines << MachinePage::tr("Virtual-work check: the driving torque by virtual work is within %1 N·m of Newton–Euler's.")
               .arg(numberText(d.virtualWorkDifference, 'g', 2));
  lines << MachinePage::tr(
               "Motor through gear ratio %1 at efficiency %2: %3 rpm, RMS torque %4 N·m, peak %5 N·m, "
               "mean power %6 W, peak %7 W.")
               .arg(n(o.gearRatio), n(o.efficiency), n(k::radPerSecToRpm(d.motor.speed)), n(d.motor.rmsTorque),
                    n(d.motor.peakTorque), n(d.motor.meanPower), n(d.motor.peakPower));
  if (!d.motor.verdict.empty()) lines << MachinePage::tr("Verdict: %1").arg(QString::fromStdString(d.motor.verdict));
  return lines.join(QLatin1Char('\n'));
}

}  // namespace

MachinePage::MachinePage(MechanismDocument* document, QWidget* parent)
    : QWidget(parent), m_document(document), m_cs(field(0.001, 0.9, 0.05, 3, QString(), QStringLiteral("machineCs"))),
      m_gearRatio(field(0.001, k::kMaxGearRatio, 1.0, 3, QString(), QStringLiteral("machineGearRatio"))),
      m_efficiency(field(0.01, 1.0, 1.0, 3, QString(), QStringLiteral("machineEfficiency"))),
      m_ratedTorque(field(0.0, 1e9, 0.0, 4, tr(" N·m"), QStringLiteral("machineRatedTorque"))),
      m_ratedSpeed(field(0.0, 1e9, 0.0, 1, tr(" rpm"), QStringLiteral("machineRatedSpeed"))), m_figures(new QLabel),
      m_speed(new ForceChartView(tr("Crank speed over a turn with the flywheel (forward dynamics)"), false)) {
  m_ratedTorque->setSpecialValueText(tr("none"));
  m_ratedSpeed->setSpecialValueText(tr("none"));
  // The fields, the figures across the page under them, then the chart; the whole
  // page scrolls when the pane is short, so nothing is clipped.
  auto* fields = new QGridLayout;
  const auto add = [fields](int row, int column, const QString& label, const QString& tip, QDoubleSpinBox* box) {
    auto* text = new QLabel(label);
    text->setBuddy(box);
    box->setToolTip(tip);
    fields->addWidget(text, row, 2 * column);
    fields->addWidget(box, row, 2 * column + 1);
  };
  add(0, 0, tr("Speed fluctuation Cs"), tr("(ω_max − ω_min)/ω the flywheel is sized for"), m_cs);
  add(1, 0, tr("Gear ratio"), tr("motor turns per crank turn"), m_gearRatio);
  add(2, 0, tr("Gearbox efficiency"), tr("the gearbox's η, above 0 and at most 1"), m_efficiency);
  add(3, 0, tr("Motor's rated torque"), tr("the motor's continuous torque; none: no verdict"), m_ratedTorque);
  add(4, 0, tr("Motor's rated speed"), tr("the motor's rated speed; none: no verdict"), m_ratedSpeed);
  fields->setColumnStretch(2, 1);
  m_figures->setObjectName(QStringLiteral("machineFigures"));
  m_figures->setWordWrap(true);
  m_figures->setTextInteractionFlags(Qt::TextSelectableByMouse);
  auto* content = new QWidget;
  auto* column = new QVBoxLayout(content);
  column->setContentsMargins(4, 4, 4, 4);
  column->addLayout(fields);
  column->addWidget(m_figures);
  m_speed->setMinimumHeight(240);
  column->addWidget(m_speed, 1);
  auto* scroll = new QScrollArea;
  scroll->setWidgetResizable(true);
  scroll->setFrameShape(QFrame::NoFrame);
  scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);  // the figures wrap to the pane
  scroll->setWidget(content);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(scroll);

  m_settle.setSingleShot(true);
  m_settle.setInterval(kSettleMs);
  connect(&m_settle, &QTimer::timeout, this, &MachinePage::refresh);
  for (QDoubleSpinBox* box : {m_cs, m_gearRatio, m_efficiency, m_ratedTorque, m_ratedSpeed})
    connect(box, &QDoubleSpinBox::valueChanged, this, &MachinePage::designChanged);
}

void MachinePage::setAngleUnit(AngleUnit unit) {
  if (unit == m_unit) return;
  m_unit = unit;
  designChanged();
}

void MachinePage::setOnScreen(bool onScreen) {
  m_onScreen = onScreen;
  if (onScreen && m_stale) refresh();
}

void MachinePage::designChanged() {
  m_stale = true;
  if (m_onScreen) m_settle.start();
}

QString MachinePage::figuresText() const { return m_figures->text(); }

void MachinePage::refresh() {
  if (!m_onScreen) return;
  m_stale = false;
  m_settle.stop();
  const k::Design& design = m_document->design();
  const auto refuse = [this](const QString& why) {
    m_figures->setText(why);
    m_speed->setVisible(false);
  };
  if (auto e = k::checkCrankDriven(design.mechanism))
    return refuse(tr("The flywheel and motor figures are for a crank turning at a steady speed: %1")
                      .arg(QString::fromStdString(e->message)));
  k::DutyOptions options;
  options.speedFluctuation = m_cs->value();
  options.gearRatio = m_gearRatio->value();
  options.efficiency = m_efficiency->value();
  if (m_ratedTorque->value() > 0.0) options.ratedTorque = m_ratedTorque->value();
  if (m_ratedSpeed->value() > 0.0) options.ratedSpeed = k::rpmToRadPerSec(m_ratedSpeed->value());
  const k::SweepSpec turn = k::designTurn(design);
  const auto duty = k::machineDuty(design.mechanism, design.dynamics, turn, options);
  if (!duty) return refuse(QString::fromStdString(duty.error().message));
  m_figures->setText(figures(*duty, options, turn.samples));

  const k::FlywheelRun& run = *duty->flywheelRun;
  const auto toUnit = [this](double angle) { return m_unit == AngleUnit::Degrees ? k::radToDeg(angle) : angle; };
  SeriesRuns speed, low, high;
  QList<QPointF> points;
  for (std::size_t i = 0; i < run.angle.size(); ++i) points.append({toUnit(run.angle[i]), run.speed[i]});
  const double from = points.front().x(), to = points.back().x();
  const double lowest = run.meanSpeed * (1.0 - 0.5 * *options.speedFluctuation);
  const double highest = run.meanSpeed * (1.0 + 0.5 * *options.speedFluctuation);
  const auto line = [](QList<QPointF> runPoints) {
    SeriesRuns r;
    r.minY = r.maxY = runPoints.front().y();
    for (const QPointF& p : runPoints) {
      r.minY = std::min(r.minY, p.y());
      r.maxY = std::max(r.maxY, p.y());
    }
    r.runs.append(std::move(runPoints));
    return r;
  };
  PlotXAxis x;
  x.source = {PlotAxis::Input, k::InputKind::Angle};
  x.range = exactAxisRange(std::min(from, to), std::max(from, to));
  x.title = inputAxisTitle(design.mechanism, m_unit);
  x.inputName = inputDisplayName(design.mechanism);
  m_speed->setCurves({{QStringLiteral("speed"), tr("ω, run in time"), linkColor(0)},
                      {QStringLiteral("slowest"), tr("ω̄ (1 − Cs/2)"), linkColor(3)},
                      {QStringLiteral("fastest"), tr("ω̄ (1 + Cs/2)"), linkColor(2)}});
  m_speed->setData({line(points), line({{from, lowest}, {to, lowest}}), line({{from, highest}, {to, highest}})},
                   tr("crank speed [rad/s]"), x);
  m_speed->setVisible(true);
}

}  // namespace linkwright::ui
