// `linkwright-cli polygon`: the velocity and acceleration polygons at the crank angles asked
// for (kinematics/analysis/vector_polygon.h): each point's vector equation, each arrow in
// drawing order with its components, size and direction, and where each side of an equation
// ends beside the solver's exact value. Text for reading, or JSON; every number from the core.

#include "app/cli/commands.h"

#include "kinematics/analysis/vector_polygon.h"
#include "kinematics/design/sweep_grid.h"
#include "kinematics/io/polygon_json.h"
#include "kinematics/model/number_text.h"
#include "kinematics/model/units.h"

#include <cmath>
#include <ostream>

namespace linkwright::cli {
namespace {

namespace k = kinematics;
using k::formatShort;

constexpr int kDigits = 9;  // significant digits, as centres prints

// A component at kDigits of the polygon's size: round-off (1e-13 of it) prints as 0.
std::string component(double value, double scale) {
  return formatShort(std::abs(value) <= 1e-12 * scale ? 0.0 : value, kDigits);
}

double sizeOf(const k::VectorPolygon& p) { return std::max((p.upper - p.lower).norm(), 1e-300); }

std::string pair(const Eigen::Vector2d& v, double scale) {
  return "(" + component(v.x(), scale) + ", " + component(v.y(), scale) + ")";
}

std::string angleDeg(const Eigen::Vector2d& v, double scale) {
  if (v.norm() <= 1e-12 * scale) return "-";
  return formatShort(k::radToDeg(std::atan2(v.y(), v.x())), 6);
}

std::string column(std::string text, std::size_t width) {
  std::size_t chars = 0;
  for (const char ch : text) chars += (static_cast<unsigned char>(ch) & 0xC0) != 0x80;
  return chars < width ? text + std::string(width - chars, ' ') : text + " ";
}

void printPolygon(std::ostream& out, const k::VectorPolygon& p) {
  const double s = sizeOf(p);
  const bool vel = p.kind == k::PolygonKind::Velocity;
  out << "\n"
      << (vel ? "velocity" : "acceleration") << " polygon (" << p.unit << "), pole o at (0, 0); box x ["
      << component(p.lower.x(), s) << ", " << component(p.upper.x(), s) << "], y [" << component(p.lower.y(), s) << ", "
      << component(p.upper.y(), s) << "]\n";
  for (const k::PolygonEquation& e : p.equations) {
    out << "  " << e.text << "\n    ends at";
    for (std::size_t i = 0; i < e.ends.size(); ++i) out << (i ? ", " : " ") << pair(e.ends[i], s);
    out << "; solver " << e.text.substr(0, e.text.find(' ')) << " = " << pair(e.solver, s) << "\n";
  }
  out << "  " << column("step", 6) << column("vector", 10) << column("x", 16) << column("y", 16)
      << column("magnitude", 16) << column("angle °", 10) << "meaning\n";
  for (const k::PolygonVector& v : p.vectors) {
    const Eigen::Vector2d d = v.value();
    out << "  " << column(std::to_string(v.step), 6) << column(v.label, 10) << column(component(d.x(), s), 16)
        << column(component(d.y(), s), 16) << column(component(d.norm(), s), 16) << column(angleDeg(d, s), 10)
        << v.meaning << "\n";
  }
}

// --omega/--rpm and --alpha with the example's defaults, in the crank's domain.
k::Result<k::DriverState> driverAt(const Invocation& inv, const GridDefaults& d, double deg) {
  // --from, --to, --step and --samples are checked too, as by every command that takes them.
  return k::crankStateAt(deg, {inv.rpm, inv.omega, inv.alpha, inv.fromDeg, inv.toDeg, inv.stepDeg, inv.samples}, d,
                         gridOptionNames(), "--at");
}

}  // namespace

ExitCode runPolygon(const Invocation& inv, std::ostream& out, std::ostream& err) {
  const auto resolved = resolveMechanism(inv);
  if (!resolved) {
    err << "linkwright-cli: " << resolved.error().message << "\n";
    return ExitCode::BadInput;
  }
  const k::Mechanism& m = resolved->mechanism;
  if (auto e = k::checkPolygonInput(m, resolved->source)) {
    err << "linkwright-cli: " << e->message << "\n";
    return ExitCode::BadInput;
  }
  ExitCode code = ExitCode::Success;
  k::io::JsonValue all = k::io::JsonValue::array();
  for (std::size_t n = 0; n < inv.atDeg.size(); ++n) {
    const double deg = inv.atDeg[n];
    const auto driver = driverAt(inv, resolved->defaults, deg);
    if (!driver) {
      err << "linkwright-cli: " << driver.error().message << "\n";
      return ExitCode::BadInput;
    }
    const auto polygons = k::polygonsAt(m, *driver);
    if (!polygons) {
      err << "linkwright-cli: crank angle " << formatShort(deg) << "°: " << polygons.error().message << "\n";
      code = ExitCode::NotAssemblable;
      continue;
    }
    if (inv.json) {
      all.push_back(k::io::polygonsJson(deg, *driver, *polygons));
      continue;
    }
    out << (n == 0 ? "" : "\n") << "crank angle " << formatShort(deg) << "°, ω "
        << formatShort(driver->velocity, kDigits) << " rad/s, α " << formatShort(driver->acceleration, kDigits)
        << " rad/s² (" << resolved->source << "; lengths in " << m.lengthUnit << ", angles CCW from +x)\n";
    printPolygon(out, polygons->velocity);
    printPolygon(out, polygons->acceleration);
  }
  if (inv.json) out << all.dump(2) << "\n";
  return code;
}

}  // namespace linkwright::cli
