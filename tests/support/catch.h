#pragma once
// The one place that knows which Catch2 the system has. Debian 12 ships Catch2 2 (one header);
// Debian 13 ships Catch2 3, the maintained line, whose headers are split and whose Approx and
// string matchers moved. Tests include this header, never Catch2's own, and write the names
// both lines accept (Approx, Catch::Contains, Catch::StartsWith, Catch::EndsWith,
// Catch::Matches). tests/CMakeLists.txt finds Catch2 and defines LINKWRIGHT_CATCH2_MAJOR.
// A runner's file defines CATCH_CONFIG_RUNNER before including this and calls Catch::Session.

#if LINKWRIGHT_CATCH2_MAJOR >= 3

#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>
#include <catch2/generators/catch_generators.hpp>
#include <catch2/generators/catch_generators_range.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>
#ifdef CATCH_CONFIG_RUNNER
#include <catch2/catch_session.hpp>
#endif

#include <string>

using Catch::Approx;

namespace Catch {
// Catch2 2's names for the string matchers, which Catch2 3 keeps under Catch::Matchers
// (and calls a substring match ContainsSubstring).
inline Matchers::StringContainsMatcher Contains(const std::string& text,
                                                CaseSensitive caseSensitivity = CaseSensitive::Yes) {
  return Matchers::ContainsSubstring(text, caseSensitivity);
}
using Matchers::EndsWith;
using Matchers::Matches;
using Matchers::StartsWith;
}  // namespace Catch

#elif LINKWRIGHT_CATCH2_MAJOR == 2

#include <catch2/catch.hpp>

#else
#error "LINKWRIGHT_CATCH2_MAJOR is not set: link the linkwright_catch2 target (tests/CMakeLists.txt)"
#endif
