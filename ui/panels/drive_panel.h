#pragma once
// What drives the linkage and how, and what the plots run against: the driver (the crank, or a
// joint next to it: kinematics/design/redrive.h), then constant speed over the grid (ω and
// α, no time base), or a motion law in time (kinematics/solve/motion_law.h: constant speed, a
// ramp to speed, a cycloidal or 3-4-5 rise, or a θ(t) table from a CSV file) with its numbers
// and the time base it is analysed on; the grid's sample count; and the plots' x axis (time or
// the input). A crank's numbers are in degrees and rpm or rad/s, a linear input's (an actuator,
// a point on a path) in its length unit (kinematics/model/driver.h). Each change is one
// undoable design edit through the document, checked field by field here (the field, the value and what is accepted) and then by the core; a
// refused value snaps back and a line says why, as in the dimensions panel.

#include "ui/document/mechanism_document.h"
#include "ui/panels/refusal_label.h"

#include <QString>
#include <QWidget>

#include <array>
#include <optional>

class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QLabel;
class QPushButton;
class QSpinBox;

namespace linkwright::ui {

class Settings;

class DrivePanel : public QWidget {
  Q_OBJECT
public:
  /// The choices of lawBox(), in its order.
  enum class Drive { AngleGrid, ConstantSpeed, RampToSpeed, CycloidalRise, PolynomialRise, Table };
  /// The numeric fields (samples has its own box).
  enum class Field { Speed, Acceleration, Start, RampTime, Rise, Duration, FromTime, ToTime };
  static constexpr int kFieldCount = 8;
  /// The most samples the designer accepts in its analysis grid: it sweeps them on every edit.
  static constexpr int kMostSamples = 100000;

  DrivePanel(MechanismDocument* document, Settings* settings, QWidget* parent = nullptr);

  /// The points the linkage can be driven from (kinematics::driverChoices), the driver first.
  QComboBox* driverBox() const { return m_driver; }
  QComboBox* lawBox() const { return m_law; }
  QComboBox* axisBox() const { return m_axis; }
  QComboBox* speedUnitBox() const { return m_speedUnit; }
  QDoubleSpinBox* fieldBox(Field field) const { return m_fields[static_cast<std::size_t>(field)]; }
  QSpinBox* samplesBox() const { return m_samples; }
  /// The last refusal, "Not applied: …"; empty when the last edit was accepted.
  QString refusalMessage() const;
  /// The drive `design` has.
  static Drive driveOf(const kinematics::Design& design);

  /// Drives the crank by the θ(t) table in the CSV file at `path` (the Load table… button
  /// without its dialog). Returns the refusal, if any: then nothing changes.
  std::optional<QString> loadTable(const QString& path);

private:
  void refresh();
  void editDriver(int index);
  void editDrive(int index);
  void editField(Field field);
  void editSamples();
  void chooseTable();
  void showOutcome(const std::optional<QString>& refusal);
  QString fieldLabel(Field field) const;
  std::optional<QString> checkField(Field field, double value) const;
  bool crankInput() const;
  double speedToShown(double rate) const;
  double speedFromShown(double shown) const;
  QString speedUnit() const;     // "rpm", "rad/s", "m/s"
  QString positionUnit() const;  // "°", "m"

  MechanismDocument* m_document;
  Settings* m_settings;
  QComboBox* m_driver;
  QComboBox* m_law;
  QComboBox* m_speedUnit;
  std::array<QDoubleSpinBox*, kFieldCount> m_fields{};
  QSpinBox* m_samples;
  QLabel* m_tableName;
  QPushButton* m_loadTable;
  QComboBox* m_axis;
  QFormLayout* m_form;
  RefusalLabel* m_message;
  QWidget* m_speedRow = nullptr;
  QWidget* m_tableRow = nullptr;
  QString m_tablePath;
  bool m_refreshing = false;
  int m_editSerial = 0;
};

}  // namespace linkwright::ui
