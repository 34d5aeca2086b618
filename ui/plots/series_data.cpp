#include "ui/plots/series_data.h"

#include "kinematics/model/fourbar.h"

#include <algorithm>

namespace linkwright::ui {
namespace {

namespace k = kinematics;

// The sweep column of `q`, or null if the sweep did not compute it.
const std::vector<double>* column(const k::SweepResult& s, PlotQuantity q) {
  const auto pick = [&s](const std::vector<std::vector<double>>& columns, std::size_t index) {
    const bool present = index < columns.size() && columns[index].size() == s.size();
    return present ? &columns[index] : nullptr;
  };
  switch (q) {
  case PlotQuantity::CouplerAngle: return pick(s.linkAngle, k::fourbar::kCoupler.index);
  case PlotQuantity::RockerAngle: return pick(s.linkAngle, k::fourbar::kRocker.index);
  case PlotQuantity::TransmissionAngle: return pick(s.transmissionAngle, k::fourbar::kC.index);
  case PlotQuantity::CouplerOmega: return pick(s.linkOmega, k::fourbar::kCoupler.index);
  case PlotQuantity::RockerOmega: return pick(s.linkOmega, k::fourbar::kRocker.index);
  case PlotQuantity::CouplerAlpha: return pick(s.linkAlpha, k::fourbar::kCoupler.index);
  case PlotQuantity::RockerAlpha: return pick(s.linkAlpha, k::fourbar::kRocker.index);
  }
  return nullptr;
}

bool sampleCarries(const k::SweepResult& s, PlotQuantity q, std::size_t j) {
  return quantityKind(q) == QuantityKind::Angle ? s.assembled(j) : s.ok(j);
}

} // namespace

qsizetype SeriesRuns::pointCount() const {
  qsizetype n = 0;
  for (const QList<QPointF>& run : runs) n += run.size();
  return n;
}

bool hasValue(const k::SweepResult& s, PlotQuantity q, std::size_t j) {
  return column(s, q) != nullptr && sampleCarries(s, q, j);
}

void buildSeriesRuns(const k::SweepResult& s, PlotQuantity q, AngleUnit unit, SeriesRuns& out) {
  const std::vector<double>* values = column(s, q);
  qsizetype runCount = 0;
  out.minY = 0.0;
  out.maxY = 0.0;
  bool first = true;
  std::size_t j = 0;
  while (values != nullptr && j < s.size()) {
    if (!sampleCarries(s, q, j)) {
      ++j;
      continue;
    }
    std::size_t end = j;
    while (end < s.size() && sampleCarries(s, q, end)) ++end;
    if (runCount == out.runs.size()) out.runs.emplace_back();
    QList<QPointF>& run = out.runs[runCount++];
    run.clear();
    run.reserve(static_cast<qsizetype>(end - j));
    for (; j < end; ++j) {
      const double y = toAngleUnit((*values)[j], unit);
      run.append(QPointF(toAngleUnit(s.inputAngle[j], unit), y));
      out.minY = first ? y : std::min(out.minY, y);
      out.maxY = first ? y : std::max(out.maxY, y);
      first = false;
    }
  }
  out.runs.resize(runCount);
}

} // namespace linkwright::ui
