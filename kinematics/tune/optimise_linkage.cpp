#include "kinematics/tune/optimise_linkage.h"

#include "kinematics/model/recognise.h"

#include <nlopt.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

namespace linkwright::kinematics {
namespace {

// What an infeasible candidate scores: above every feasible score (a peak α, a torque or a
// distance is far below it, a transmission angle's negative is at most 0), finite so that
// Nelder–Mead's ordering and centroid stay finite.
constexpr double kBarrier = 1e300;
// Nelder–Mead's first simplex: a tenth of each range (the variables are scaled to [0, 1]).
constexpr double kInitialStep = 0.1;
// Stop a run when a step changes no variable by more than this (scaled: 1e-9 of its range).
constexpr double kStepTolerance = 1e-9;
// Draws tried for a feasible random start before the run begins from the best so far.
constexpr int kStartDraws = 8;

Error invalid(const std::string& field, const std::string& message) {
  return Error{ErrorCode::InvalidValue, field, message};
}

// The start's class and branch, which every candidate must keep.
struct Baseline {
  std::optional<GrashofClass> grashof;
  Branch branch = Branch::Open;
  std::size_t singular = 0;
};

struct Measured {
  bool feasible = false;
  ObjectiveValue objective;
};

class Search {
public:
  Search(const Design& start, const OptimiseRequest& request, std::vector<OptimiseDimension> dims,
         const std::atomic<bool>* cancel, const OptimiseProgress& progress)
      : m_start(start), m_request(request), m_dims(std::move(dims)), m_cancel(cancel), m_progress(progress),
        m_spec(designSweepSpec(start)) {
    for (std::size_t d = 0; d < m_dims.size(); ++d)
      if (!m_dims[d].fixed && m_dims[d].hi > m_dims[d].lo) m_free.push_back(d);
  }

  const std::vector<OptimiseDimension>& dimensions() const { return m_dims; }
  std::size_t freeCount() const { return m_free.size(); }

  std::vector<double> startValues() const {
    std::vector<double> v;
    for (const OptimiseDimension& d : m_dims) v.push_back(d.dimension.value);
    return v;
  }

  std::vector<double> unscale(const double* x) const {
    std::vector<double> v = startValues();
    for (std::size_t i = 0; i < m_free.size(); ++i) {
      const OptimiseDimension& d = m_dims[m_free[i]];
      v[m_free[i]] = d.lo + std::clamp(x[i], 0.0, 1.0) * (d.hi - d.lo);
    }
    return v;
  }

  std::vector<double> scale(const std::vector<double>& values) const {
    std::vector<double> x;
    for (const std::size_t f : m_free) {
      const OptimiseDimension& d = m_dims[f];
      x.push_back((values[f] - d.lo) / (d.hi - d.lo));
    }
    return x;
  }

  Design designAt(const std::vector<double>& values) const {
    Design d = m_start;
    d.mechanism = withDimensionValues(m_start.mechanism, m_dims, values);
    return d;
  }

  // The design at `values` measured and checked against the baseline.
  Measured measure(const Design& d) {
    Measured out;
    if (sweepInto(d.mechanism, m_spec, {}, m_sweep)) return out;
    for (std::size_t j = 0; j < m_sweep.size(); ++j)
      if (!m_sweep.assembled(j)) return out;
    if (!m_sweep.lockedBetween.empty() || m_sweep.singularAngles.size() > m_baseline.singular) return out;
    if (m_baseline.grashof) {
      const auto f = asFourBar(d.mechanism);
      if (!f || classifyGrashof(f->lengths).category != *m_baseline.grashof || f->branch != m_baseline.branch)
        return out;
    }
    auto value = measureObjective(d, m_request.objective, m_sweep);
    if (!value) return out;
    out.feasible = true;
    out.objective = std::move(*value);
    return out;
  }

  // Sets the baseline from the start; the start's measurement, or why it cannot be improved on.
  Result<ObjectiveValue> measureStart() {
    if (auto e = sweepInto(m_start.mechanism, m_spec, {}, m_sweep)) return *e;
    for (std::size_t j = 0; j < m_sweep.size(); ++j)
      if (!m_sweep.assembled(j) || m_sweep.lockedAfter(j))
        return Error{ErrorCode::NotAssemblable, "design",
                     "the design does not move through its whole grid (" +
                         m_sweep.firstFailure.value_or("it locks between two samples") +
                         "): an optimisation keeps every candidate assembled, so it needs a start that is"};
    m_baseline.singular = m_sweep.singularAngles.size();
    if (const auto f = asFourBar(m_start.mechanism)) {
      m_baseline.grashof = classifyGrashof(f->lengths).category;
      m_baseline.branch = f->branch;
      if (*m_baseline.grashof == GrashofClass::ChangePoint)
        return invalid("design",
                       "the four-bar is a change-point linkage (S + L = P + Q): no other lengths keep that "
                       "class, so it cannot be optimised while keeping it");
    }
    auto value = measureObjective(m_start, m_request.objective, m_sweep);
    if (!value)
      return invalid("objective", "the " + objectiveName(m_request.objective) +
                                      " cannot be measured on the design (no sample where it exists)");
    return std::move(*value);
  }

