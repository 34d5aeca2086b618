// `linkwright-cli polygon`: the velocity and acceleration polygons at the crank angles asked
// for (kinematics/analysis/vector_polygon.h): each point's vector equation, each arrow in
// drawing order with its components, size and direction, and where each side of an equation
// ends beside the solver's exact value. Text for reading, or JSON; every number from the core.

#include "app/cli/commands.h"

#include "kinematics/analysis/vector_polygon.h"
#include "kinematics/io/json.h"
#include "kinematics/model/number_text.h"
#include "kinematics/model/units.h"
#include "kinematics/model/validate.h"

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

k::io::JsonValue vectorJson(const Eigen::Vector2d& v) { return k::io::JsonValue::array({v.x(), v.y()}); }

k::io::JsonValue polygonJson(const k::VectorPolygon& p) {
  k::io::JsonValue j;
  j["unit"] = p.unit;
  j["box"] = {{"lower", vectorJson(p.lower)}, {"upper", vectorJson(p.upper)}};
  j["equations"] = k::io::JsonValue::array();
  for (const k::PolygonEquation& e : p.equations) {
    k::io::JsonValue ends = k::io::JsonValue::array();
    for (const Eigen::Vector2d& end : e.ends) ends.push_back(vectorJson(end));
    j["equations"].push_back({{"text", e.text}, {"ends", ends}, {"solver", vectorJson(e.solver)}});
  }
  j["vectors"] = k::io::JsonValue::array();
  for (const k::PolygonVector& v : p.vectors)
    j["vectors"].push_back({{"step", v.step},
                            {"label", v.label},
                            {"from", vectorJson(v.from)},
                            {"to", vectorJson(v.to)},
                            {"magnitude", v.value().norm()},
                            {"meaning", v.meaning}});
  j["images"] = k::io::JsonValue::array();
  for (const k::PolygonImage& im : p.images)
    j["images"].push_back({{"label", im.label}, {"position", vectorJson(im.position)}, {"coincident", im.coincident}});
  return j;
}

// --omega/--rpm and --alpha with the example's defaults, in the crank's domain.
k::Result<k::DriverState> driverAt(const Invocation& inv, const GridDefaults& d, double deg) {
  const k::InputDomain domain = k::inputDomain(k::InputKind::Angle);
  if (auto e = k::checkMagnitude(deg, "--at", k::kMaxAngleDeg, "degrees")) return *e;
  // --rpm and --omega checked in their own units (the core's grid rule), before --rpm becomes rad/s.
  if (auto e = checkDriveOptions(inv, k::InputKind::Angle)) return *e;
  const double omega = inv.rpm ? k::rpmToRadPerSec(*inv.rpm) : inv.omega.value_or(d.omega);
  if (auto e = k::checkMagnitude(omega, inv.rpm ? "--rpm" : "--omega", domain.rate, domain.rateUnit)) return *e;
  const double alpha = inv.alpha.value_or(d.alpha);
  if (auto e = k::checkMagnitude(alpha, "--alpha", domain.acceleration, domain.accelerationUnit)) return *e;
  return k::DriverState{k::degToRad(deg), omega, alpha};
}

}  // namespace

ExitCode runPolygon(const Invocation& inv, std::ostream& out, std::ostream& err) {
  const auto resolved = resolveMechanism(inv);
  if (!resolved) {
    err << "linkwright-cli: " << resolved.error().message << "\n";
    return ExitCode::BadInput;
  }
  const k::Mechanism& m = resolved->mechanism;
  if (k::inputKind(m) != k::InputKind::Angle) {
    err << "linkwright-cli: polygon needs a crank-driven linkage (" << resolved->source << " is driven by its "
        << k::inputName(m) << ")\n";
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
      all.push_back({{"crank_angle_deg", deg},
                     {"omega_rad_s", driver->velocity},
                     {"alpha_rad_s2", driver->acceleration},
                     {"velocity", polygonJson(polygons->velocity)},
                     {"acceleration", polygonJson(polygons->acceleration)}});
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
