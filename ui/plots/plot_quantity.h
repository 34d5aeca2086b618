#pragma once
// The quantities the plots can show for the current mechanism, read off its structure the way
// the CSV columns are (kinematics/solve/sweep_columns.h): the angle, ω and α of every moving link
// but the driven crank, the transmission angle at every dyad joint that has one, each
// slider's position, velocity and acceleration along the axis its ground guide mostly runs,
// and for a four-bar or a slider-crank its velocity ratio and mechanical advantage (from the
// instant centres at each sample: kinematics/analysis/advantage_sweep.h).
// Each has a kind (which chart it goes on), a key, a name, a colour (the link's, as on the
// canvas), and the SolveRequest a selection of them needs follows from their kinds. One
// table, so the checkboxes, the legends, the read-outs and the request all agree.

#include "ui/plots/angle_unit.h"

#include "kinematics/analysis/instant_centres.h"
#include "kinematics/model/mechanism.h"
#include "kinematics/solve/pose.h"
#include "kinematics/solve/sweep_columns.h"

#include <QColor>
#include <QString>

#include <QStringList>

#include <array>
#include <optional>
#include <vector>

namespace linkwright::ui {

/// What a quantity is; one chart per kind, in this order.
enum class QuantityKind { Angle, Omega, Alpha, Position, Velocity, Acceleration, VelocityRatio, Advantage };
inline constexpr int kQuantityKindCount = 8;

/// Angle, ω and α are shown in the angle unit; slider kinds in the length unit; ratios in the core's.
constexpr bool isAngular(QuantityKind kind) {
  return kind == QuantityKind::Angle || kind == QuantityKind::Omega || kind == QuantityKind::Alpha;
}

/// A ratio of output to input motion the instant centres give (instant_centres.h): for a
/// turning output b, ωb/ω2 and Tb/T2 (dimensionless, a four-bar's ω4/ω2 and T4/T2); for a
/// sliding one, v/ω2 (length unit per rad) and F/T2 (1 / length unit).
enum class RatioQuantity { None, VelocityRatio, Advantage };

/// One plottable quantity: a sweep column of a link or a point (its `index`), or a ratio.
struct PlotQuantity {
  kinematics::ColumnQuantity column = kinematics::ColumnQuantity::LinkAngle;
  std::size_t index = 0;
  /// Not None: this ratio between the `bodies` of the linkage (then `column` and `index` are
  /// unused).
  RatioQuantity ratio = RatioQuantity::None;
  kinematics::RatioBodies bodies;
  bool operator==(const PlotQuantity&) const = default;

  static PlotQuantity ofRatio(RatioQuantity ratio, kinematics::RatioBodies bodies) {
    return {kinematics::ColumnQuantity::InputAngle, 0, ratio, bodies};
  }

  /// A four-bar's quantities (the ids of kinematics/model/fourbar.h).
  static const PlotQuantity CouplerAngle;
  static const PlotQuantity RockerAngle;
  static const PlotQuantity TransmissionAngle;
  static const PlotQuantity CouplerOmega;
  static const PlotQuantity RockerOmega;
  static const PlotQuantity CouplerAlpha;
  static const PlotQuantity RockerAlpha;
};

/// A quantity as the plots show it for one mechanism.
struct PlotCurve {
  PlotQuantity quantity;
  QString key;   ///< stable, untranslated, after the CSV column names: "rocker_omega", "C_x"
  QString name;  ///< legend and checkbox: "rocker ω4", "transmission μ", "C x"
  QColor color;  ///< the link's colour on the canvas, for every chart it appears on
  /// The legend's name where the whole one does not fit a narrow chart: "θ4", "μ", "μ E", "ω4/ω2".
  QString symbol;
  bool operator==(const PlotCurve&) const = default;
};

QuantityKind quantityKind(PlotQuantity quantity);

/// The plottable quantities of `mechanism` solved as `pose`, in checkbox and legend order.
std::vector<PlotCurve> plotCurves(const kinematics::Mechanism& mechanism, const kinematics::Pose& pose);

/// The curve of `quantity` in `curves`, or null.
const PlotCurve* findCurve(const std::vector<PlotCurve>& curves, PlotQuantity quantity);

/// Unit of a kind's values: "deg", "rad/s", "deg/s²", "mm", "mm/s", "mm/s²"; for the ratio
/// kinds a four-bar's (none).
/// A ratio's symbol with its bodies' numbers: "ω4/ω2", "T6/T2", "v/ω2", "F/T2"; empty for
/// a sweep column.
QString ratioSymbol(PlotQuantity quantity);

QString quantityUnit(QuantityKind kind, AngleUnit unit, const QString& lengthUnit = QStringLiteral("mm"));
/// Unit of a quantity's values: its kind's, but a ratio's is the core's whatever the angle
/// unit: none for a four-bar's, "mm/rad" or "1/mm" for a slider-crank's.
QString quantityUnit(PlotQuantity quantity, AngleUnit unit, const QString& lengthUnit = QStringLiteral("mm"));
/// The y-axis title of a chart: "angle [deg]", "ω [rad/s]", "position [mm]", ...
QString valueAxisTitle(QuantityKind kind, AngleUnit unit, const QString& lengthUnit = QStringLiteral("mm"));
/// The y-axis title of a chart showing `quantity` (a ratio chart shows one linkage's): its
/// kind's, or the ratio's symbol: "ω4/ω2", "T4/T2", "v/ω2 [mm/rad]", "F/T2 [1/mm]".
QString valueAxisTitle(PlotQuantity quantity, AngleUnit unit, const QString& lengthUnit = QStringLiteral("mm"));
/// (The x axis's title is plot_x_axis.h's: the time or the input.)

/// Which quantities are shown: all but those the user unticked. A quantity the mechanism
/// does not have is simply never drawn.
class QuantitySelection {
public:
  /// Everything selected (the default).
  static QuantitySelection all() { return {}; }

  bool contains(PlotQuantity quantity) const;
  void set(PlotQuantity quantity, bool on);
  /// True if any of `curves` of `kind` is selected: its chart is shown.
  bool any(QuantityKind kind, const std::vector<PlotCurve>& curves) const;
  /// Equal when the same quantities are unticked, in whatever order.
  bool operator==(const QuantitySelection& other) const;

private:
  std::vector<PlotQuantity> m_hidden;  // in the order they were unticked
};

/// What a new mechanism shows first: everything but the ratios (asked for by name), except
/// that with sliders the links' ω and α also start unticked, so the slider's three charts and
/// the angles fit the window.
QuantitySelection defaultSelection(const std::vector<PlotCurve>& curves);

/// The selection once the curves change from `before` to `after`: the user's ticks while the
/// quantities stay the same (renamed links keep them), else the new mechanism's defaults.
QuantitySelection selectionAfter(const std::vector<PlotCurve>& before, const QuantitySelection& current,
                                 const std::vector<PlotCurve>& after);

/// The selection showing exactly the curves whose keys are in `keys` (the command line's
/// --plots); nullopt if a key is not one of `curves`', which `unknown` then names.
std::optional<QuantitySelection> selectionOfKeys(const std::vector<PlotCurve>& curves, const QStringList& keys,
                                                 QString& unknown);

/// What the sweep must compute for `selection` of `curves`: velocities only if an ω or a
/// velocity is shown; accelerations (which imply velocities) only if an α or an acceleration is.
/// (The ratios need positions only: the instant centres come from the pose.)
kinematics::SolveRequest requestFor(const QuantitySelection& selection, const std::vector<PlotCurve>& curves);

}  // namespace linkwright::ui
