// `linkwright-cli centres`: the six instant centres of a four-bar or slider-crank at the crank
// angles asked for, with the velocity ratio and the ideal mechanical advantage they give
// (kinematics/analysis/instant_centres.h). Text for reading; every number comes from the core.

#include "app/cli/commands.h"

#include "kinematics/analysis/instant_centres.h"
#include "kinematics/io/number_format.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"

#include <algorithm>
#include <cmath>
#include <ostream>

namespace linkwright::cli {
namespace {

namespace k = kinematics;
using k::io::formatShort;

constexpr int kDigits = 9;  // significant digits: ample for a drawing, short enough to read

struct BodyNames {
  const char* names[5];  // 1-based: frame, crank, coupler/rod, rocker/slider
};

BodyNames bodiesOf(k::CentreLinkage linkage) {
  if (linkage == k::CentreLinkage::FourBar) return {{"", "frame", "crank", "coupler", "rocker"}};
  return {{"", "frame", "crank", "rod", "slider"}};
}

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
  }
  return {};
}

// What a centre is, or why it is where it is.
std::string centreNote(const k::InstantCentre& c, int i, int j, const BodyNames& b, const char* pin) {
  const std::string pair = std::string(b.names[i]) + " and " + b.names[j];
  if (c.kind == k::CentreKind::AtInfinity) return pair + " have no relative rotation";
  if (c.kind == k::CentreKind::Indeterminate) return "Kennedy's lines coincide: all joints in one line";
  return pin ? std::string("pin ") + pin : std::string();
}

std::string ratioText(const k::Ratio& r, const std::string& unit) {
  if (r.kind == k::RatioKind::Infinite) return "infinite";
  if (r.kind == k::RatioKind::Undefined) return "undefined";
  return formatShort(r.value, kDigits) + unit;
}

// Why a ratio is zero, infinite or undefined at this pose; empty when it is not.
std::string toggleNote(const k::MechanicalAdvantage& ma, k::CentreLinkage linkage) {
  const bool fourBar = linkage == k::CentreLinkage::FourBar;
  if (ma.velocityRatio.kind == k::RatioKind::Undefined) return "all joints lie in one line: the ratios are undefined";
  if (ma.velocityRatio.kind == k::RatioKind::Infinite)
    return fourBar ? "coupler and rocker in line: the crank cannot drive the linkage here"
                   : "rod normal to the guide: the crank cannot drive the slider here";
  if (ma.advantage.kind == k::RatioKind::Infinite)
    return fourBar ? "toggle: crank and coupler in line, the rocker is momentarily at rest (a limit position)"
                   : "dead centre: crank and rod in line, the slider is momentarily at rest";
  return {};
}

void printPose(std::ostream& out, const k::InstantCentres& c, const std::string& unit) {
  const BodyNames b = bodiesOf(c.linkage);
  const bool fourBar = c.linkage == k::CentreLinkage::FourBar;
  const struct {
    const char* name;
    const k::InstantCentre* centre;
    int i, j;
    const char* pin;
  } rows[] = {
      {"I12", &c.i12, 1, 2, "O2"}, {"I13", &c.i13, 1, 3, nullptr}, {"I14", &c.i14, 1, 4, fourBar ? "O4" : nullptr},
      {"I23", &c.i23, 2, 3, "B"},  {"I24", &c.i24, 2, 4, nullptr}, {"I34", &c.i34, 3, 4, "C"}};
  for (const auto& row : rows) {
    std::string note = centreNote(*row.centre, row.i, row.j, b, row.pin);
    if (!fourBar && row.centre == &c.i14) note = "the slider translates along the guide";
    const std::string text = centreText(*row.centre, c.scale, unit);
    out << "  " << row.name << "  " << (note.empty() ? text : padded(text, 42) + "  " + note) << "\n";
  }
  const k::MechanicalAdvantage ma = k::mechanicalAdvantage(c);
  if (fourBar) {
    out << "  velocity ratio        ω4/ω2 = " << ratioText(ma.velocityRatio, "") << "\n";
    out << "  mechanical advantage  T4/T2 = ω2/ω4 = " << ratioText(ma.advantage, "") << "\n";
  } else {
    out << "  velocity ratio        v/ω2 = " << ratioText(ma.velocityRatio, " " + unit + "/rad") << "\n";
    out << "  mechanical advantage  F/T2 = ω2/v = " << ratioText(ma.advantage, " 1/" + unit) << "\n";
  }
  if (const std::string note = toggleNote(ma, c.linkage); !note.empty()) out << "  note: " << note << "\n";
}

void printHeader(std::ostream& out, const k::InstantCentres& c, const std::string& unit) {
  const BodyNames b = bodiesOf(c.linkage);
  out << "instant centres of the " << (c.linkage == k::CentreLinkage::FourBar ? "four-bar" : "slider-crank")
      << ": bodies 1 " << b.names[1] << ", 2 " << b.names[2] << ", 3 " << b.names[3] << ", 4 " << b.names[4]
      << "; lengths in " << unit << ", directions CCW from +x\n";
  if (c.linkage == k::CentreLinkage::SliderCrank)
    out << "slider velocity v and force F along the guide, direction "
        << formatShort(k::radToDeg(std::atan2(c.guideDirection.y(), c.guideDirection.x()))) << "°\n";
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
    if (!headerDone) printHeader(out, *centres, m.lengthUnit);
    headerDone = true;
    out << "\ncrank angle " << formatShort(deg) << "°\n";
    printPose(out, *centres, m.lengthUnit);
  }
  return code;
}

}  // namespace linkwright::cli
