#include "app/cli/commands.h"

#include "kinematics/design/design.h"
#include "kinematics/design/fourbar_dimensions.h"
#include "kinematics/design/sweep_grid.h"
#include "kinematics/io/bounded_read.h"
#include "kinematics/io/document_json.h"
#include "kinematics/model/driver.h"
#include "kinematics/model/mechanism_check.h"
#include "kinematics/model/validate.h"

namespace linkwright::cli {

namespace k = kinematics;

namespace {

// The document named on the command line; errors name the file.
k::Result<k::Design> readDocumentFile(const std::string& path) {
  const auto text = k::io::readFileBounded(path, k::io::kMaxDocumentBytes, "a Linkwright document");
  if (!text) return k::Error{text.error().code, path, text.error().message};
  auto design = k::io::readDocument(*text);
  if (!design) return k::Error{design.error().code, path, path + ": " + design.error().message};
  return design;
}

k::Error unknownExample(const std::string& name) {
  std::string names;
  for (const k::Example& x : k::examples()) names += (names.empty() ? "" : ", ") + x.name;
  return k::Error{k::ErrorCode::InvalidValue, "--example",
                  "--example: no example named '" + name + "' (available: " + names + ")"};
}

k::Result<ResolvedMechanism> resolveExample(const std::string& name) {
  auto e = k::findExample(name);
  if (!e) return unknownExample(name);
  return ResolvedMechanism{
      std::move(e->mechanism), k::sweepGridOf(*e), std::move(e->dynamics), "the example " + e->name, e->kind,
      e->description};
}

k::Result<ResolvedMechanism> resolveSource(const Invocation& inv) {
  if (inv.documentPath) {
    auto design = readDocumentFile(*inv.documentPath);
    if (!design) return design.error();
    return ResolvedMechanism{std::move(design->mechanism),
                             k::sweepGridOf(*design),
                             std::move(design->dynamics),
                             *inv.documentPath,
                             design->kind,
                             ""};
  }
  if (inv.example) return resolveExample(*inv.example);
  auto m = k::makeFourBar(*inv.fourBar, k::Branch::Open, inv.lengthUnit);
  if (!m) return m.error();
  return ResolvedMechanism{std::move(*m), {}, {}, "--fourbar", "", ""};
}

// --branch and --coupler-point name a four-bar's branch and its point P.
std::optional<k::Error> applyFourBarOptions(const Invocation& inv, ResolvedMechanism& r) {
  if (!inv.branch && !inv.couplerPoint) return std::nullopt;
  const auto fourBar = k::asFourBar(r.mechanism);
  if (!fourBar) {
    const std::string option = inv.couplerPoint ? "--coupler-point" : "--branch";
    const std::string what = inv.documentPath ? "this " + r.kind : r.source.substr(r.source.rfind(' ') + 1);
    return k::Error{k::ErrorCode::InvalidValue, option, option + " applies to four-bars, not to " + what};
  }
  if (inv.branch) r.mechanism = k::withFourBarBranch(r.mechanism, *fourBar, *inv.branch);
  if (inv.couplerPoint) {
    if (auto e = k::checkCoordinate(inv.couplerPoint->along, "coupler point along")) return e;
    if (auto e = k::checkCoordinate(inv.couplerPoint->across, "coupler point across")) return e;
    auto m = k::withCouplerPoint(r.mechanism, *fourBar, *inv.couplerPoint);
    if (!m) return m.error();
    r.mechanism = std::move(*m);
  }
  return k::checkMechanism(r.mechanism);  // P counts in the linkage's spread of sizes
}

}  // namespace

kinematics::Result<kinematics::Design> resolveDesign(const Invocation& inv) {
  if (inv.documentPath) return readDocumentFile(*inv.documentPath);
  if (inv.example) {
    auto design = k::designForExample(*inv.example);
    if (!design) return unknownExample(*inv.example);
    return std::move(*design);
  }
  return k::Error{k::ErrorCode::InvalidValue, "--example", "a document or --example NAME is needed"};
}

kinematics::Result<ResolvedMechanism> resolveMechanism(const Invocation& inv) {
  auto r = resolveSource(inv);
  if (!r) return r.error();
  if (auto e = applyFourBarOptions(inv, r.value())) return *e;
  r.value().defaults.input = k::inputKind(r.value().mechanism);
  r.value().defaults.lengthUnit = r.value().mechanism.lengthUnit;
  return r;
}

}  // namespace linkwright::cli
