// linkwright_soak: random linkages of every kind (random_linkages.h), each swept over a full
// turn and checked (soak_checks.h). Exit 0 when every check passed, 1 on any finding (each
// printed with the seed, the linkage's index and its dimensions, to reproduce), 2 for bad
// usage. CTest runs it briefly (soak.short); docs/robustness.md gives the long command.
//
//   linkwright_soak [--count N] [--seed S] [--samples K] [--kind all|four-bar|slider-crank|shaper|six-bar|newton|driven]
//                   [--from I]
//
// --from I draws the first I linkages without checking them, so a finding's linkage I is
// reproduced (with the same seed, count and kind) in seconds.

#include "tests/kinematics/soak/random_linkages.h"
#include "tests/kinematics/soak/soak_checks.h"

#include "kinematics/model/units.h"

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <map>
#include <string>
#include <vector>

using namespace linkwright;
namespace k = kinematics;

namespace {

struct Options {
  long long count = 2000;
  long long from = 0;
  unsigned seed = 20261124;
  std::size_t samples = 73;
  std::vector<test::LinkageKind> kinds{std::begin(test::kAllKinds), std::end(test::kAllKinds)};
};

struct Tally {
  long long drawn = 0, refused = 0, assembled = 0, findings = 0;
  std::size_t samples = 0, ratesCompared = 0, ratesSkipped = 0;
  double worstClosure = 0.0, worstRateRatio = 0.0;
};

bool parse(int argc, char** argv, Options& o) {
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (i + 1 >= argc) return false;
    const std::string v = argv[++i];
    if (a == "--count") o.count = std::atoll(v.c_str());
    else if (a == "--from") o.from = std::atoll(v.c_str());
    else if (a == "--seed") o.seed = static_cast<unsigned>(std::strtoul(v.c_str(), nullptr, 10));
    else if (a == "--samples") o.samples = static_cast<std::size_t>(std::atoll(v.c_str()));
    else if (a == "--kind") {
      o.kinds.clear();
      for (const auto kind : test::kAllKinds)
        if (v == "all" || v == test::kindName(kind)) o.kinds.push_back(kind);
      if (o.kinds.empty()) return false;
    } else return false;
  }
  return o.count > 0 && o.samples >= 3 && o.from >= 0 && o.from < o.count;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  if (!parse(argc, argv, o)) {
    std::cerr << "usage: linkwright_soak [--count N] [--seed S] [--samples K>=3] "
                 "[--kind all|four-bar|slider-crank|shaper|six-bar|newton|driven] [--from I<N]\n";
    return 2;
  }
  const auto start = std::chrono::steady_clock::now();
  std::mt19937 rng(o.seed);
  std::map<std::string, Tally> tallies;
  int printed = 0;
  for (long long n = 0; n < o.count; ++n) {
    const test::LinkageKind kind = o.kinds[static_cast<std::size_t>(n) % o.kinds.size()];
    const test::DrawnLinkage d = test::drawLinkage(kind, rng);
    // A crank speed between 0.1 and 1000 rad/s either way, α up to ±ω².
    const double omega =
        (test::unit(rng) < 0.5 ? -1.0 : 1.0) * std::exp(std::log(0.1) + std::log(1e4) * test::unit(rng));
    const double alpha = (2.0 * test::unit(rng) - 1.0) * omega * omega;
    if (n < o.from) continue;
    Tally& t = tallies[test::kindName(kind)];
    ++t.drawn;
    std::vector<std::string> findings;
    if (!d.mechanism) {
      ++t.refused;
      if (d.refusal.empty()) findings.push_back("refused without a message");
    } else {
      // The drawn speed per unit of input: a linear driver's scales with the linkage.
      const k::SweepSpec spec{d.inputFrom, d.inputTo, o.samples, omega * d.inputScale, alpha * d.inputScale};
      const auto s = k::sweep(*d.mechanism, spec);
      if (!s) {
        findings.push_back("sweep failed: " + s.error().message);
      } else {
        const test::SweepCheck c = test::checkSweep(*d.mechanism, spec, *s, 3, d.inputScale);
        if (c.assembled > 0) ++t.assembled;
        t.samples += c.assembled;
        t.ratesCompared += c.ratesCompared;
        t.ratesSkipped += c.ratesSkipped;
        t.worstClosure = std::max(t.worstClosure, c.worstClosure);
        t.worstRateRatio = std::max(t.worstRateRatio, c.worstRateRatio);
        findings = c.findings;
      }
    }
    if (findings.empty()) continue;
    ++t.findings;
    if (printed++ < 20) {
      std::cout << "FINDING: seed " << o.seed << ", linkage " << n << ": " << d.description << ", omega " << omega
                << " rad/s, alpha " << alpha << " rad/s2\n";
      for (std::size_t f = 0; f < std::min<std::size_t>(findings.size(), 5); ++f)
        std::cout << "  " << findings[f] << "\n";
    }
  }
  long long findings = 0;
  std::cout << "kind          drawn  refused  assembled  samples  rates compared/skipped  worst closure  worst "
               "rate/tol  findings\n";
  for (const auto& [name, t] : tallies) {
    std::printf("%-12s %6lld %8lld %10lld %8zu %12zu/%-9zu %14.2e %15.3f %9lld\n", name.c_str(), t.drawn, t.refused,
                t.assembled, t.samples, t.ratesCompared, t.ratesSkipped, t.worstClosure, t.worstRateRatio, t.findings);
    findings += t.findings;
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << o.count - o.from << " linkages, seed " << o.seed << ", " << o.samples << " samples each, " << seconds
            << " s: " << (findings == 0 ? "no finding" : std::to_string(findings) + " with findings") << "\n";
  return findings == 0 ? 0 : 1;
}
