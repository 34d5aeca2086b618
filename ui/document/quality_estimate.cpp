#include "ui/document/quality_estimate.h"

#include <QCoreApplication>

#include <chrono>
#include <cmath>

namespace linkwright::ui {

namespace k = kinematics;

double estimateOmega(double omega) { return std::isfinite(omega) && omega != 0.0 ? std::abs(omega) : 1.0; }

QualityEstimate estimatePeakError(const k::Mechanism& mechanism, double omega, std::size_t samplesPerRevolution,
                                  const k::NewtonSettings& newton) {
  const auto start = std::chrono::steady_clock::now();
  QualityEstimate e;
  e.samplesPerRevolution = samplesPerRevolution;
  const double w = estimateOmega(omega);
  const auto exact = k::exactPeaks(mechanism, w);
  const auto read =
      exact ? k::sampledPeaks(mechanism, w, samplesPerRevolution, k::DerivativeMethod::Exact, newton) : exact;
  if (read && exact) {
    e.error = k::peakError(*read, *exact);
  } else {
    const k::Error& why = exact ? read.error() : exact.error();
    e.detail = QString::fromStdString(why.message);
    // The core refuses a crank that cannot turn fully (field "crank"): there is no cycle whose
    // peaks could be read off, so no error to state.
    e.unavailable =
        why.field == "crank"
            ? QCoreApplication::translate("QualityEstimate", "not measurable: the crank does not turn fully")
            : QCoreApplication::translate("QualityEstimate", "not measurable: %1").arg(e.detail);
  }
  e.measureMilliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return e;
}

}  // namespace linkwright::ui
