#include "tests/fuzz/fuzz_checks.h"

#include "app/cli/arguments.h"
#include "app/cli/cli.h"
#include "app/cli/commands.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>

namespace linkwright::fuzz {
namespace {

constexpr std::size_t kMaxArguments = 32;
constexpr std::size_t kMaxArgumentBytes = 256;

bool isTokenChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '+' || c == '-'; }

std::string lowerCase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

}  // namespace

std::optional<std::string> checkCliRun(const std::vector<std::string>& args, std::string_view typed, int* exitCode) {
  std::ostringstream out, err;
  const int code = cli::runCli(args, out, err);
  if (exitCode != nullptr) *exitCode = code;
  std::string call, quoted(typed);
  for (const auto& a : args) {
    call += " '" + a + "'";
    quoted += "\n" + a;
  }
  if (code < 0 || code > 3) return "exit code " + std::to_string(code) + " for" + call;
  if (code == 2 && err.str().empty()) return "exit code 2 without a message for" + call;
  if (const auto token = nonFiniteToken(out.str(), quoted)) return "'" + *token + "' in the output of" + call;
  if (const auto token = nonFiniteToken(err.str(), quoted)) return "'" + *token + "' in the messages of" + call;
  return std::nullopt;
}

std::optional<std::string> nonFiniteToken(std::string_view text, std::string_view typed) {
  std::optional<std::string> typedLower;  // made only when a nan or inf turns up
  std::size_t i = 0;
  while (i < text.size()) {
    if (!isTokenChar(text[i])) {
      ++i;
      continue;
    }
    std::size_t end = i;
    while (end < text.size() && isTokenChar(text[end])) ++end;
    const std::string token(text.substr(i, end - i));
    const std::size_t sign = token[0] == '-' || token[0] == '+' ? 1 : 0;
    const std::string bare = token.size() - sign == 3 ? lowerCase(token.substr(sign)) : std::string();
    if (bare == "nan" || bare == "inf") {
      if (!typedLower) typedLower = lowerCase(std::string(typed));
      if (typedLower->find(lowerCase(token)) == std::string::npos) return token;
    }
    i = end;
  }
  return std::nullopt;
}

std::vector<std::string> splitArguments(std::string_view bytes) {
  std::vector<std::string> args;
  std::size_t start = 0;
  while (start <= bytes.size() && args.size() < kMaxArguments) {
    const std::size_t nul = bytes.find('\0', start);
    const std::size_t end = nul == std::string_view::npos ? bytes.size() : nul;
    args.emplace_back(bytes.substr(start, std::min(end - start, kMaxArgumentBytes)));
    if (nul == std::string_view::npos) break;
    start = nul + 1;
  }
  return args;
}

std::optional<std::string> checkDocument(std::string_view bytes, const std::string& scratchPath) {
  {
    std::ofstream file(scratchPath, std::ios::binary | std::ios::trunc);
    file.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!file) return "cannot write the scratch file " + scratchPath;
  }
  // analyze first: a document it refuses, as most mutated inputs are, the others would refuse
  // the same way.
  int code = 0;
  if (auto finding = checkCliRun({"analyze", scratchPath, "--samples", "13"}, bytes, &code)) return finding;
  if (code == 2) return std::nullopt;
  if (auto finding = checkCliRun({"analyze", scratchPath, "--samples", "13", "--forces"}, bytes)) return finding;
  if (auto finding = checkCliRun({"classify", scratchPath}, bytes)) return finding;
  // Kennedy's circle diagram on whatever bodies the document's linkage has.
  if (auto finding = checkCliRun({"centres", scratchPath, "--at", "0,100,230"}, bytes)) return finding;
  return std::nullopt;
}

bool isCheapToRun(const cli::Invocation& inv) {
  using cli::Command;
  if (inv.outputFile || inv.svgFile || inv.documentPath || inv.lawTable) return false;  // files: not here
  switch (inv.command) {
  case Command::Classify:
  case Command::Centres:
  case Command::Examples:
  case Command::Help:
  case Command::Version: return true;
  case Command::Analyze:
  case Command::Extremes: {
    // The grid the CLI itself would sweep, so that no accepted range (--to 999999 at 1°) or
    // --step-time makes a run slow; an invocation it refuses stops before the sweep.
    constexpr std::size_t kMaxFuzzedSamples = 4000;
    const auto resolved = cli::resolveMechanism(inv);
    if (!resolved) return true;
    const auto spec = cli::sweepSpecFor(inv, resolved->defaults);
    return !spec || spec->samples <= kMaxFuzzedSamples;
  }
  default: return false;
  }
}

std::optional<std::string> checkArguments(std::string_view bytes) {
  const auto args = splitArguments(bytes);
  const auto parsed = cli::parseArguments(args);
  if (!parsed) {
    if (parsed.error().message.empty()) return std::string("a parse error without a message");
    std::string typed;
    for (const auto& a : args) typed += a + "\n";
    if (const auto token = nonFiniteToken(parsed.error().message, typed)) return "'" + *token + "' in the parse error";
    return std::nullopt;
  }
  if (!isCheapToRun(*parsed)) return std::nullopt;
  return checkCliRun(args);
}

}  // namespace linkwright::fuzz
