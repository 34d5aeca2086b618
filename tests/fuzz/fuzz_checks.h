#pragma once
// What a fuzzed input must never do, as plain functions: the libFuzzer targets call them
// and abort on a finding, and fuzz_regression_test.cpp runs every stored input through them
// in the ordinary test suite, so a crash once found stays fixed.
//
// The promise checked: any input gives a clear error or a result, never a crash, a hang, an
// exit code outside the documented ones, or "nan"/"inf" in any output.

#include "app/cli/arguments.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace linkwright::fuzz {

/// A document's bytes as linkwright-cli sees them: written to `scratchPath`, then analyze and
/// analyze --forces over a 13-sample grid, classify, and centres at three inputs. Returns what went wrong, or nothing.
/// (extremes, whose refinement costs ten times more, is left to the arguments fuzzer and the
/// soak, so that the loader runs fast enough to be fuzzed for 10^7 inputs.)
std::optional<std::string> checkDocument(std::string_view bytes, const std::string& scratchPath);

/// NUL-separated command-line arguments: parsed, and run when isCheapToRun. Returns what went
/// wrong, or nothing.
std::optional<std::string> checkArguments(std::string_view bytes);

/// One linkwright-cli run, in-process: its exit code must be a documented one, exit code 2 must
/// come with a message, and no output or message may hold a nan or inf not in `typed` (the
/// arguments, and any file the run reads, are added to it). Returns what went wrong, or nothing;
/// `exitCode`, if given, receives the exit code.
std::optional<std::string> checkCliRun(const std::vector<std::string>& args, std::string_view typed = {},
                                       int* exitCode = nullptr);

/// Whether the fuzzer runs `invocation`: a command that reads and writes no file and finishes
/// in milliseconds (classify, centres, examples, help, version, and analyze or extremes whose
/// grid is at most a few thousand samples). Anything slower would be reported as a hang.
bool isCheapToRun(const cli::Invocation& invocation);

/// The arguments in NUL-separated bytes (at most 32, each at most 256 bytes: the rest is
/// dropped, so an input cannot ask for unbounded work).
std::vector<std::string> splitArguments(std::string_view bytes);

/// The first "nan" or "inf" written as a number in `text` ("-nan", "inf", "+INF"…) that the
/// user did not type (is not part of `typed`: the arguments or the document, which messages
/// quote), or nothing. Words such as "infinite" or "at infinity" are not numbers and pass.
std::optional<std::string> nonFiniteToken(std::string_view text, std::string_view typed = {});

}  // namespace linkwright::fuzz
