#pragma once
// The quantities the plots can show, what kind each is (angle, ω, α), which chart it goes on,
// its name, colour and the SolveRequest a selection of them needs. One table, so the
// checkboxes, the legends, the read-outs and the request all agree.

#include "ui/plots/angle_unit.h"

#include "kinematics/solve/pose.h"

#include <QColor>
#include <QString>

#include <array>

namespace linkwright::ui {

enum class PlotQuantity {
  CouplerAngle, RockerAngle, TransmissionAngle,
  CouplerOmega, RockerOmega,
  CouplerAlpha, RockerAlpha,
};
inline constexpr int kPlotQuantityCount = 7;

/// What a quantity is; one chart per kind, in this order.
enum class QuantityKind { Angle, Omega, Alpha };
inline constexpr int kQuantityKindCount = 3;

/// All quantities, in checkbox and legend order.
constexpr std::array<PlotQuantity, kPlotQuantityCount> allPlotQuantities() {
  return {PlotQuantity::CouplerAngle, PlotQuantity::RockerAngle, PlotQuantity::TransmissionAngle,
          PlotQuantity::CouplerOmega, PlotQuantity::RockerOmega,
          PlotQuantity::CouplerAlpha, PlotQuantity::RockerAlpha};
}

QuantityKind quantityKind(PlotQuantity quantity);
/// Stable, untranslated key after the CSV column names: "rocker_omega", "transmission_angle".
QString quantityKey(PlotQuantity quantity);
/// Legend and checkbox name: "rocker ω4", "transmission μ".
QString quantityName(PlotQuantity quantity);
/// Line colour, the same on every chart for the same link.
QColor quantityColor(PlotQuantity quantity);
/// Unit of the quantity's values: "deg", "rad/s", "deg/s²", ...
QString quantityUnit(QuantityKind kind, AngleUnit unit);
/// The y-axis title of a chart: "angle [deg]", "ω [rad/s]", "α [rad/s²]".
QString valueAxisTitle(QuantityKind kind, AngleUnit unit);
/// The x-axis title: "crank angle [deg]".
QString crankAxisTitle(AngleUnit unit);

/// Which quantities are shown.
class QuantitySelection {
public:
  /// Everything selected (the default).
  static QuantitySelection all();

  bool contains(PlotQuantity quantity) const { return m_on[index(quantity)]; }
  void set(PlotQuantity quantity, bool on) { m_on[index(quantity)] = on; }
  /// True if any quantity of `kind` is selected: its chart is shown.
  bool any(QuantityKind kind) const;
  bool operator==(const QuantitySelection&) const = default;

private:
  static std::size_t index(PlotQuantity q) { return static_cast<std::size_t>(q); }
  std::array<bool, kPlotQuantityCount> m_on{};
};

/// What the sweep must compute for `selection`: only positions unless an ω or α is shown;
/// accelerations (which imply velocities) only if an α is shown.
kinematics::SolveRequest requestFor(const QuantitySelection& selection);

} // namespace linkwright::ui
