#include "app/cli/commands.h"

#include "kinematics/io/document_json.h"

#include <fstream>
#include <sstream>

namespace linkwright::cli {

namespace k = kinematics;

namespace {

// A design's grid as defaults: its samples become the step that reproduces them.
GridDefaults gridOf(const k::Design& d) {
  return std::visit(
      [](const auto& x) {
        return GridDefaults{x.omega, x.alpha, x.fromDeg, x.toDeg,
                            (x.toDeg - x.fromDeg) / static_cast<double>(x.samples - 1)};
      },
      d);
}

// The document named on the command line; errors name the file.
k::Result<k::Design> readDocumentFile(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) return k::Error{k::ErrorCode::InvalidValue, path, path + ": cannot be opened for reading"};
  std::stringstream text;
  text << file.rdbuf();
  auto design = k::io::readDocument(text.str());
  if (!design) return k::Error{design.error().code, path, path + ": " + design.error().message};
  return design;
}

}  // namespace

kinematics::Result<ResolvedFourBar> resolveFourBar(const Invocation& inv) {
  ResolvedFourBar r;
  if (inv.example) {
    r.example = k::findFourBarExample(*inv.example);
    if (!r.example) {
      if (const auto other = k::findMechanismExample(*inv.example))
        return k::Error{k::ErrorCode::InvalidValue, "--example",
                        "--example: '" + *inv.example + "' is not a four-bar but a " + other->kind +
                            "; classify works on four-bars and shapers (try analyze or extremes)"};
      std::string names;
      for (const auto& e : k::fourBarExamples()) names += (names.empty() ? "" : ", ") + e.name;
      for (const auto& e : k::mechanismExamples()) names += ", " + e.name;
      return k::Error{k::ErrorCode::InvalidValue, "--example",
                      "--example: no example named '" + *inv.example + "' (available: " + names + ")"};
    }
    r.lengths = r.example->lengths;
    r.lengthUnit = r.example->lengthUnit;
    r.branch = r.example->branch;
  } else {
    r.lengths = *inv.fourBar;
    r.lengthUnit = inv.lengthUnit;
  }
  if (inv.branch) r.branch = *inv.branch;
  return r;
}

kinematics::Result<ResolvedMechanism> resolveMechanism(const Invocation& inv) {
  ResolvedMechanism r;
  if (inv.documentPath) {
    const auto design = readDocumentFile(*inv.documentPath);
    if (!design) return design.error();
    r.defaults = gridOf(*design);
    r.source = *inv.documentPath;
    r.dynamics = std::visit([](const auto& d) { return d.dynamics; }, *design);
    if (const auto* f = std::get_if<k::FourBarDesign>(&*design)) {
      r.fourBar = ResolvedFourBar{f->lengths, f->lengthUnit, inv.branch.value_or(f->branch), std::nullopt};
      const auto couplerPoint = inv.couplerPoint ? inv.couplerPoint : f->couplerPoint;
      auto m = k::makeFourBar(f->lengths, r.fourBar->branch, f->lengthUnit, couplerPoint);
      if (!m) return m.error();
      r.mechanism = std::move(*m);
      return r;
    }
    if (inv.couplerPoint || inv.branch)
      return k::Error{k::ErrorCode::InvalidValue, inv.couplerPoint ? "--coupler-point" : "--branch",
                      std::string(inv.couplerPoint ? "--coupler-point" : "--branch") +
                          " applies to four-bars, not to this " + std::get<k::MechanismDesign>(*design).kind};
    r.mechanism = std::get<k::MechanismDesign>(*design).mechanism;
    return r;
  }
  if (inv.example) {
    if (auto other = k::findMechanismExample(*inv.example)) {
      if (inv.couplerPoint)
        return k::Error{k::ErrorCode::InvalidValue, "--coupler-point",
                        "--coupler-point applies to four-bars, not to " + other->name};
      if (inv.branch)
        return k::Error{k::ErrorCode::InvalidValue, "--branch", "--branch applies to four-bars, not to " + other->name};
      r.mechanism = std::move(other->mechanism);
      r.defaults = {other->omega, 0.0, other->fromDeg, other->toDeg, other->stepDeg};
      r.dynamics = std::move(other->dynamics);
      r.source = "the example " + other->name;
      return r;
    }
  }
  auto fb = resolveFourBar(inv);
  if (!fb) return fb.error();
  const auto couplerPoint =
      inv.couplerPoint ? inv.couplerPoint : (fb->example ? fb->example->couplerPoint : std::nullopt);
  auto m = k::makeFourBar(fb->lengths, fb->branch, fb->lengthUnit, couplerPoint);
  if (!m) return m.error();
  r.mechanism = std::move(*m);
  r.source = "--fourbar";
  if (const auto& e = fb->example) {
    r.defaults = {e->omega, e->alpha, e->fromDeg, e->toDeg, e->stepDeg};
    r.dynamics = e->dynamics;
    r.source = "the example " + e->name;
  }
  r.fourBar = std::move(*fb);
  return r;
}

}  // namespace linkwright::cli
