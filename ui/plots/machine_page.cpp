#include "ui/plots/machine_page.h"

#include "ui/colors.h"
#include "ui/document/mechanism_document.h"
#include "ui/number_box.h"
#include "ui/number_text.h"
#include "ui/plots/force_chart_view.h"
#include "ui/plots/plot_x_axis.h"

#include "kinematics/design/design.h"
#include "kinematics/dynamics/machine_request.h"
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

// A field of the core's machine request (kinematics/dynamics/machine_request.h): its range, its
// unit and its help as the CLI and Python give them; an optional one reads "none" at 0.
QDoubleSpinBox* requestField(const std::string& key, int decimals, const QString& name) {
  const k::RequestField& f = *k::findField(k::machineFields(), key);
  const double step = std::pow(10.0, -decimals);
  const bool optional = !f.value && f.minimum == 0.0;
  auto* box = new NumberBox;
  box->setDecimals(decimals);
  // An end the field's decimals cannot show is moved inside the range by a step.
  const double low = f.minimumIncluded ? f.minimum : f.minimum + step;
  box->setRange(optional ? 0.0 : (low > 0.0 && low < step ? step : low),
                f.maximumIncluded ? f.maximum : f.maximum - step);
  if (optional) box->setSpecialValueText(MachinePage::tr("none"));
  box->setValue(f.value.value_or(key == "cs" ? 0.05 : 0.0));
  if (!f.unit.empty()) box->setSuffix(QStringLiteral(" ") + QString::fromStdString(f.unit));
  box->setToolTip(QString::fromStdString(k::helpText(f)));
  box->setObjectName(name);
  box->setKeyboardTracking(false);       // a value counts once typed, not at each keystroke
  box->setFocusPolicy(Qt::StrongFocus);  // the wheel scrolls the page until the field is clicked
  return box;
}

QString fieldLabel(const std::string& key) {
  return QString::fromStdString(k::fieldName(*k::findField(k::machineFields(), key), k::FrontEnd::Designer));
}

QString n(double value) { return numberText(value, 'g', 8); }

// The core's figures (dutyFigures) as the CLI lists them: as plain lines (figuresText) and as
// the page shows them, two figures a row so that the chart stays in sight on a laptop's screen.
struct FiguresText {
  QString plain;
  QString html;
};

FiguresText figures(const k::MachineRun& run, const k::MachineRequest& request) {
  const k::MachineDuty& d = run.duty;
  QStringList head, cells, tail, plain;
  QString accuracy = run.converged ? MachinePage::tr("every figure within %1 relative")
                                         .arg(QString::fromStdString(k::formatCompact(run.tolerance, 2)))
                                   : MachinePage::tr("the largest error estimate %1, over the tolerance %2")
                                         .arg(QString::fromStdString(k::formatCompact(d.worstAccuracy(), 2)),
                                              QString::fromStdString(k::formatCompact(run.tolerance, 2)));
  head << MachinePage::tr("One crank turn at %1 rad/s (%2 rpm), read at %3 samples; %4.")
              .arg(n(d.omega), n(k::radPerSecToRpm(d.omega)))
              .arg(run.samples)
              .arg(accuracy);
  head << MachinePage::tr("The motor through the gearbox (ratio %1, efficiency %2) turns at %3 rpm.")
              .arg(n(request.duty.gearRatio), n(request.duty.efficiency), n(k::radPerSecToRpm(d.motor.speed)));
  for (const k::DutyFigure& f : k::dutyFigures(d, request.duty)) {
    QString value = QStringLiteral("%1 %2").arg(n(f.value), QString::fromStdString(f.unit));
    if (f.accuracy && *f.accuracy > run.tolerance)
      value += MachinePage::tr(" (error estimate %1)").arg(QString::fromStdString(k::formatCompact(*f.accuracy, 2)));
    const QString label = QString::fromStdString(f.label);
    cells << QStringLiteral("%1: <b>%2</b>").arg(label.toHtmlEscaped(), value.toHtmlEscaped());
    plain << QStringLiteral("%1: %2").arg(label, value);
  }
  if (d.flywheelRun)
    tail << MachinePage::tr("Run in time with that flywheel, the speed varies by Cs %1, from %2 to %3 rad/s.")
                .arg(n(d.flywheelRun->speedFluctuation), n(d.flywheelRun->slowest()), n(d.flywheelRun->fastest()));
  tail << MachinePage::tr("Virtual-work check: the driving torque by virtual work is within %1 N·m of Newton–Euler's.")
              .arg(numberText(d.virtualWorkDifference, 'g', 2));
  if (!d.motor.verdict.empty()) tail << MachinePage::tr("Verdict: %1").arg(QString::fromStdString(d.motor.verdict));

  QString table = QStringLiteral("<table cellspacing=\"0\" cellpadding=\"1\">");
  for (qsizetype i = 0; i < cells.size(); i += 2)
    table += QStringLiteral("<tr><td>%1</td><td width=\"24\"></td><td>%2</td></tr>")
                 .arg(cells[i], i + 1 < cells.size() ? cells[i + 1] : QString());
  table += QStringLiteral("</table>");
  const auto paragraphs = [](const QStringList& lines) {
    QStringList escaped;
    for (const QString& line : lines) escaped << line.toHtmlEscaped();
    return escaped.join(QStringLiteral("<br>"));
  };
  return {(head + plain + tail).join(QLatin1Char('\n')),
          QStringLiteral("<p>%1</p>%2<p>%3</p>").arg(paragraphs(head), table, paragraphs(tail))};
}

}  // namespace