  // NLopt's objective: the score of the scaled point x, kBarrier when infeasible. `opt` is the
  // run to stop on a cancel, null for a start's draw.
  double score(const double* x, nlopt_opt opt) {
    if (m_cancel != nullptr && m_cancel->load(std::memory_order_relaxed)) {
      m_cancelled = true;
      if (opt != nullptr) nlopt_force_stop(opt);
      return kBarrier;
    }
    const std::vector<double> values = unscale(x);
    const Measured m = measure(designAt(values));
    ++m_evaluations;
    if (m_request.options.recordEvaluations) m_evaluated.push_back(values);
    if (m_progress) m_progress(m_evaluations, m_request.options.evaluations);
    if (!m.feasible) return kBarrier;
    ++m_feasible;
    const double s = maximised(m_request.objective.kind) ? -m.objective.value : m.objective.value;
    if (s < m_bestScore) {
      m_bestScore = s;
      m_best = values;
    }
    return s;
  }

  // One Nelder–Mead run from the scaled point x, with `budget` measurements at most.
  void run(std::vector<double> x, int budget) {
    const unsigned n = static_cast<unsigned>(m_free.size());
    nlopt_opt opt = nlopt_create(NLOPT_LN_NELDERMEAD, n);
    const std::vector<double> lo(n, 0.0), hi(n, 1.0), step(n, kInitialStep);
    nlopt_set_lower_bounds(opt, lo.data());
    nlopt_set_upper_bounds(opt, hi.data());
    nlopt_set_initial_step(opt, step.data());
    nlopt_set_xtol_abs1(opt, kStepTolerance);
    nlopt_set_maxeval(opt, budget);
    struct Call {
      Search* search;
      nlopt_opt opt;
    } call{this, opt};
    nlopt_set_min_objective(
        opt,
        [](unsigned, const double* p, double*, void* data) {
          auto* c = static_cast<Call*>(data);
          return c->search->score(p, c->opt);
        },
        &call);
    double f = 0.0;
    nlopt_optimize(opt, x.data(), &f);
    nlopt_destroy(opt);
  }

  // A scaled start for run k ≥ 1: a feasible uniform draw, else a draw about the best so far.
  std::vector<double> draw(std::mt19937& random, int& budget) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const std::vector<double> best = scale(m_best);
    for (int tries = 0; tries < 2 * kStartDraws && budget > 0 && !stopped(); ++tries) {
      std::vector<double> x(m_free.size());
      for (std::size_t i = 0; i < x.size(); ++i)
        x[i] = tries < kStartDraws ? unit(random) : std::clamp(best[i] + 0.2 * (unit(random) - 0.5), 0.0, 1.0);
      --budget;
      if (score(x.data(), nullptr) < kBarrier) return x;
    }
    return best;
  }

  bool stopped() const { return m_cancelled || (m_cancel != nullptr && m_cancel->load(std::memory_order_relaxed)); }

  void setStart(double score) {
    m_best = startValues();
    m_bestScore = score;
  }

