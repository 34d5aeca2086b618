// `linkwright-cli compare`: another tool's table (SolidWorks Motion, MATLAB, Excel, NX) against
// the exact solution at the table's own inputs (kinematics/compare/table_comparison.h). Prints
// each mapped column's worst and rms deviation and the rows beyond the tolerance. Flagged rows
// are the comparison's result, not a failure: the exit code is 0 whenever the comparison ran,
// 2 when the table, the mapping or an option is wrong.

#include "app/cli/commands.h"
#include "app/cli/compare_report.h"
#include "app/cli/option_values.h"
#include "app/cli/progress.h"

#include "kinematics/compare/header_mapping.h"
#include "kinematics/compare/table_comparison.h"
#include "kinematics/io/bounded_read.h"
#include "kinematics/io/numeric_table_csv.h"
#include "kinematics/model/units.h"
#include "kinematics/model/validate.h"

#include <cmath>
#include <ostream>

namespace linkwright::cli {
namespace {

namespace k = kinematics;
namespace kc = kinematics::compare;

k::Result<k::io::NumericTable> readTableFile(const std::string& path) {
  const auto text = k::io::readFileBounded(path, k::io::kMaxNumericTableBytes, "a table");
  if (!text) return k::Error{text.error().code, path, text.error().message};
  auto table = k::io::readNumericTable(*text);
  if (!table) return k::Error{table.error().code, path, path + ": " + table.error().message};
  return table;
}

// The drive at the table's inputs: the linkage's own speed, or --rpm / --omega, --alpha, --from.
k::Result<kc::CompareDrive> driveFor(const Invocation& inv, const GridDefaults& d) {
  // As analyze checks them: --from nan made every row "agree", --rpm nan blamed --omega.
  if (auto e = checkDriveOptions(inv, d.input)) return *e;
  kc::CompareDrive drive;
  drive.omega = inv.rpm ? k::rpmToRadPerSec(*inv.rpm) : inv.omega.value_or(d.omega);
  drive.alpha = inv.alpha.value_or(d.alpha);
  drive.startAngle = d.toInput(inv.fromDeg.value_or(d.fromDeg));
  if (d.time) {
    if (inv.rpm || inv.omega || inv.alpha || inv.fromDeg)
      return usage(inv.rpm     ? "--rpm"
                   : inv.omega ? "--omega"
                   : inv.alpha ? "--alpha"
                               : "--from",
                   "this linkage's driver follows a motion law in time; its speed cannot be replaced here");
    drive.law = d.time->law;
  }
  return drive;
}

kc::CompareOptions optionsFor(const Invocation& inv) {
  kc::CompareOptions options;
  if (inv.compareOffset) {
    options.offset = inv.compareOffset->mode;
    options.offsetDeg = inv.compareOffset->degrees;
  }
  if (inv.compareTolerance) {
    options.relativeTolerance = inv.compareTolerance->percent / 100.0;
    options.absoluteTolerance = inv.compareTolerance->absolute;
  }
  return options;
}

// --map's text, or with "auto" the mapping the table's headers propose (the report's map:
// line shows it, in the form --map reads back).
k::Result<kc::ColumnMapping> mappingFor(const std::string& text, const k::io::NumericTable& table,
                                        const k::Mechanism& mechanism) {
  if (text != "auto") return kc::parseColumnMap(text, mechanism);
  kc::ColumnMapping proposed = kc::proposeColumnMapping(table, mechanism);
  if (!proposed.axis || proposed.columns.empty())
    return k::Error{k::ErrorCode::InvalidValue, "--map",
                    std::string("--map auto: the table's headers name ") +
                        (proposed.axis ? "no quantity" : "no crank angle or time column") +
                        " clearly (such as \"theta2 (deg)\", \"omega4 [rad/s]\", \"time (s)\"); give --map "
                        "COLUMN=WHAT[:UNIT],... instead"};
  return proposed;
}

}  // namespace

ExitCode runCompare(const Invocation& inv, std::ostream& out, std::ostream& err) {
  const auto fail = [&err](const std::string& message) {
    err << "linkwright-cli: " << message << "\n";
    return ExitCode::BadInput;
  };
  const auto resolved = resolveMechanism(inv);
  if (!resolved) return fail(resolved.error().message);
  const auto table = readTableFile(*inv.compareTable);
  if (!table) return fail(table.error().message);
  const auto mapping = mappingFor(*inv.compareMap, *table, resolved->mechanism);
  if (!mapping) return fail(mapping.error().message);
  if (auto e = kc::checkColumnMapping(*mapping, *table)) return fail("--map: " + e->message);
  const auto drive = driveFor(inv, resolved->defaults);
  if (!drive) return fail(drive.error().message);
  const kc::CompareOptions options = optionsFor(inv);
  const auto comparison = kc::compareTable(resolved->mechanism, *drive, *table, *mapping, options);
  if (!comparison) {
    const k::Error& e = comparison.error();
    const std::string option = e.field == "offset" ? "--offset: " : e.field == "tolerance" ? "--tolerance: " : "";
    return fail(option + e.message);
  }
  const CompareContext context{*inv.compareTable, resolved->source, *table, *drive, options, *mapping};
  // A long table's JSON takes seconds to write: a person at a terminal sees how far it is.
  Progress progress(err, "compare", "rows written", progressShown(err, &out));
  if (inv.json)
    writeComparisonJson(out, context, *comparison,
                        [&progress](std::size_t done, std::size_t total) { progress.update(done, total); });
  else writeComparisonText(out, context, *comparison);
  return ExitCode::Success;
}

}  // namespace linkwright::cli
