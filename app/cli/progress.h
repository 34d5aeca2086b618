#pragma once
// Progress of long work on the error stream, for a person watching a terminal: "analyze: 45 %
// (4 500 000 of 10 000 000 samples)", redrawn in place at most ten times a second once the work
// has taken a second, and cleared when it ends. When the stream is not a terminal (a pipe, a
// log, a test's string) nothing is written, so scripts and goldens see no difference.

#include <chrono>
#include <cstddef>
#include <ostream>
#include <string>

namespace linkwright::cli {

/// Whether `err` is the process's standard error and that is a terminal.
bool isTerminal(const std::ostream& err);

/// Whether progress is worth drawing for work that writes to `output` meanwhile (null: to a
/// file): stderr is a terminal, and the output is not drawn on a terminal too, where the
/// progress line would break it up.
bool progressShown(const std::ostream& err, const std::ostream* output);

class Progress {
public:
  /// `what` names the work ("analyze"), `unit` what is counted ("samples"). `shown`: whether to
  /// draw at all; `after`: how long the work runs before the first line.
  Progress(std::ostream& err, std::string what, std::string unit, bool shown,
           std::chrono::milliseconds after = std::chrono::seconds(1));
  Progress(std::ostream& err, std::string what, std::string unit)
      : Progress(err, std::move(what), std::move(unit), isTerminal(err)) {}
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  /// `done` of `total` are done.
  void update(std::size_t done, std::size_t total);
  /// Erases the line drawn, if any, so that output to the same terminal starts on a clean
  /// line; the next update draws it again.
  void clear();

private:
  using Clock = std::chrono::steady_clock;
  std::ostream& m_err;
  std::string m_what, m_unit;
  bool m_shown;
  Clock::time_point m_start = Clock::now();
  Clock::time_point m_last{};
  std::chrono::milliseconds m_after;
  std::size_t m_width = 0;  // of the line drawn, to clear it
};

}  // namespace linkwright::cli
