#include "app/cli/progress.h"

#include <algorithm>
#include <iostream>

#include <unistd.h>

namespace linkwright::cli {

bool isTerminal(const std::ostream& err) { return &err == &std::cerr && isatty(STDERR_FILENO) == 1; }

bool progressShown(const std::ostream& err, const std::ostream* output) {
  const bool outputOnTerminal = output == &std::cout && isatty(STDOUT_FILENO) == 1;
  return isTerminal(err) && !outputOnTerminal;
}

Progress::Progress(std::ostream& err, std::string what, std::string unit, bool shown, std::chrono::milliseconds after)
    : m_err(err), m_what(std::move(what)), m_unit(std::move(unit)), m_shown(shown), m_after(after) {}

Progress::~Progress() { clear(); }

void Progress::clear() {
  if (m_width > 0) m_err << '\r' << std::string(m_width, ' ') << '\r' << std::flush;
  m_width = 0;
  m_last = {};
}

void Progress::update(std::size_t done, std::size_t total) {
  if (!m_shown || total == 0) return;
  const Clock::time_point now = Clock::now();
  if (now - m_start < m_after || now - m_last < std::chrono::milliseconds(100)) return;
  m_last = now;
  const std::string line = m_what + ": " + std::to_string(done * 100 / total) + " % (" + std::to_string(done) + " of " +
                           std::to_string(total) + " " + m_unit + ")";
  m_err << '\r' << line;
  if (line.size() < m_width) m_err << std::string(m_width - line.size(), ' ');
  m_err << std::flush;
  m_width = std::max(m_width, line.size());
}

}  // namespace linkwright::cli