  const std::vector<double>& best() const { return m_best; }
  int evaluations() const { return m_evaluations; }
  int feasible() const { return m_feasible; }
  bool cancelled() const { return stopped(); }
  std::vector<std::vector<double>> takeEvaluated() { return std::move(m_evaluated); }

private:
  const Design& m_start;
  const OptimiseRequest& m_request;
  std::vector<OptimiseDimension> m_dims;
  const std::atomic<bool>* m_cancel;
  const OptimiseProgress& m_progress;
  SweepSpec m_spec;
  std::vector<std::size_t> m_free;
  SweepResult m_sweep;
  Baseline m_baseline;
  std::vector<double> m_best;
  double m_bestScore = std::numeric_limits<double>::infinity();
  int m_evaluations = 0;
  int m_feasible = 0;
  bool m_cancelled = false;
  std::vector<std::vector<double>> m_evaluated;
};

std::optional<Error> checkOptions(const OptimiseOptions& o) {
  if (o.evaluations < kMinOptimiseEvaluations || o.evaluations > kMaxOptimiseEvaluations)
    return invalid("evaluations", "evaluations must be between " + std::to_string(kMinOptimiseEvaluations) + " and " +
                                      std::to_string(kMaxOptimiseEvaluations) + " (got " +
                                      std::to_string(o.evaluations) + ")");
  if (o.starts < kMinOptimiseStarts || o.starts > kMaxOptimiseStarts)
    return invalid("starts", "starts must be between " + std::to_string(kMinOptimiseStarts) + " and " +
                                 std::to_string(kMaxOptimiseStarts) + " (got " + std::to_string(o.starts) + ")");
  return std::nullopt;
}

// A constant α (the driven crank's at a steady speed) leaves nothing to optimise.
std::optional<Error> checkVaries(const OptimiseObjective& o, const ObjectiveValue& start) {
  if (o.kind != ObjectiveKind::PeakAlpha) return std::nullopt;
  const auto [lo, hi] = std::minmax_element(start.curve.y.begin(), start.curve.y.end());
  if (*hi - *lo > 1e-12 * std::max(1.0, start.value)) return std::nullopt;
  return invalid("objective.link", "objective.link: the α of '" + o.link +
                                       "' is the same at every sample (the driver sets it): no dimension changes it");
}

OptimiseConstraintState stateOf(const Design& start, const Design& result, const std::vector<OptimiseDimension>& dims,
                                const std::vector<double>& values) {
  OptimiseConstraintState s;
  const auto before = asFourBar(start.mechanism), after = asFourBar(result.mechanism);
  if (before) s.grashofBefore = classifyGrashof(before->lengths).category;
  if (after) s.grashofAfter = classifyGrashof(after->lengths).category;
  s.branchKept = !before || (after && after->branch == before->branch);
  for (std::size_t d = 0; d < dims.size(); ++d) {
    if (values[d] < dims[d].lo || values[d] > dims[d].hi) s.withinRanges = false;
    if (dims[d].fixed && values[d] != dims[d].dimension.value) s.pivotsKept = false;
  }
  // A fixed pivot is where it was to the bit: none of its numbers is offset.
  for (const OptimiseDimension& d : dims) {
    const std::size_t p = d.dimension.parameter.point.index;
    if (d.fixed && start.mechanism.points[p].definition != result.mechanism.points[p].definition) s.pivotsKept = false;
  }
  return s;
}

}  // namespace

Result<LinkageOptimisation> optimiseLinkage(const Design& design, const OptimiseRequest& request,
                                            const std::atomic<bool>* cancel, const OptimiseProgress& progress) {
  if (auto e = checkDesign(design)) return *e;
  if (design.samples > kMaxOptimiseSamples)
    return invalid("samples", "optimise sweeps every candidate over the design's grid, which may hold at most " +
                                  std::to_string(kMaxOptimiseSamples) + " samples (got " +
                                  std::to_string(design.samples) + "): give the design a coarser grid");
  if (auto e = checkOptions(request.options)) return *e;
  if (auto e = checkObjective(design, request.objective)) return *e;
  auto dims = optimiseDimensions(design.mechanism, request.constraints);
  if (!dims) return dims.error();

  Search search(design, request, std::move(dims).value(), cancel, progress);
  auto start = search.measureStart();
  if (!start) return start.error();
  if (auto e = checkVaries(request.objective, *start)) return *e;
  const double startScore = maximised(request.objective.kind) ? -start->value : start->value;
  search.setStart(startScore);

  nlopt_srand(request.options.seed);
  std::mt19937 random(request.options.seed);
  LinkageOptimisation out;
  int budget = request.options.evaluations;
  for (int k = 0; k < request.options.starts && budget > 0 && !search.cancelled(); ++k) {
    std::vector<double> x = k == 0 ? search.scale(search.startValues()) : search.draw(random, budget);
    if (budget <= 0 || search.cancelled()) break;
    ++out.startsRun;
    search.run(std::move(x), std::max(1, budget / (request.options.starts - k)));
    budget = request.options.evaluations - search.evaluations();
  }

  out.dimensions = search.dimensions();
  out.values = search.best();
  out.design = search.designAt(out.values);
  out.objective = request.objective;
  out.before = start->value;
  out.curveBefore = start->curve;
  const Measured after = search.measure(out.design);
  const bool better = after.feasible && (maximised(request.objective.kind) ? after.objective.value > start->value
                                                                           : after.objective.value < start->value);
  if (!better) {
    out.values = search.startValues();
    out.design = design;
  }
  out.improved = better;
  out.after = better ? after.objective.value : start->value;
  out.curveAfter = better ? after.objective.curve : start->curve;
  out.constraints = stateOf(design, out.design, out.dimensions, out.values);
  out.evaluations = search.evaluations();
  out.feasibleEvaluations = search.feasible();
  out.cancelled = search.cancelled();
  out.evaluated = search.takeEvaluated();
  return out;
}

}  // namespace linkwright::kinematics
