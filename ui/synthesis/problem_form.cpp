#include "ui/synthesis/problem_form.h"

#include "ui/number_box.h"

#include "kinematics/design/synthesis_ranges.h"

#include <QDoubleSpinBox>
#include <QFormLayout>

namespace linkwright::ui {

namespace {
// Wide enough to type any wrong value and be told why; the core decides what it accepts. A
// document stores what the fields hold, and its reader takes the same range.
constexpr double kFieldLimit = kinematics::kMaxTargetValue;
}  // namespace

ProblemForm::ProblemForm(QWidget* parent) : QWidget(parent) {}

void ProblemForm::setLengthUnit(const QString& unit) {
  m_unit = unit;
  for (QDoubleSpinBox* box : m_lengthBoxes) box->setSuffix(QLatin1Char(' ') + unit);
}

QString ProblemForm::fieldLabel(const std::string& field) const {
  QString best;
  std::size_t bestLength = 0;
  for (const auto& [name, label] : m_labels) {
    const bool prefix = field.compare(0, name.size(), name) == 0 &&
                        (field.size() == name.size() || field[name.size()] == '.' || field[name.size()] == '[');
    if (prefix && name.size() > bestLength) {
      best = label;
      bestLength = name.size();
    }
  }
  return best;
}

QString ProblemForm::explain(const std::string& field, const std::string& message) const {
  const QString label = fieldLabel(field);
  QString text = QString::fromStdString(message);
  if (label.isEmpty()) return text;
  // The core's sentence names its field ("timeRatio must be…"); the form says it in its own
  // words, as the box's label, rather than beside them ("Time ratio Q: timeRatio must be…").
  const QString key = QString::fromStdString(field);
  if (text.startsWith(key + QLatin1Char(' '))) return label + text.mid(key.size());
  return tr("%1: %2").arg(label, text);
}

QDoubleSpinBox* ProblemForm::numberBox(const QString& label) const {
  const auto it = m_boxes.find(label);
  return it == m_boxes.end() ? nullptr : it->second;
}

QDoubleSpinBox* ProblemForm::addNumber(QFormLayout* form, const QString& label, double value, Kind kind,
                                       const std::string& field, int decimals) {
  auto* box = new NumberBox(this);
  box->setObjectName(QString::fromStdString(field));
  box->setDecimals(decimals);
  box->setRange(-kFieldLimit, kFieldLimit);
  box->setAccelerated(true);
  box->setValue(value);
  if (kind == Kind::Length) {
    box->setSuffix(QLatin1Char(' ') + m_unit);
    m_lengthBoxes.push_back(box);
  } else if (kind == Kind::Angle) {
    box->setSuffix(QStringLiteral("°"));
  }
  form->addRow(label, box);
  m_labels[field] = label;
  m_boxes[label] = box;
  connect(box, &QDoubleSpinBox::valueChanged, this, &ProblemForm::edited);
  return box;
}

}  // namespace linkwright::ui
