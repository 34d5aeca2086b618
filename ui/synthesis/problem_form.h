#pragma once
// The base of the synthesis panel's input forms, one per problem: number fields in a form
// layout, lengths in the document's unit (the suffix follows it) and angles in degrees, each
// field knowing which of the core's fields it feeds, so that a refusal from the core
// ("timeRatio must be … (got 0.5)") is shown under the label the user sees ("Time ratio Q").
// Fields accept more than the core does, so a wrong value can be typed and be told why.

#include "kinematics/design/synthesis_targets.h"

#include <QString>
#include <QWidget>

#include <map>
#include <string>
#include <vector>

class QDoubleSpinBox;
class QFormLayout;

namespace linkwright::ui {

class ProblemForm : public QWidget {
  Q_OBJECT
public:
  explicit ProblemForm(QWidget* parent = nullptr);

  /// Puts the length fields in `unit` (the document's length unit): only their suffix changes.
  void setLengthUnit(const QString& unit);
  QString lengthUnit() const { return m_unit; }
  /// The label of the field the core calls `field` ("timeRatio", "poses[1].angle"); the
  /// longest known prefix decides; empty if none is known.
  QString fieldLabel(const std::string& field) const;
  /// `message` as the panel shows it: "<label>: <message>" when the field is known.
  QString explain(const std::string& field, const std::string& message) const;
  /// Shows this form's part of saved targets (design/synthesis_targets.h), without emitting
  /// edited().
  virtual void load(const kinematics::SynthesisTargets& targets) = 0;
  /// Writes the fields, as typed, into this form's part of `targets` (angles in radians); a
  /// table with a cell that cannot be read leaves its part as it was.
  virtual void store(kinematics::SynthesisTargets& targets) const = 0;

  /// The number box labelled `label`, if any (for tests).
  QDoubleSpinBox* numberBox(const QString& label) const;

signals:
  /// A field changed: the panel solves again (closed form) or marks the result stale (path).
  void edited();

protected:
  enum class Kind { Plain, Length, Angle };
  /// Adds a number row to `form`, fed to the core's `field`.
  QDoubleSpinBox* addNumber(QFormLayout* form, const QString& label, double value, Kind kind, const std::string& field,
                            int decimals = 4);
  /// Names a core field that has no number box of its own (a table row, a choice).
  void nameField(const std::string& field, const QString& label) { m_labels[field] = label; }

private:
  QString m_unit = QStringLiteral("mm");
  std::vector<QDoubleSpinBox*> m_lengthBoxes;
  std::map<std::string, QString> m_labels;
  std::map<QString, QDoubleSpinBox*> m_boxes;
};

}  // namespace linkwright::ui
