// Where the time of `linkwright-cli analyze --example funsho-fourbar --forces --samples 6284`
// goes (issue 20, item 4: "the CLI's output is not the bottleneck"): seed 004's loop, θ from 0
// to 2π in 6284 samples, solved with forces and written as CSV. Names read Csv/<Part>; every
// case handles the same 6284-row table once per iteration.
//   Solve         sweep() and sweepForces(), fresh results, as the CLI calls them
//   Write         io::writeSweepCsv into an std::ostringstream, then str(): the CLI's bytes
//   Analyze       Solve then Write: the CLI in process, without the file
//   Cells         the writer's cell texts appended to one reserved string, no stream
//   Printf17g     the same cells with std::snprintf("%.17g"), the comparison
//   ToChars       the same cells with std::to_chars shortest, no stream
//   Stream        the CLI's finished rows inserted one by one into an std::ostringstream, as
//                 the writer does, then str(): the stream's own cost, in memory the loop has
//                 already mapped (a fresh process, and Write, pay page faults on top)
// bytes_per_second is the output's size over the time (the CLI's bytes for Solve and Analyze,
// so the rates compare). Before running, the program checks that Cells reproduces the writer's
// bytes and exits 1 if not. docs/benchmarks.md ("CSV output") has the figures.

#include "kinematics/design/examples.h"
#include "kinematics/dynamics/force_columns.h"
#include "kinematics/dynamics/force_sweep.h"
#include "kinematics/io/csv_writer.h"
#include "kinematics/model/number_text.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/sweep.h"
#include "kinematics/solve/sweep_columns.h"

#include <benchmark/benchmark.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

using namespace linkwright::kinematics;

namespace {

// Seed 004: `for TH1=0:0.001:2*pi`, 6284 values of the crank angle.
constexpr std::size_t kSamples = 6284;

struct Table {
  Example example;
  SweepSpec spec;
  SweepResult kinematics;
  ForceSweep forces;
  std::string cliCsv;  // what the CLI writes
};

// The CLI's sweep for `--example funsho-fourbar --samples 6284` (sweep_options.cpp: the
// example's speed and its 0–360° table, split into --samples points).
const Table& table() {
  static const Table t = [] {
    Table s;
    s.example = findExample("funsho-fourbar").value();
    s.spec =
        SweepSpec{degToRad(s.example.fromDeg), degToRad(s.example.toDeg), kSamples, s.example.omega, s.example.alpha};
    s.kinematics = sweep(s.example.mechanism, s.spec).value();
    s.forces = sweepForces(s.example.mechanism, s.example.dynamics, s.kinematics).value();
    std::ostringstream out;
    io::writeSweepCsv(out, s.example.mechanism, s.kinematics, s.forces);
    s.cliCsv = out.str();
    return s;
  }();
  return t;
}

void reportBytes(benchmark::State& state, std::size_t bytesPerCall) {
  state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(bytesPerCall));
  state.counters["bytes"] = static_cast<double>(bytesPerCall);
}

void solveBenchmark(benchmark::State& state) {
  const Table& t = table();
  for (auto _ : state) {
    auto kinematics = sweep(t.example.mechanism, t.spec);
    auto forces = sweepForces(t.example.mechanism, t.example.dynamics, *kinematics);
    benchmark::DoNotOptimize(forces);
  }
  reportBytes(state, t.cliCsv.size());
}

void writeBenchmark(benchmark::State& state) {
  const Table& t = table();
  std::size_t bytes = 0;
  for (auto _ : state) {
    std::ostringstream out;
    io::writeSweepCsv(out, t.example.mechanism, t.kinematics, t.forces);
    const std::string text = out.str();
    bytes = text.size();
    benchmark::DoNotOptimize(text.data());
  }
  reportBytes(state, bytes);
}

void analyzeBenchmark(benchmark::State& state) {
  const Table& t = table();
  std::size_t bytes = 0;
  for (auto _ : state) {
    auto kinematics = sweep(t.example.mechanism, t.spec);
    auto forces = sweepForces(t.example.mechanism, t.example.dynamics, *kinematics);
    std::ostringstream out;
    io::writeSweepCsv(out, t.example.mechanism, *kinematics, *forces);
    const std::string text = out.str();
    bytes = text.size();
    benchmark::DoNotOptimize(text.data());
  }
  reportBytes(state, bytes);
}

