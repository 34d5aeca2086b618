#include "ui/synthesis/synthesis_forms.h"

#include "ui/number_text.h"

#include "kinematics/model/units.h"
#include "kinematics/synthesis/named_function.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QSignalBlocker>
#include <QSpinBox>

#include <cmath>

namespace linkwright::ui {

namespace k = kinematics;

namespace {

QFormLayout* formLayout(QWidget* form) {
  auto* layout = new QFormLayout(form);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
  return layout;
}

QComboBox* addChoice(ProblemForm* form, QFormLayout* layout, const QString& label, const QStringList& items) {
  auto* box = new QComboBox(form);
  box->addItems(items);
  layout->addRow(label, box);
  QObject::connect(box, &QComboBox::currentIndexChanged, form, &ProblemForm::edited);
  return box;
}

QSpinBox* addCount(ProblemForm* form, QFormLayout* layout, const QString& label, int value, int low, int high) {
  auto* box = new QSpinBox(form);
  box->setRange(low, high);
  box->setValue(value);
  layout->addRow(label, box);
  QObject::connect(box, &QSpinBox::valueChanged, form, &ProblemForm::edited);
  return box;
}

// Sets a box without emitting its change: loading saved targets is not an edit.
template <typename Box, typename Value>
void setQuietly(Box* box, Value value) {
  const QSignalBlocker block(box);
  box->setValue(value);
}

void chooseQuietly(QComboBox* box, int index) {
  const QSignalBlocker block(box);
  box->setCurrentIndex(index);
}

k::Error refusal(const std::string& field, const QString& message) {
  return k::Error{k::ErrorCode::InvalidValue, field, message.toStdString()};
}

// A span typed in degrees: nonzero and less than a turn, as the core wants it in radians.
std::optional<k::Error> checkSpanDeg(double degrees, const std::string& field, const QString& label) {
  if (degrees != 0.0 && std::abs(degrees) < 360.0) return std::nullopt;
  return refusal(field, QCoreApplication::translate("FunctionForm",
                                                    "%1: must be nonzero and less than 360° in size "
                                                    "(got %2°)")
                            .arg(label, numberText(degrees)));
}

}  // namespace

CrankRockerForm::CrankRockerForm(QWidget* parent) : ClosedForm(parent) {
  QFormLayout* form = formLayout(this);
  m_swing = addNumber(form, tr("Rocker swing ψ"), 60.0, Kind::Angle, "swing");
  m_timeRatio = addNumber(form, tr("Time ratio Q"), 1.3, Kind::Plain, "timeRatio");
  m_timeRatio->setToolTip(tr("Slow stroke / quick stroke, from 1 (no quick return) to 100"));
  m_scale = addChoice(this, form, tr("Fixed length"), {tr("Rocker"), tr("Frame")});
  m_length = addNumber(form, tr("Its length"), 45.0, Kind::Length, "length");
  m_count = addCount(this, form, tr("Family members"), 41, 1, 1000);
  m_count->setToolTip(tr("How many crank-rockers of the family to list, spread evenly over it, besides the best"));
}

k::Result<ClosedFormRequest> CrankRockerForm::request() const {
  k::SynthesisTargets t;
  store(t);
  return ClosedFormRequest(SwingRequest{t.swing, static_cast<std::size_t>(m_count->value())});
}

void CrankRockerForm::load(const k::SynthesisTargets& t) {
  setQuietly(m_swing, k::radToDeg(t.swing.swing));
  setQuietly(m_timeRatio, t.swing.timeRatio);
  chooseQuietly(m_scale, t.swing.scale == k::SwingScale::Frame ? 1 : 0);
  setQuietly(m_length, t.swing.length);
}

void CrankRockerForm::store(k::SynthesisTargets& t) const {
  t.swing = {k::degToRad(m_swing->value()), m_timeRatio->value(), m_length->value(),
             m_scale->currentIndex() == 1 ? k::SwingScale::Frame : k::SwingScale::Rocker, lengthUnit().toStdString()};
}

SliderCrankForm::SliderCrankForm(QWidget* parent) : ClosedForm(parent) {
  QFormLayout* form = formLayout(this);
  m_stroke = addNumber(form, tr("Stroke H"), 100.0, Kind::Length, "stroke");
  m_timeRatio = addNumber(form, tr("Time ratio Q"), 1.2, Kind::Plain, "timeRatio");
  m_choice = addChoice(this, form, tr("Fixed"), {tr("Rod length"), tr("Offset")});
  m_value = addNumber(form, tr("Its value"), 120.0, Kind::Length, "rod");
  nameField("offset", tr("Its value"));
}

k::Result<ClosedFormRequest> SliderCrankForm::request() const {
  k::SynthesisTargets t;
  store(t);
  return ClosedFormRequest(t.slider);
}

void SliderCrankForm::load(const k::SynthesisTargets& t) {
  setQuietly(m_stroke, t.slider.stroke);
  setQuietly(m_timeRatio, t.slider.timeRatio);
  chooseQuietly(m_choice, t.slider.choice == k::SliderChoice::Offset ? 1 : 0);
  setQuietly(m_value, t.slider.value);
}

void SliderCrankForm::store(k::SynthesisTargets& t) const {
  t.slider = {m_stroke->value(), m_timeRatio->value(),
              m_choice->currentIndex() == 1 ? k::SliderChoice::Offset : k::SliderChoice::Rod, m_value->value(),
              lengthUnit().toStdString()};
}

ShaperForm::ShaperForm(QWidget* parent) : ClosedForm(parent) {
  QFormLayout* form = formLayout(this);
  m_stroke = addNumber(form, tr("Stroke H"), 100.0, Kind::Length, "stroke");
  m_timeRatio = addNumber(form, tr("Time ratio Q"), 1.5, Kind::Plain, "timeRatio");
  m_timeRatio->setToolTip(tr("Slow stroke / quick stroke, above 1 (a crank-shaper always returns quickly)"));
  m_crank = addNumber(form, tr("Crank r"), 25.0, Kind::Length, "crank");
  m_link = addNumber(form, tr("Link to the ram"), 60.0, Kind::Length, "link");
}

k::Result<ClosedFormRequest> ShaperForm::request() const {
  k::SynthesisTargets t;
  store(t);
  return ClosedFormRequest(t.shaper);
}

void ShaperForm::load(const k::SynthesisTargets& t) {
  setQuietly(m_stroke, t.shaper.stroke);
  setQuietly(m_timeRatio, t.shaper.timeRatio);
  setQuietly(m_crank, t.shaper.crank);
  setQuietly(m_link, t.shaper.link);
}

void ShaperForm::store(k::SynthesisTargets& t) const {
  t.shaper = {m_stroke->value(), m_timeRatio->value(), m_crank->value(),
              m_link->value(),   std::nullopt,         lengthUnit().toStdString()};
}

FunctionForm::FunctionForm(QWidget* parent) : ClosedForm(parent) {
  QFormLayout* form = formLayout(this);
  QStringList names;
  for (const k::NamedFunction& f : k::namedFunctions())
    names << QString::fromUtf8(f.label.data(), static_cast<qsizetype>(f.label.size()));
  m_function = addChoice(this, form, tr("y = f(x)"), names);
  nameField("function", tr("y = f(x)"));
  m_x0 = addNumber(form, tr("x0"), 1.0, Kind::Plain, "x0");
  m_x1 = addNumber(form, tr("x1"), 10.0, Kind::Plain, "x1");
  m_inputStart = addNumber(form, tr("Input start"), 60.0, Kind::Angle, "inputStart");
  m_inputSpan = addNumber(form, tr("Input span"), 120.0, Kind::Angle, "inputSpan");
  m_outputStart = addNumber(form, tr("Output start"), 240.0, Kind::Angle, "outputStart");
  m_outputSpan = addNumber(form, tr("Output span"), 60.0, Kind::Angle, "outputSpan");
  m_frame = addNumber(form, tr("Frame length"), 50.0, Kind::Length, "frame");
  m_points = addCount(this, form, tr("Chebyshev points"), 3, 3, 50);
  nameField("points", tr("Chebyshev points"));
  nameField("count", tr("Chebyshev points"));
  m_points->setToolTip(tr("3 are met exactly; more are fitted by least squares"));
}

k::Result<ClosedFormRequest> FunctionForm::request() const {
  const k::NamedFunction& f = k::namedFunctions()[static_cast<std::size_t>(std::max(0, m_function->currentIndex()))];
  const double x0 = m_x0->value(), x1 = m_x1->value();
  if (!(x1 > x0))
    return refusal("x1", tr("x1: must be greater than x0 (got x0 %1, x1 %2)").arg(numberText(x0), numberText(x1)));
  if (auto e = k::checkFunctionRange(f, x0, x1)) return refusal(e->field, explain(e->field, e->message));
  if (auto e = checkSpanDeg(m_inputSpan->value(), "inputSpan", tr("Input span"))) return *e;
  if (auto e = checkSpanDeg(m_outputSpan->value(), "outputSpan", tr("Output span"))) return *e;
  FunctionRequest r;
  r.target.f = f.f;
  r.target.x0 = x0;
  r.target.x1 = x1;
  r.target.inputStart = k::degToRad(m_inputStart->value());
  r.target.inputSpan = k::degToRad(m_inputSpan->value());
  r.target.outputStart = k::degToRad(m_outputStart->value());
  r.target.outputSpan = k::degToRad(m_outputSpan->value());
  r.target.frame = m_frame->value();
  r.target.lengthUnit = lengthUnit().toStdString();
  r.options.count = static_cast<std::size_t>(m_points->value());
  return ClosedFormRequest(r);
}

void FunctionForm::load(const k::SynthesisTargets& t) {
  const k::FunctionSpec& f = t.function;
  const auto& functions = k::namedFunctions();
  for (std::size_t i = 0; i < functions.size(); ++i)
    if (functions[i].name == f.function) chooseQuietly(m_function, static_cast<int>(i));
  setQuietly(m_x0, f.x0);
  setQuietly(m_x1, f.x1);
  setQuietly(m_inputStart, k::radToDeg(f.inputStart));
  setQuietly(m_inputSpan, k::radToDeg(f.inputSpan));
  setQuietly(m_outputStart, k::radToDeg(f.outputStart));
  setQuietly(m_outputSpan, k::radToDeg(f.outputSpan));
  setQuietly(m_frame, f.frame);
  setQuietly(m_points, static_cast<int>(f.count));
}

void FunctionForm::store(k::SynthesisTargets& t) const {
  const auto index = static_cast<std::size_t>(std::max(0, m_function->currentIndex()));
  t.function = {std::string(k::namedFunctions()[index].name),
                m_x0->value(),
                m_x1->value(),
                k::degToRad(m_inputStart->value()),
                k::degToRad(m_inputSpan->value()),
                k::degToRad(m_outputStart->value()),
                k::degToRad(m_outputSpan->value()),
                m_frame->value(),
                {},
                static_cast<std::size_t>(m_points->value())};
}

}  // namespace linkwright::ui
