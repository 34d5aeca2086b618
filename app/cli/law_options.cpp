#include "app/cli/commands.h"

#include "kinematics/io/bounded_read.h"
#include "kinematics/io/law_table_csv.h"

namespace linkwright::cli {
namespace {

namespace k = kinematics;

// A measured q(t) (io/law_table_csv.h), from a regular file of at most 64 MiB (io/bounded_read.h).
k::Result<k::TableLaw> readLawTable(const std::string& path, const GridDefaults& d) {
  const auto text = k::io::readFileBounded(path, k::io::kMaxLawTableBytes, "a table");
  if (!text) return k::Error{k::ErrorCode::InvalidValue, "--law-table", "--law-table " + text.error().message};
  auto law = k::io::readLawTableCsv(*text, d.input, d.lengthUnit);
  if (!law)
    return k::Error{k::ErrorCode::InvalidValue, "--law-table", "--law-table " + path + ": " + law.error().message};
  return law;
}

}  // namespace

kinematics::Result<kinematics::SweepGridRequest> lawRequest(const Invocation& inv, const GridDefaults& d,
                                                            kinematics::SweepGridRequest request) {
  request.law = inv.law;
  request.rampTime = inv.rampTime;
  request.rise = inv.riseDeg;
  request.duration = inv.duration;
  request.fromTime = inv.fromTime;
  request.toTime = inv.toTime;
  request.stepTime = inv.stepTime;
  if (inv.lawTable) {
    auto table = readLawTable(*inv.lawTable, d);
    if (!table) return table.error();
    request.table = std::move(table).value();
  }
  return request;
}

}  // namespace linkwright::cli
