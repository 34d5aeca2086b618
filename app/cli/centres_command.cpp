// `linkwright-cli centres`: every instant centre of a linkage at the crank angles asked for,
// each with the pin, slide or Kennedy lines that locate it, and the velocity ratio and the
// ideal mechanical advantage they give (kinematics/analysis/instant_centres.h). Text for
// reading; every number comes from the core.

#include "app/cli/commands.h"

#include "kinematics/analysis/advantage_sweep.h"
#include "kinematics/analysis/instant_centres.h"
#include "kinematics/model/number_text.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"

#include <algorithm>
#include <cmath>
#include <ostream>

namespace linkwright::cli {
namespace {

namespace k = kinematics;
using k::formatShort;

constexpr int kDigits = 9;  // significant digits: ample for a drawing, short enough to read

// Pads to `width` characters (UTF-8 code points: "°" is one character, two bytes).
std::string padded(const std::string& text, std::size_t width) {
  const std::size_t chars = static_cast<std::size_t>(
      std::count_if(text.begin(), text.end(), [](char ch) { return (static_cast<unsigned char>(ch) & 0xC0) != 0x80; }));
  return chars < width ? text + std::string(width - chars, ' ') : text;
}

// A coordinate at kDigits significant digits of the linkage's size: round-off below that
// (cos 90° = 6e-17) prints as 0, not as 1.5e-15.
std::string coordinate(double value, double scale) {
  return formatShort(std::abs(value) <= k::kCentreTolerance * scale ? 0.0 : value, kDigits);
}

std::string centreText(const k::InstantCentre& c, double scale, const std::string& unit) {
  switch (c.kind) {
  case k::CentreKind::Finite:
    return "(" + coordinate(c.position.x(), scale) + ", " + coordinate(c.position.y(), scale) + ") " + unit;
  case k::CentreKind::AtInfinity:
    return "at infinity, direction " + formatShort(k::radToDeg(std::atan2(c.direction.y(), c.direction.x()))) + "°";
  case k::CentreKind::Indeterminate: return "indeterminate";
  case k::CentreKind::Unresolved: return "not located";
  }
  return {};
}

std::string pairName(std::size_t i, std::size_t j) {
  if (i > j) std::swap(i, j);
  return "I" + std::to_string(i) + (i > 9 || j > 9 ? "," : "") + std::to_string(j);
}

// The Kennedy line through Iik and Ijk.
std::string lineName(std::size_t i, std::size_t j, std::size_t k) { return pairName(i, k) + "–" + pairName(j, k); }

// What a centre is, or how Kennedy's lines locate it.
std::string centreNote(const k::InstantCentres& c, std::size_t i, std::size_t j) {
  const k::InstantCentre& centre = c.centre(i, j);
  const k::CentreOrigin& o = c.origin(i, j);
  const std::string pair = c.bodies[i - 1] + " and " + c.bodies[j - 1];
  switch (o.rule) {
  case k::CentreRule::Pin: return "pin " + o.joint;
  case k::CentreRule::Slide: return "slide at " + o.joint + ": " + pair + " have no relative rotation";
  case k::CentreRule::None: return "unresolved: Kennedy's theorem does not reach it";
  case k::CentreRule::Kennedy: break;
  }
  const std::string lines = lineName(i, j, o.via[0]) + " and " + lineName(i, j, o.via[1]);
  if (centre.kind == k::CentreKind::Indeterminate)
    return "Kennedy's lines " + lines + " coincide: all joints in one line";
  if (centre.kind == k::CentreKind::AtInfinity) return pair + " have no relative rotation (" + lines + " parallel)";
  return "on " + lines;
}

std::string ratioText(const k::Ratio& r, const std::string& unit) {
  if (r.kind == k::RatioKind::Infinite) return "infinite";
  if (r.kind == k::RatioKind::Undefined) return "undefined";
  return formatShort(r.value, kDigits) + unit;
}

// Why a ratio is zero, infinite or undefined at this pose; empty when it is not.
std::string toggleNote(const k::InstantCentres& c, const k::MechanicalAdvantage& ma) {
  const std::size_t a = c.ratio.input, b = c.ratio.output;
  const std::string iab = pairName(a, b);
  if (ma.velocityRatio.kind == k::RatioKind::Undefined) return iab + " is not located: the ratios are undefined";
  if (ma.velocityRatio.kind == k::RatioKind::Infinite)
    return (c.ratio.outputSlides ? iab + " at infinity" : iab + " on the output's pivot " + pairName(1, b)) +
           ": the crank cannot drive the output here";
  if (ma.advantage.kind == k::RatioKind::Infinite)
    return iab + " on the crank's pivot " + pairName(1, a) +
           ": the output is momentarily at rest (a limit position, or a slider's dead centre)";
  return {};
}

void printPose(std::ostream& out, const k::InstantCentres& c, const std::string& unit) {
  for (std::size_t i = 1; i <= c.bodyCount(); ++i)
    for (std::size_t j = i + 1; j <= c.bodyCount(); ++j) {
      const std::string text = centreText(c.centre(i, j), c.scale, unit);
      out << "  " << padded(pairName(i, j), 3) << "  " << padded(text, 42) << "  " << centreNote(c, i, j) << "\n";
    }
  if (!c.ratio.exists()) return;
  const k::MechanicalAdvantage ma = k::mechanicalAdvantage(c);
  const std::string a = std::to_string(c.ratio.input), b = std::to_string(c.ratio.output);
  if (!c.ratio.outputSlides) {
    out << "  velocity ratio        ω" << b << "/ω" << a << " = " << ratioText(ma.velocityRatio, "") << "\n";
    out << "  mechanical advantage  T" << b << "/T" << a << " = ω" << a << "/ω" << b << " = "
        << ratioText(ma.advantage, "") << "\n";
  } else {
    out << "  velocity ratio        v/ω" << a << " = " << ratioText(ma.velocityRatio, " " + unit + "/rad") << "\n";
    out << "  mechanical advantage  F/T" << a << " = ω" << a << "/v = " << ratioText(ma.advantage, " 1/" + unit)
        << "\n";
  }
  if (const std::string note = toggleNote(c, ma); !note.empty()) out << "  note: " << note << "\n";
}

void printHeader(std::ostream& out, const k::Mechanism& m, const k::InstantCentres& c) {
  out << "instant centres: bodies";
  for (std::size_t b = 1; b <= c.bodyCount(); ++b) out << (b == 1 ? " " : ", ") << b << " " << c.bodies[b - 1];
  out << "; lengths in " << m.lengthUnit << ", directions CCW from +x\n";
  if (const auto why = k::ratioUnavailable(m)) {
    out << "ratios: none (" << why->message << ")\n";
    return;
  }
  if (c.ratio.outputSlides)
    out << "output " << c.bodies[c.ratio.output - 1] << ": velocity v and force F along its guide, direction "
        << formatShort(k::radToDeg(std::atan2(c.outputDirection.y(), c.outputDirection.x()))) << "°\n";
  out << "ratios: ω = angular velocity (rad/s, CCW positive); mechanical advantage ideal (no friction, no inertia), "
         "negative when the output turns against the input\n";
}

}  // namespace

ExitCode runCentres(const Invocation& inv, std::ostream& out, std::ostream& err) {
  const auto resolved = resolveMechanism(inv);
  if (!resolved) {
    err << "linkwright-cli: " << resolved.error().message << "\n";
    return ExitCode::BadInput;
  }
  const k::Mechanism& m = resolved->mechanism;
  if (auto e = checkAtOption(inv, resolved->defaults)) {
    err << "linkwright-cli: " << e->message << "\n";
    return ExitCode::BadInput;
  }
  ExitCode code = ExitCode::Success;
  bool headerDone = false;
  for (const double deg : inv.atDeg) {
    // Positions are all the centres need; without rates a toggle pose still solves.
    const auto pose = k::solvePose(m, {k::degToRad(deg), 0.0, 0.0}, k::SolveRequest{false, false});
    if (!pose) {
      err << "linkwright-cli: crank angle " << formatShort(deg) << "°: " << pose.error().message << "\n";
      code = ExitCode::NotAssemblable;
      continue;
    }
    const auto centres = k::instantCentres(m, *pose);
    if (!centres) {
      err << "linkwright-cli: " << centres.error().message << "\n";
      return ExitCode::BadInput;
    }
    if (!headerDone) printHeader(out, m, *centres);
    headerDone = true;
    out << "\ncrank angle " << formatShort(deg) << "°\n";
    printPose(out, *centres, m.lengthUnit);
  }
  return code;
}

}  // namespace linkwright::cli
