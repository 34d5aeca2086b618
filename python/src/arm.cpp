// linkwright.arm (kinematics/design/arm_request.h): the two-link arm with its tip on a line at
// constant speed, as the core's one request; its rows the columns linkwright-cli arm writes, as
// masked arrays (a cell the CLI leaves empty is masked), its notes the CLI's sentences as
// SweepWarning, and with `output` the CLI's CSV (or table) written where -o writes it.

#include "python/src/bindings.h"
#include "python/src/convert.h"

#include "kinematics/design/arm_request.h"
#include "kinematics/io/arm_table.h"
#include "kinematics/io/safe_file.h"

#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <cmath>
#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace linkwright::python {
namespace {

namespace k = kinematics;

py::handle armWarning;

std::optional<k::Branch> elbowOf(const std::optional<std::string>& elbow) {
  if (!elbow) return std::nullopt;
  if (*elbow == "up") return k::Branch::Open;
  if (*elbow == "down") return k::Branch::Crossed;
  throw CoreError{k::Error{k::ErrorCode::InvalidValue, "elbow", "elbow must be 'up' or 'down' (got '" + *elbow + "')"}};
}

// The columns of armColumns, filled a window at a time: each sized once, at the first window,
// to the run's rows, so 10⁷ rows take 11 columns of 9 bytes a row and no copy of the rows.
struct ArmArrays {
  std::vector<k::ArmColumn> columns;
  std::vector<std::vector<double>> values;
  std::vector<std::vector<std::uint8_t>> masked;

  explicit ArmArrays(const std::string& unit)
      : columns(k::armColumns(unit)), values(columns.size()), masked(columns.size()) {}

  void add(const std::vector<k::ArmRow>& rows, std::size_t rowsInAll) {
    for (std::size_t c = 0; c < columns.size(); ++c) {
      values[c].reserve(rowsInAll);
      masked[c].reserve(rowsInAll);
      for (const k::ArmRow& row : rows) {
        const double value = k::armCellDefined(columns[c], row) ? columns[c].value(row) : 0.0;
        const bool ok = k::armCellDefined(columns[c], row) && std::isfinite(value);
        values[c].push_back(ok ? value : 0.0);
        masked[c].push_back(ok ? 0 : 1);
      }
    }
  }

  py::dict take() {
    py::dict out;
    for (std::size_t c = 0; c < columns.size(); ++c)
      out[py::str(columns[c].name)] = maskedArrayTaking(std::move(values[c]), std::move(masked[c]));
    return out;
  }
};

py::dict arm(std::optional<std::string> example, std::optional<std::pair<double, double>> lengths,
             std::optional<Eigen::Vector2d> fromPoint, std::optional<Eigen::Vector2d> toPoint,
             std::optional<double> speed, std::optional<std::string> elbow, std::optional<long long> samples,
             std::optional<double> stepTime, std::string unit, std::optional<std::string> output, bool table) {
  const k::ArmRequest request{std::move(example), lengths, fromPoint, toPoint,         speed,
                              elbowOf(elbow),     samples, stepTime,  std::move(unit), k::FrontEnd::Python};
  ArmArrays arrays(request.lengthUnit);
  // One run fills the arrays and, with `output`, writes the CLI's bytes as the rows come: the
  // same writer as -o, so the file is never held whole either.
  std::optional<k::Result<k::ArmRun>> run;
  std::optional<k::Error> unwritten;
  {
    py::gil_scoped_release unlocked;
    const auto runInto = [&](std::ostream* to) {
      std::optional<k::io::ArmTableWriter> writer;
      run = k::runArm(request, [&](const std::vector<k::ArmRow>& rows, std::size_t rowsInAll) {
        arrays.add(rows, rowsInAll);
        if (!to) return true;
        if (!writer) writer.emplace(*to, request.lengthUnit, table);
        writer->write(rows);
        return static_cast<bool>(*to);  // a failed write stops the run; the writer says why
      });
    };
    if (output)
      unwritten = k::io::writeStreamSafely(*output, [&](std::ostream& to) -> std::optional<std::string> {
        runInto(&to);
        if (!*run && run->error().code != k::ErrorCode::Cancelled) return run->error().message;
        return std::nullopt;
      });
    else runInto(nullptr);
  }
  if (run && !*run && run->error().code != k::ErrorCode::Cancelled) throw CoreError(run->error());
  if (unwritten) {
    PyErr_SetString(PyExc_OSError, unwritten->message.c_str());
    throw py::error_already_set();
  }
  for (const std::string& note : k::armNotes(**run))
    if (PyErr_WarnEx(armWarning.ptr(), note.c_str(), 2) != 0) throw py::error_already_set();
  return arrays.take();
}

}  // namespace

void bindArm(py::module_& module, py::handle warning) {
  armWarning = warning;
  module.def("arm", &arm, py::kw_only(), py::arg("example") = py::none(), py::arg("arm") = py::none(),
             py::arg("from_point") = py::none(), py::arg("to_point") = py::none(), py::arg("speed") = py::none(),
             py::arg("elbow") = py::none(), py::arg("samples") = py::none(), py::arg("step_time") = py::none(),
             py::arg("unit") = "m", py::arg("output") = py::none(), py::arg("table") = false,
             "The two-link arm with its tip on a straight line at constant speed, as linkwright-cli arm: "
             "example='seed-arm' (seed 004, in metres) or arm=(upper, forearm), from_point=(x, y), "
             "to_point=(x, y) and speed (length unit/s), each overriding the example's; elbow 'up' or 'down'; "
             "samples rows over the path (2 to 1e7, default 101) or one every step_time seconds; unit, the "
             "length unit's name (default 'm'). Returns a dict of the CLI's columns (time_s, tip_x_UNIT, "
             "tip_y_UNIT, upper_angle_deg, forearm_angle_deg, upper_omega_rad_s, forearm_omega_rad_s, "
             "upper_alpha_rad_s2, forearm_alpha_rad_s2, elbow_x_UNIT, elbow_y_UNIT) as masked arrays: joint "
             "entries are masked where the tip cannot be reached, rates also where the arm is stretched out or "
             "folded. Those rows are SweepWarnings with the CLI's sentences (the exact times the path leaves "
             "the workspace). With output=PATH the CSV (table=True: the aligned table) is written there, "
             "atomically (OSError if it cannot be, the old file kept).");
}

}  // namespace linkwright::python
