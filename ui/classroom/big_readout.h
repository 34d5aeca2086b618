#pragma once
// The big read-out (issue 21, the classroom): a strip of large type across the window that a
// back row reads, giving the input where the linkage stands and its main outputs there, e.g.
// "θ2 = 120.0°   θ4 = 75.3°   ω4 = −2.14 rad/s   μ = 48.2°". The input is the crank angle
// (after the time on a time base) or a path or actuator driver's length; the outputs are the
// angle and ω of the last link turning about a ground pivot (a four-bar's rocker), the first
// ground slider's position and velocity, and the first transmission angle, chosen from the
// plots' own quantities (plot_quantity.h). Every value is the core's: SweepColumn::valueOf on
// the document's solved pose, in the plots' angle unit and the document's length unit; a rate
// the pose does not have (a toggle position) or a value that is not finite reads "—". The
// choice of quantities is made on a design change; a crank move only rewrites the text.

#include "ui/document/mechanism_document.h"
#include "ui/plots/angle_unit.h"

#include "kinematics/solve/sweep_columns.h"

#include <QLabel>
#include <QString>

#include <vector>

namespace linkwright::ui {

/// One quantity of the read-out: what it is and its symbol ("θ4", "C x").
struct ReadoutQuantity {
  enum class Kind { Time, Input, Angle, AngularRate, Length, LengthRate };
  Kind kind = Kind::Input;
  kinematics::SweepColumn column;  ///< for Angle, AngularRate, Length, LengthRate
  QString symbol;
};

/// One entry as shown: "θ4" and "75.3°".
struct ReadoutEntry {
  QString symbol;
  QString value;  ///< with its unit; "—" where the value does not exist
};

/// The quantities the read-out shows for `document`'s linkage, in order.
std::vector<ReadoutQuantity> readoutQuantities(const MechanismDocument& document);
/// Their values at the document's current pose.
std::vector<ReadoutEntry> readoutEntries(const MechanismDocument& document,
                                         const std::vector<ReadoutQuantity>& quantities, AngleUnit unit);
/// A number as the read-out writes it: fixed `decimals`, a true minus sign (U+2212), "—" if
/// not finite.
QString readoutNumber(double value, int decimals);

class BigReadout : public QLabel {
  Q_OBJECT
public:
  explicit BigReadout(MechanismDocument* document, QWidget* parent = nullptr);

  /// The plots' angle unit: angles and angular rates are given in it.
  void setAngleUnit(AngleUnit unit);
  /// The type's size: `factor` times the normal read-out's (the window's presentation scale).
  void setPresentationScale(double factor);
  /// Takes the current theme's colours (ui/colors.h).
  void refreshColors();
  const std::vector<ReadoutEntry>& entries() const { return m_entries; }

protected:
  void resizeEvent(QResizeEvent* event) override;
  void showEvent(QShowEvent* event) override;

private:
  void onDocumentChanged(Changes what);
  void refresh();
  // The type at its full size again, then smaller if the text does not fit the width.
  void fitFont();

  MechanismDocument* m_document;
  AngleUnit m_unit = AngleUnit::Degrees;
  std::vector<ReadoutQuantity> m_quantities;
  std::vector<ReadoutEntry> m_entries;
  bool m_stale = false;       // the document changed while it was off screen
  double m_pointSize = 18.0;  // the type's full size
};

}  // namespace linkwright::ui