// The writer's cells (same columns, same empty cells, the header copied) appended to one
// string reserved up front, each number by `format(out, value, grid)`; `grid` marks the input
// column, which the writer prints to 12 significant digits.
template <typename Format>
void formatTable(const Table& t, std::string& out, Format format) {
  const Mechanism& m = t.example.mechanism;
  const SweepResult& r = t.kinematics;
  const std::vector<SweepColumn> columns = sweepColumns(m, r.request, !r.time.empty());
  const std::vector<ForceColumn> forceCols = forceColumns(t.forces.bodies);
  out.clear();
  out.reserve(t.cliCsv.size() * 2);
  out.append(t.cliCsv, 0, t.cliCsv.find('\n') + 1);
  for (std::size_t j = 0; j < r.size(); ++j) {
    if (!r.assembled(j)) continue;
    for (std::size_t c = 0; c < columns.size(); ++c) {
      if (c) out += ',';
      const bool grid = columns[c].quantity == ColumnQuantity::InputAngle;
      if (r.ok(j) || !columns[c].isRate()) format(out, columns[c].value(r, j), grid);
    }
    for (const ForceColumn& c : forceCols) {
      out += ',';
      if (t.forces.ok(j)) format(out, c.value(t.forces, j), false);
    }
    out += "\r\n";
  }
}

// The writer's own cell texts (number_text.h), one std::string each: the CLI's bytes
// without the stream.
void cliCells(std::string& out, double value, bool grid) { out += grid ? formatShort(value, 12) : formatDouble(value); }

void printf17g(std::string& out, double value, bool) {
  char buffer[32];
  out.append(buffer, static_cast<std::size_t>(std::snprintf(buffer, sizeof buffer, "%.17g", value)));
}

void toCharsShortest(std::string& out, double value, bool) {
  char buffer[32];
  out.append(buffer, std::to_chars(buffer, buffer + sizeof buffer, value).ptr);
}

template <void (*Format)(std::string&, double, bool)>
void formatBenchmark(benchmark::State& state) {
  const Table& t = table();
  std::string out;
  for (auto _ : state) {
    formatTable(t, out, Format);
    benchmark::DoNotOptimize(out.data());
  }
  reportBytes(state, out.size());
}

void streamBenchmark(benchmark::State& state) {
  const Table& t = table();
  std::vector<std::string_view> rows;
  for (std::size_t from = 0; from < t.cliCsv.size();) {
    const std::size_t to = t.cliCsv.find('\n', from) + 1;
    rows.emplace_back(t.cliCsv.data() + from, to - from);
    from = to;
  }
  for (auto _ : state) {
    std::ostringstream out;
    for (const std::string_view row : rows) out << row;
    const std::string text = out.str();
    benchmark::DoNotOptimize(text.data());
  }
  reportBytes(state, t.cliCsv.size());
}

}  // namespace

int main(int argc, char** argv) {
  const Table& t = table();
  std::size_t cells = 0;
  for (const char c : t.cliCsv) cells += c == ',' || c == '\n' ? 1 : 0;
  std::printf("funsho-fourbar --forces --samples %zu: %zu rows, %zu cells with the header, %zu bytes of CSV\n",
              kSamples, t.kinematics.size(), cells, t.cliCsv.size());
  std::string text;
  formatTable(t, text, cliCells);
  if (text != t.cliCsv) {
    std::fprintf(stderr, "Csv/Cells does not reproduce the writer's bytes\n");
    return 1;
  }
  for (const auto& [name, fn] : {std::pair{"Csv/Solve", &solveBenchmark},
                                 {"Csv/Write", &writeBenchmark},
                                 {"Csv/Analyze", &analyzeBenchmark},
                                 {"Csv/Cells", &formatBenchmark<cliCells>},
                                 {"Csv/Printf17g", &formatBenchmark<printf17g>},
                                 {"Csv/ToChars", &formatBenchmark<toCharsShortest>},
                                 {"Csv/Stream", &streamBenchmark}})
    benchmark::RegisterBenchmark(name, fn)->Unit(benchmark::kMillisecond);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
