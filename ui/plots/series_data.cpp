#include "ui/plots/series_data.h"

#include <algorithm>
#include <cmath>

namespace linkwright::ui {
namespace {

namespace k = kinematics;
using k::ColumnQuantity;

// Reads one quantity's samples from the sweep, in the plot's units; empty if the sweep did
// not compute its column.
class Column {
public:
  Column(const k::SweepResult& s, PlotQuantity q, AngleUnit unit, const k::AdvantageSeries* ratios)
      : m_q(q), m_unit(unit) {
    if (q.ratio != RatioQuantity::None) {
      if (ratios == nullptr) return;
      const auto& column = q.ratio == RatioQuantity::VelocityRatio ? ratios->velocityRatio : ratios->advantage;
      if (column.size() == s.size()) m_ratio = &column;
      return;
    }
    const auto pick = [&s](const auto& columns, std::size_t index) {
      const bool present = index < columns.size() && columns[index].size() == s.size();
      return present ? &columns[index] : nullptr;
    };
    switch (q.column) {
    case ColumnQuantity::Time: m_scalar = &s.time; break;
    case ColumnQuantity::InputAngle:
    case ColumnQuantity::InputLength: m_scalar = &s.inputAngle; break;
    case ColumnQuantity::LinkAngle: m_scalar = pick(s.linkAngle, q.index); break;
    case ColumnQuantity::LinkOmega: m_scalar = pick(s.linkOmega, q.index); break;
    case ColumnQuantity::LinkAlpha: m_scalar = pick(s.linkAlpha, q.index); break;
    case ColumnQuantity::TransmissionAngle: m_scalar = pick(s.transmissionAngle, q.index); break;
    case ColumnQuantity::PointX:
    case ColumnQuantity::PointY: m_vector = pick(s.position, q.index); break;
    case ColumnQuantity::PointVx:
    case ColumnQuantity::PointVy: m_vector = pick(s.velocity, q.index); break;
    case ColumnQuantity::PointAx:
    case ColumnQuantity::PointAy: m_vector = pick(s.acceleration, q.index); break;
    }
  }

  bool present() const { return m_scalar != nullptr || m_vector != nullptr || m_ratio != nullptr; }
  /// False where a ratio is infinite or undefined.
  bool finite(std::size_t j) const { return m_ratio == nullptr || (*m_ratio)[j].kind == k::RatioKind::Finite; }

  double at(std::size_t j) const {
    if (m_ratio != nullptr) return (*m_ratio)[j].value;  // the core's unit, whatever the angle unit
    if (m_scalar != nullptr) return toAngleUnit((*m_scalar)[j], m_unit);
    const bool x = m_q.column == ColumnQuantity::PointX || m_q.column == ColumnQuantity::PointVx ||
                   m_q.column == ColumnQuantity::PointAx;
    return x ? (*m_vector)[j].x() : (*m_vector)[j].y();
  }

private:
  PlotQuantity m_q;
  AngleUnit m_unit;
  const std::vector<double>* m_scalar = nullptr;           // angles, rad
  const std::vector<Eigen::Vector2d>* m_vector = nullptr;  // points, length unit
  const std::vector<k::Ratio>* m_ratio = nullptr;
};

// Positions (and the ratios they give) exist wherever assembled; rates only where the sample is ok.
bool sampleCarries(const k::SweepResult& s, PlotQuantity q, std::size_t j) {
  const QuantityKind kind = quantityKind(q);
  const bool positional =
      kind == QuantityKind::Angle || kind == QuantityKind::Position || q.ratio != RatioQuantity::None;
  return positional ? s.assembled(j) : s.ok(j);
}

}  // namespace

qsizetype SeriesRuns::pointCount() const {
  qsizetype n = 0;
  for (const QList<QPointF>& run : runs) n += run.size();
  return n;
}

bool hasValue(const k::SweepResult& s, PlotQuantity q, std::size_t j, const k::AdvantageSeries* ratios) {
  const Column column(s, q, AngleUnit::Radians, ratios);
  return column.present() && sampleCarries(s, q, j) && column.finite(j);
}

void buildSeriesRuns(const k::SweepResult& s, PlotQuantity q, AngleUnit unit, SeriesRuns& out, const XSource& x,
                     const k::AdvantageSeries* ratios) {
  const Column values(s, q, unit, ratios);
  qsizetype runCount = 0;
  out.minY = 0.0;
  out.maxY = 0.0;
  bool first = true;
  std::size_t j = 0;
  // The last guard: a value that is still not finite is left out like a missing one.
  const auto plottable = [&](std::size_t k) {
    return sampleCarries(s, q, k) && values.finite(k) && std::isfinite(values.at(k));
  };
  // Within an assembled stretch the advantage changes sign only through infinity (the output
  // at rest between two samples): it would pass zero only where the crank cannot drive, which
  // ends the crank's range and so the stretch. The line is broken there, not drawn across.
  const bool breaksAtSignChange = q.ratio == RatioQuantity::Advantage;
  const auto continues = [&](std::size_t k) {
    return plottable(k) && !(breaksAtSignChange && std::signbit(values.at(k)) != std::signbit(values.at(k - 1)));
  };
  while (values.present() && j < s.size()) {
    if (!plottable(j)) {
      ++j;
      continue;
    }
    std::size_t end = j + 1;
    while (end < s.size() && continues(end)) ++end;
    if (runCount == out.runs.size()) out.runs.emplace_back();
    QList<QPointF>& run = out.runs[runCount++];
    run.clear();
    run.reserve(static_cast<qsizetype>(end - j));
    for (; j < end; ++j) {
      const double y = values.at(j);
      run.append(QPointF(sampleX(s, j, x, unit), y));
      out.minY = first ? y : std::min(out.minY, y);
      out.maxY = first ? y : std::max(out.maxY, y);
      first = false;
    }
  }
  out.runs.resize(runCount);
}

}  // namespace linkwright::ui
