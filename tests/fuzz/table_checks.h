#pragma once
// What a fuzzed table must never do, for the two readers of other people's numbers: compare's
// table of another tool's results (kinematics/io/numeric_table_csv.h) and a measured motion
// law (kinematics/io/law_table_csv.h). The libFuzzer targets call these and abort on a
// finding; fuzz_regression_test.cpp runs every stored table through them.
//
// The promise checked: any bytes give a clear error or a table that keeps what its header
// documents, never a crash, an exception, a non-finite number or "nan"/"inf" in a message
// that the bytes did not hold.

#include <optional>
#include <string>
#include <string_view>

namespace linkwright::fuzz {

/// Tables above this many rows are read and checked, but not compared: the comparison solves
/// a pose per row at each of about 150 offsets, which a fuzzer would report as a hang.
inline constexpr std::size_t kMaxComparedRows = 200;

/// The bytes as a compare table: on success every row has a cell per column, every value and
/// rounding is finite, the line numbers increase, the layout flags agree; then, written to
/// `scratchPath`, `linkwright-cli compare --example thesis-crank-rocker FILE --map auto` (and
/// --json) must exit 0 or 2 with finite output. Returns what went wrong, or nothing.
std::optional<std::string> checkCompareTable(std::string_view bytes, const std::string& scratchPath);

/// The bytes as a law table, for a crank and for a linear driver in mm: on success at least
/// four rows, times strictly increasing within ±1e6 s, every value finite and within the input
/// domain; a law checkMotionLaw accepts gives a finite state at every row and between. Every
/// message is non-empty. Returns what went wrong, or nothing.
std::optional<std::string> checkLawTable(std::string_view bytes);

}  // namespace linkwright::fuzz
