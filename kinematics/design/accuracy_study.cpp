#include "kinematics/design/accuracy_study.h"

#include "kinematics/design/examples.h"
#include "kinematics/model/constraint_form.h"
#include "kinematics/model/number_text.h"
#include "kinematics/solve/pose_solver.h"

#include <algorithm>
#include <chrono>
#include <utility>

namespace linkwright::kinematics {
namespace {

constexpr std::size_t kSampleCounts[] = {12, 36, 360, 3600};
constexpr std::size_t kReferenceSamples = 7200;  // refined too: independent of every row's grid
constexpr int kRepeats = 5;
constexpr double kNewtonTolerances[] = {1e-4, 1e-6, 1e-8, 1e-10, 1e-12, 1e-14};
constexpr std::size_t kNewtonSamples = 360;

struct Subject {
  std::string name;
  Mechanism mechanism;
  double omega = 0.0;
};

// The median wall time of a few runs, in microseconds, and the last run's result.
template <typename F>
auto timed(F&& f, double& microseconds) {
  std::vector<double> times;
  auto result = f();
  for (int i = 0; i < kRepeats; ++i) {
    const auto start = std::chrono::steady_clock::now();
    result = f();
    times.push_back(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count());
  }
  std::nth_element(times.begin(), times.begin() + kRepeats / 2, times.end());
  microseconds = times[kRepeats / 2];
  return result;
}

// The same linkage with every RRR joint solved by Newton, at each tolerance, against the
// closed form at the same samples: this isolates the solver's error from the sampling's.
Result<std::vector<AccuracyRow>> measureNewton(const Subject& s) {
  const auto start = solvePose(s.mechanism, {0.0, s.omega, 0.0}, {false, false});
  if (!start) return start.error();
  const Mechanism newton = withNewtonPoints(s.mechanism, start->position);
  AccuracyRow closed{s.name, "closed-form", kNewtonSamples, 0.0, {}, "-"};
  const auto exact = timed([&] { return sampledPeaks(s.mechanism, s.omega, kNewtonSamples, DerivativeMethod::Exact); },
                           closed.microseconds);
  if (!exact) return exact.error();
  std::vector<AccuracyRow> rows{closed};
  for (const double tolerance : kNewtonTolerances) {
    AccuracyRow r{s.name, "newton-" + formatShort(tolerance, 1), kNewtonSamples, 0.0, {}, "closed-form"};
    const NewtonSettings settings{tolerance, 50};
    const auto read =
        timed([&] { return sampledPeaks(newton, s.omega, kNewtonSamples, DerivativeMethod::Exact, settings); },
              r.microseconds);
    if (!read) return read.error();
    r.error = peakError(*read, *exact);
    rows.push_back(r);
  }
  return rows;
}

Result<std::vector<AccuracyRow>> measure(const Subject& s, FrontEnd frontEnd) {
  const auto reference = exactPeaks(s.mechanism, s.omega, kReferenceSamples);
  if (!reference)
    return Error{reference.error().code, fieldName("example", frontEnd), s.name + ": " + reference.error().message};
  std::vector<AccuracyRow> rows;
  for (const std::size_t n : kSampleCounts) {
    for (const auto& choice :
         {std::pair{"samples", DerivativeMethod::Exact}, {"frames", DerivativeMethod::FiniteDifference}}) {
      // A plain local, not a structured binding: clang 14 cannot capture those in a lambda.
      const DerivativeMethod derivative = choice.second;
      AccuracyRow r{s.name, choice.first, n, 0.0, {}};
      const auto read = timed([&] { return sampledPeaks(s.mechanism, s.omega, n, derivative); }, r.microseconds);
      if (!read) return read.error();
      r.error = peakError(*read, *reference);
      rows.push_back(r);
    }
    AccuracyRow r{s.name, "refined", n, 0.0, {}};
    const auto refined = timed([&] { return exactPeaks(s.mechanism, s.omega, n); }, r.microseconds);
    if (!refined) return refined.error();
    r.error = peakError(*refined, *reference);
    rows.push_back(r);
  }
  const auto newton = measureNewton(s);
  if (!newton) return newton.error();
  rows.insert(rows.end(), newton->begin(), newton->end());
  return rows;
}

}  // namespace

std::vector<std::string> defaultAccuracyExamples() { return {"miranda-fourbar", "ls3-engine", "shaper", "watt-ii"}; }

Result<std::vector<AccuracyRow>> measureAccuracy(const AccuracyRequest& request, const RunControl& control) {
  const std::vector<std::string> names = request.example ? std::vector{*request.example} : defaultAccuracyExamples();
  std::vector<AccuracyRow> rows;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (control.cancelled()) return cancelledError();
    const auto example = findExample(names[i]);
    if (!example) {
      const std::string name = fieldName("example", request.frontEnd);
      return Error{ErrorCode::InvalidValue, name,
                   name + ": no example named '" + names[i] + "' (see " +
                       (request.frontEnd == FrontEnd::Python ? "linkwright.examples()" : "linkwright-cli examples") +
                       ")"};
    }
    const auto measured = measure({names[i], example->mechanism, example->omega}, request.frontEnd);
    if (!measured) return measured.error();
    rows.insert(rows.end(), measured->begin(), measured->end());
    if (control.progress) control.progress(i + 1, names.size());
  }
  return rows;
}

}  // namespace linkwright::kinematics