MachinePage::MachinePage(MechanismDocument* document, QWidget* parent)
    : QWidget(parent), m_document(document), m_cs(requestField("cs", 3, QStringLiteral("machineCs"))),
      m_gearRatio(requestField("gear_ratio", 3, QStringLiteral("machineGearRatio"))),
      m_efficiency(requestField("efficiency", 3, QStringLiteral("machineEfficiency"))),
      m_ratedTorque(requestField("rated_torque", 4, QStringLiteral("machineRatedTorque"))),
      m_ratedSpeed(requestField("rated_speed", 1, QStringLiteral("machineRatedSpeed"))), m_figures(new QLabel),
      m_speed(new ForceChartView(tr("Crank speed over a turn with the flywheel (forward dynamics)"), false)),
      m_run([this](const Outcome& outcome) { display(outcome); }) {
  // The fields, the figures across the page under them, then the chart; the whole
  // page scrolls when the pane is short, so nothing is clipped.
  auto* fields = new QGridLayout;
  const auto add = [fields](int row, const QString& label, QDoubleSpinBox* box) {
    auto* text = new QLabel(label);
    text->setBuddy(box);
    fields->addWidget(text, row, 0);
    fields->addWidget(box, row, 1);
  };
  add(0, tr("Speed fluctuation %1").arg(fieldLabel("cs")), m_cs);
  add(1, fieldLabel("gear_ratio"), m_gearRatio);
  add(2, tr("Gearbox %1").arg(fieldLabel("efficiency").toLower()), m_efficiency);
  add(3, tr("Motor's %1").arg(fieldLabel("rated_torque").toLower()), m_ratedTorque);
  add(4, tr("Motor's %1").arg(fieldLabel("rated_speed").toLower()), m_ratedSpeed);
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
  m_run.cancel();  // its answer is for the design or fields this change replaced
  if (m_onScreen) m_settle.start();
}

QString MachinePage::figuresText() const { return m_plain; }

void MachinePage::waitForFigures() { m_run.wait(); }

void MachinePage::refuse(const QString& why) {
  m_run.cancel();
  m_plain = why;
  m_figures->setTextFormat(Qt::PlainText);
  m_figures->setText(why);
  m_speed->setVisible(false);
}

void MachinePage::refresh() {
  if (!m_onScreen) return;
  m_stale = false;
  m_settle.stop();
  const k::Design& design = m_document->design();
  if (auto e = k::checkCrankDriven(design.mechanism))
    return refuse(tr("The flywheel and motor figures are for a crank turning at a steady speed: %1")
                      .arg(QString::fromStdString(e->message)));
  k::RequestValues values{
      {"cs", m_cs->value()}, {"gear_ratio", m_gearRatio->value()}, {"efficiency", m_efficiency->value()}};
  if (m_ratedTorque->value() > 0.0) values["rated_torque"] = m_ratedTorque->value();
  if (m_ratedSpeed->value() > 0.0) values["rated_speed"] = m_ratedSpeed->value();
  auto request = k::machineRequest(values, k::FrontEnd::Designer);
  if (!request) return refuse(QString::fromStdString(request.error().message));
  m_request = *request;
  m_run.start(machineJob(design, *request));
}

void MachinePage::display(const Outcome& outcome) {
  if (outcome.error) {
    if (outcome.error->code != k::ErrorCode::Cancelled) refuse(QString::fromStdString(outcome.error->message));
    return;
  }
  const k::MachineRun& run = *outcome.run;
  const FiguresText text = figures(run, m_request);
  m_plain = text.plain;
  m_figures->setTextFormat(Qt::RichText);
  m_figures->setText(text.html);
  if (!run.duty.flywheelRun) {
    m_speed->setVisible(false);
    return;
  }
  const k::FlywheelRun& flywheel = *run.duty.flywheelRun;
  const double cs = *m_request.duty.speedFluctuation;
  const auto toUnit = [this](double angle) { return m_unit == AngleUnit::Degrees ? k::radToDeg(angle) : angle; };
  QList<QPointF> points;
  for (std::size_t i = 0; i < flywheel.angle.size(); ++i) points.append({toUnit(flywheel.angle[i]), flywheel.speed[i]});
  const double from = points.front().x(), to = points.back().x();
  const double lowest = flywheel.meanSpeed * (1.0 - 0.5 * cs);
  const double highest = flywheel.meanSpeed * (1.0 + 0.5 * cs);
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
  const k::Design& design = m_document->design();
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
