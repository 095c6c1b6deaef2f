#include "tools/residual/model_fit.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numeric>

#include "model/observer.hpp"
#include "model/typical_ranges.hpp"
#include "tools/optimisation/particle_swarm.hpp"

namespace mrd::tools {

namespace {

// Sample i of the series as the observer takes it: on a run kept at its recorded times, each
// step is the sample's own interval (the run's first a period).
struct SampleMeasurement {
  const FitSeries& series;
  std::size_t from;     // the run's first sample
  double period;        // [s]
  bool recorded_times;  // the run's timing is record::RunTiming::kRecorded

  [[nodiscard]] model::Measurement operator()(std::size_t i) const {
    model::Measurement m{.displacement = series.displacement[i], .velocity = series.velocity[i],
                         .coil_current = series.current[i]};
    if (recorded_times) m.step_duration = i == from ? period : series.time[i] - series.time[i - 1];
    return m;
  }
};

// One observer per run, from a demagnetised core, fed each sample; `step` returns the estimate.
template <typename Step>
void run_observer(const model::DamperModel& model, const FitSeries& series, Step step) {
  const bool with_temperature = !series.temperature.empty();
  model::ObserverSettings settings;
  for (std::size_t r = 0; r < series.run_starts.size(); ++r) {
    settings.sample_period = series.run_periods[r];
    const std::size_t from = series.run_starts[r];
    const std::size_t to = r + 1 < series.run_starts.size() ? series.run_starts[r + 1] : series.size();
    const SampleMeasurement sample{.series = series, .from = from, .period = settings.sample_period,
                                  .recorded_times = series.timing_of_run(r) == record::RunTiming::kRecorded};
    model::Observer observer(model, settings);
    for (std::size_t i = from; i < to; ++i) {
      if (with_temperature) observer.set_measured_temperature(series.temperature[i]);
      step(observer, sample(i), i);
    }
  }
}

}  // namespace

InductionTrace::InductionTrace(const model::DamperModel& model, const FitSeries& series)
    : magnetics_(model), B_(series.size()) {
  run_observer(model, series, [&](model::Observer& o, const model::Measurement& m, std::size_t i) { B_[i] = o.step(m).B; });
}

bool InductionTrace::serves(const model::DamperModel& m) const {
  return m.jiles_atherton == magnetics_.jiles_atherton && m.circuit == magnetics_.circuit &&
         m.integration == magnetics_.integration &&
         std::ranges::all_of(model::effect_infos(), [&](const model::EffectInfo& e) {
           return !e.changes_induction || e.same(m.effects, magnetics_.effects);
         });
}

void predict_force(const model::DamperModel& model, const FitSeries& series,
                   std::vector<double>& force, const InductionTrace* trace) {
  force.resize(series.size());
  if (trace != nullptr && trace->induction().size() == series.size() && trace->serves(model)) {
    const std::vector<double>& B = trace->induction();
    run_observer(model, series, [&](model::Observer& o, const model::Measurement& m, std::size_t i) {
      force[i] = o.step_at_induction(m, B[i]).force;
    });
    return;
  }
  run_observer(model, series,
               [&](model::Observer& o, const model::Measurement& m, std::size_t i) { force[i] = o.step(m).force; });
}

void predict_force_and_induction(const model::DamperModel& model, const FitSeries& series,
                                 std::vector<double>& force, std::vector<double>& B) {
  force.resize(series.size());
  B.resize(series.size());
  run_observer(model, series, [&](model::Observer& o, const model::Measurement& m, std::size_t i) {
    const model::ObserverEstimate e = o.step(m);
    force[i] = e.force;
    B[i] = e.B;
  });
}

ResidualRms residual_rms(const FitSeries& series, const std::vector<double>& predicted) {
  double sum[2] = {0.0, 0.0};
  double weight[2] = {0.0, 0.0};
  ResidualRms out;
  for (std::size_t i = 0; i < series.size(); ++i) {
    if (series.role[i] == SampleRole::kExcluded) continue;
    const double r = series.force[i] - predicted[i];
    sum[static_cast<std::size_t>(series.role[i])] += series.loss.rho(r);
    weight[static_cast<std::size_t>(series.role[i])] += 1.0;
    out.max = std::max(out.max, std::fabs(r));
  }
  const auto rms = [](double s, double w) { return w > 0.0 ? std::sqrt(s / w) : 0.0; };
  out.fitting = rms(sum[0], weight[0]);
  out.validation = rms(sum[1], weight[1]);
  out.all = rms(sum[0] + sum[1], weight[0] + weight[1]);
  return out;
}

namespace {

// At most the base's three columns and the effects'.
constexpr int kMaxLinearColumns = 9;
using NormalMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxLinearColumns, kMaxLinearColumns>;
using NormalVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxLinearColumns, 1>;

// The base columns: F_m, the viscous shape and, with shapes and a friction column, the sign term.
struct BaseColumns {
  const std::optional<model::BinghamDamper>& shapes;
  bool friction;
  [[nodiscard]] bool has_friction() const { return shapes && friction; }
};

int base_column_count(const BaseColumns& base) { return base.has_friction() ? 3 : 2; }


int column_count(const LinearEffects& effects, const BaseColumns& base) {
  int n = base_column_count(base);
  for (const model::EffectInfo* e : effects) n += static_cast<int>(e->linear.size());
  return n;
}

// Columns of the linear fit at sample i.
void fill_columns(const FitSeries& s, const std::vector<double>& predicted, const LinearEffects& effects,
                  const BaseColumns& base, std::size_t i, double* column) {
  const std::optional<model::BinghamDamper>& shapes = base.shapes;
  column[0] = predicted[i];
  int c = 1;
  if (shapes) {
    const double c0 = shapes->viscous_coefficient();
    column[c++] = c0 > 0.0 ? shapes->viscous_force(s.velocity[i]) / c0 : s.velocity[i];
    if (base.friction) column[c++] = shapes->sign_term(s.velocity[i]);
  } else {
    column[c++] = s.velocity[i];
  }
  for (const model::EffectInfo* e : effects) {
    for (const model::LinearColumn kind : e->linear) {
      column[c++] = kind == model::LinearColumn::kConstant ? 1.0 : s.displacement[i];
    }
  }
}

}  // namespace

namespace {

// A coefficient c_j whose parameter a v_j + c_j must stay >= 0 (v_j its present value, scaled
// by the force scale a as apply_linear_terms does).
struct NonNegative {
  int column;
  double present;
};

std::vector<NonNegative> non_negative_columns(const LinearEffects& effects, const model::DamperModel* present,
                                             const BaseColumns& base) {
  const std::optional<model::BinghamDamper>& shapes = base.shapes;
  std::vector<NonNegative> out;
  if (present == nullptr) return out;
  if (shapes) {
    out.push_back({1, shapes->viscous_coefficient()});
    if (base.friction) out.push_back({2, shapes->seal_friction()});
  }
  int c = base_column_count(base);
  for (const model::EffectInfo* e : effects) {
    double values[kMaxLinearColumns] = {};
    e->linear_values(present->effects, std::span<double>(values, e->linear.size()));
    for (std::size_t k = 0; k < e->linear.size(); ++k, ++c) {
      if (!e->linear_non_negative.empty() && e->linear_non_negative[k]) out.push_back({c, values[k]});
    }
  }
  return out;
}

// Least squares with the columns in `held` tied to the force scale (c_j = -v_j a): theta = M
// theta', M the identity less the held columns, which take -v_j in the force scale's column.
NormalVector solve_holding(const NormalMatrix& normal, const NormalVector& rhs, const std::vector<NonNegative>& held) {
  const int n = static_cast<int>(normal.rows());
  const int free = n - static_cast<int>(held.size());
  NormalMatrix m = NormalMatrix::Zero(n, free);
  int f = 0;
  for (int r = 0; r < n; ++r) {
    const auto tied = std::ranges::find(held, r, &NonNegative::column);
    if (tied != held.end()) {
      m(r, 0) = -tied->present;
    } else {
      m(r, f++) = 1.0;
    }
  }
  NormalMatrix reduced = m.transpose() * normal * m;
  for (int r = 0; r < free; ++r) reduced(r, r) += 1e-12 * (reduced(r, r) + 1.0);
  const NormalVector theta = reduced.ldlt().solve(NormalVector(m.transpose() * rhs));
  return m * theta;
}

}  // namespace

namespace {

// fit_linear_terms with `weights` per sample (empty: every sample 1).
LinearTerms solve_linear_terms(const FitSeries& series, const std::vector<double>& predicted,
                               const LinearEffects& effects, const model::DamperModel* present,
                               const std::vector<double>& weights) {
  std::optional<model::BinghamDamper> shapes;
  if (present != nullptr) shapes.emplace(present->geometry, present->fluid.viscosity, present->fluid.flow_index);
  // At a constant current the model's force is (yield + friction) s(v) + c0 u(v): the force
  // scale and a friction column would be one direction, split by the ridge and not the data.
  const BaseColumns base{shapes, current_varies(series)};
  const int n = column_count(effects, base);
  NormalMatrix normal = NormalMatrix::Zero(n, n);
  NormalVector rhs = NormalVector::Zero(n);
  double column[kMaxLinearColumns];
  for (std::size_t i = 0; i < series.size(); ++i) {
    if (series.role[i] != SampleRole::kFitting) continue;
    fill_columns(series, predicted, effects, base, i, column);
    const double w = weights.empty() ? 1.0 : weights[i];
    for (int r = 0; r < n; ++r) {
      rhs[r] += w * column[r] * series.force[i];
      for (int c = 0; c < n; ++c) normal(r, c) += w * column[r] * column[c];
    }
  }
  // A light ridge keeps the solve defined when a column is all zero (no force predicted at all).
  const std::vector<NonNegative> signed_columns = non_negative_columns(effects, present, base);
  std::vector<NonNegative> held;
  NormalVector solution = solve_holding(normal, rhs, held);
  // Active set: hold each parameter that the solve drives negative, until none is.
  for (std::size_t pass = 0; pass < signed_columns.size(); ++pass) {
    bool more = false;
    for (const NonNegative& s : signed_columns) {
      const bool is_held = std::ranges::find(held, s.column, &NonNegative::column) != held.end();
      if (!is_held && std::max(solution[0], 0.0) * s.present + solution[s.column] < 0.0) {
        held.push_back(s);
        more = true;
      }
    }
    if (!more) break;
    solution = solve_holding(normal, rhs, held);
  }
  LinearTerms t;
  t.force_scale = std::max(solution[0], 0.0);
  t.extra_viscous = solution[1];
  const int first = base_column_count(base);
  if (base.has_friction()) t.extra_friction = solution[2];
  t.friction_column = base.friction;
  t.effects = effects;
  t.coefficients.assign(solution.data() + first, solution.data() + n);
  t.shapes = shapes;
  return t;
}

}  // namespace

LinearTerms fit_linear_terms(const FitSeries& series, const std::vector<double>& predicted,
                             const LinearEffects& effects, const model::DamperModel* present) {
  return solve_linear_terms(series, predicted, effects, present, {});
}

namespace {

// Calls visit(i, F_fit - (a F_m + ...)) for each fitting sample i of the series.
template <class Visit>
void for_each_linear_residual(const FitSeries& series, const std::vector<double>& predicted, const LinearTerms& t,
                              Visit visit) {
  const BaseColumns base{t.shapes, t.friction_column};
  const int n = column_count(t.effects, base);
  double coefficients[kMaxLinearColumns] = {t.force_scale, t.extra_viscous, t.extra_friction};
  std::copy(t.coefficients.begin(), t.coefficients.end(), coefficients + base_column_count(base));
  for (std::size_t i = 0; i < series.size(); ++i) {
    if (series.role[i] != SampleRole::kFitting) continue;
    double column[kMaxLinearColumns];
    fill_columns(series, predicted, t.effects, base, i, column);
    double f = 0.0;
    for (int c = 0; c < n; ++c) f += coefficients[c] * column[c];
    visit(i, series.force[i] - f);
  }
}

}  // namespace

double linear_fit_rms(const FitSeries& series, const std::vector<double>& predicted,
                      const LinearTerms& t) {
  double sum = 0.0;
  double count = 0.0;
  for_each_linear_residual(series, predicted, t, [&](std::size_t, double r) {
    sum += series.loss.rho(r);
    count += 1.0;
  });
  return count > 0.0 ? std::sqrt(sum / count) : 0.0;
}

model::DamperModel apply_linear_terms(model::DamperModel m, const LinearTerms& t) {
  const double a = std::max(t.force_scale, 1e-9);
  const model::BinghamDamper before(m.geometry, m.fluid.viscosity);
  const double c0 = before.viscous_coefficient();
  m.geometry.pole_length *= a;
  // c0 is proportional to the viscosity at fixed geometry. A solve that holds c0 at 0 leaves the
  // viscosity at the least a fluid has (model/typical_ranges.hpp), not a share of the last one:
  // applied again and again, a share ran Dyke's and a bump stop's fits to 1e-108 Pa s.
  const double per_viscosity = model::BinghamDamper(m.geometry, 1.0).viscous_coefficient();  // c0 at 1 Pa s
  const double target = std::max(a * c0 + t.extra_viscous, model::kTypicalViscosity.lo * per_viscosity);
  m.fluid.viscosity = target / per_viscosity;
  m.geometry.seal_friction = std::max(a * m.geometry.seal_friction + t.extra_friction, 0.0);
  for (const model::EffectInfo& e : model::effect_infos()) e.scale_force(m.effects, a);
  std::size_t c = 0;
  for (const model::EffectInfo* e : t.effects) {
    e->add_linear(m.effects, std::span<const double>(t.coefficients).subspan(c, e->linear.size()));
    c += e->linear.size();
  }
  return m;
}

namespace {

// Reweighted solves of the linear terms under the robust loss, from the least-squares terms.
constexpr int kRobustSolves = 4;

struct TrialFit {
  LinearTerms terms;
  double fitness = 0.0;  // [N]
};

// The linear terms at one trial point and the fitness they leave, sqrt(mean rho(r)) of the
// series' loss: by least squares, or under a robust loss by reweighted solves from the
// least-squares terms.
TrialFit fit_trial(const FitSeries& series, const std::vector<double>& predicted, const LinearEffects& effects,
                   const model::DamperModel& present) {
  TrialFit out{fit_linear_terms(series, predicted, effects, &present), 0.0};
  if (!series.loss.squares()) {
    std::vector<double> weight(series.size(), 1.0);
    for (int pass = 0; pass < kRobustSolves; ++pass) {
      for_each_linear_residual(series, predicted, out.terms,
                               [&](std::size_t i, double r) { weight[i] = series.loss.weight(r); });
      out.terms = solve_linear_terms(series, predicted, effects, &present, weight);
    }
  }
  out.fitness = linear_fit_rms(series, predicted, out.terms);
  return out;
}

double fitness_at(const ParameterSpace& space, const FitSeries& series, const Point& theta,
                  std::vector<double>& buffer) {
  const model::DamperModel model = space.build(theta);
  if (!model::validate(model).ok()) return 1e300;
  predict_force(model, series, buffer, space.induction.get());
  const double fitness = fit_trial(series, buffer, space.linear, model).fitness;
  return std::isfinite(fitness) ? fitness : 1e300;
}

// The swarm's objective: points in parallel on the pool (or serially), one buffer per worker.
class SpaceObjective final : public BatchObjective {
 public:
  SpaceObjective(const ParameterSpace& space, const FitSeries& series, WorkerPool* pool)
      : space_(space), series_(series), pool_(pool), buffers_(pool != nullptr ? pool->size() : 1) {}

  void evaluate(const std::vector<Point>& points, std::vector<double>& fitness,
                const std::vector<double>* /*cutoffs*/) override {
    fitness.resize(points.size());
    if (pool_ == nullptr) {
      for (std::size_t i = 0; i < points.size(); ++i) fitness[i] = fitness_at(space_, series_, points[i], buffers_[0]);
      return;
    }
    pool_->run(points.size(), [&](std::size_t i, unsigned worker) {
      fitness[i] = fitness_at(space_, series_, points[i], buffers_[worker]);
    });
  }

 private:
  const ParameterSpace& space_;
  const FitSeries& series_;
  WorkerPool* pool_;
  std::vector<std::vector<double>> buffers_;
};

}  // namespace

FittedModel fitted_at(const ParameterSpace& space, const FitSeries& series, const Point& theta,
                      std::int64_t evaluations) {
  FittedModel out;
  out.theta = theta;
  out.evaluations = evaluations;
  std::vector<double> force;
  const model::DamperModel model = space.build(theta);
  predict_force(model, series, force, space.induction.get());
  TrialFit trial = fit_trial(series, force, space.linear, model);
  out.linear = std::move(trial.terms);
  out.fitting_rms = trial.fitness;
  out.model = apply_linear_terms(model, out.linear);
  return out;
}


double space_fitness(const ParameterSpace& space, const FitSeries& series, const Point& p,
                     std::vector<double>& buffer) {
  return fitness_at(space, series, p, buffer);
}

bool space_residuals(const ParameterSpace& space, const FitSeries& series, const Point& p, std::vector<double>& buffer,
                     std::vector<double>& residuals) {
  const model::DamperModel model = space.build(p);
  if (!model::validate(model).ok()) return false;
  predict_force(model, series, buffer, space.induction.get());
  const TrialFit trial = fit_trial(series, buffer, space.linear, model);
  if (!std::isfinite(trial.fitness)) return false;
  residuals.clear();
  for_each_linear_residual(series, buffer, trial.terms, [&](std::size_t, double r) {
    residuals.push_back(std::copysign(std::sqrt(series.loss.rho(r)), r));
  });
  return true;
}

FittedModel best_of(const ParameterSpace& space, const FitSeries& series, const std::vector<Point>& points) {
  std::vector<double> buffer;
  std::size_t best = 0;
  double best_fitness = 1e301;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double f = fitness_at(space, series, points[i], buffer);
    if (f < best_fitness) {
      best_fitness = f;
      best = i;
    }
  }
  return fitted_at(space, series, points.at(best), static_cast<std::int64_t>(points.size()) + 1);
}

ParameterSpace combine(const ParameterSpace& first, const ParameterSpace& second) {
  ParameterSpace joint;
  joint.name = first.name + "+" + second.name;
  joint.parameters = first.parameters;
  joint.parameters.insert(joint.parameters.end(), second.parameters.begin(), second.parameters.end());
  const Eigen::Index n1 = first.bounds.dimension(), n2 = second.bounds.dimension();
  joint.bounds.lower.resize(n1 + n2);
  joint.bounds.upper.resize(n1 + n2);
  joint.bounds.lower << first.bounds.lower, second.bounds.lower;
  joint.bounds.upper << first.bounds.upper, second.bounds.upper;
  joint.origin = first.origin;
  joint.edit = [e1 = first.edit, e2 = second.edit, n1, n2](model::DamperModel m, const Point& p) {
    return e2(e1(std::move(m), p.head(n1)), p.tail(n2));
  };
  joint.linear = first.linear;
  for (const model::EffectInfo* e : second.linear) {
    if (std::ranges::find(joint.linear, e) == joint.linear.end()) joint.linear.push_back(e);
  }
  return joint;
}

FittedModel fit_space(const ParameterSpace& space, const FitSeries& series, WorkerPool* pool,
                      std::uint64_t seed, int evaluations_per_parameter) {
  const auto dimension = space.bounds.dimension();
  if (dimension == 0) return fitted_at(space, series, Point(0), 1);
  SpaceObjective objective(space, series, pool);
  Budget budget;
  budget.population = static_cast<int>(std::clamp<Eigen::Index>(4 + 4 * dimension, 8, 16));
  budget.evaluations = evaluations_per_parameter * dimension;
  const OptimisationResult best = run_improved_pso(objective, space.bounds, budget, ImprovedPsoSettings{}, seed);
  return fitted_at(space, series, best.best, best.evaluations + 1);
}

FittedModel refine_space(const ParameterSpace& space, const FitSeries& series, const Point& start,
                         int max_evaluations, double step) {
  const auto n = space.bounds.dimension();
  if (n == 0) return fitted_at(space, series, Point(0), 1);
  std::vector<double> buffer;
  std::int64_t evaluations = 0;
  const auto f = [&](const Point& p) {
    ++evaluations;
    return fitness_at(space, series, p, buffer);
  };
  // Simplex: the start and one step along each coordinate (away from the nearer bound).
  std::vector<Point> x(static_cast<std::size_t>(n + 1), space.bounds.clamp(start));
  std::vector<double> fx(x.size());
  const Point range = space.bounds.upper - space.bounds.lower;
  for (Eigen::Index i = 0; i < n; ++i) {
    Point& p = x[static_cast<std::size_t>(i + 1)];
    const double h = step * range[i];
    p[i] += (p[i] + h <= space.bounds.upper[i]) ? h : -h;
  }
  for (std::size_t i = 0; i < x.size(); ++i) fx[i] = f(x[i]);
  std::vector<std::size_t> order(x.size());
  while (evaluations < max_evaluations) {
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return fx[a] < fx[b]; });
    const std::size_t best = order.front(), worst = order.back(), second = order[order.size() - 2];
    if (fx[worst] - fx[best] <= 1e-5 * std::fabs(fx[best])) break;
    Point centroid = Point::Zero(n);
    for (std::size_t i = 0; i + 1 < order.size(); ++i) centroid += x[order[i]];
    centroid /= static_cast<double>(n);
    const auto along = [&](double t) { return space.bounds.clamp(centroid + t * (x[worst] - centroid)); };
    const Point reflected = along(-1.0);
    const double fr = f(reflected);
    if (fr < fx[best]) {
      const Point expanded = along(-2.0);
      const double fe = f(expanded);
      if (fe < fr) {
        x[worst] = expanded;
        fx[worst] = fe;
      } else {
        x[worst] = reflected;
        fx[worst] = fr;
      }
    } else if (fr < fx[second]) {
      x[worst] = reflected;
      fx[worst] = fr;
    } else {
      const Point contracted = fr < fx[worst] ? along(-0.5) : along(0.5);
      const double fc = f(contracted);
      if (fc < std::min(fr, fx[worst])) {
        x[worst] = contracted;
        fx[worst] = fc;
      } else {
        for (std::size_t i = 0; i < x.size(); ++i) {
          if (i == best) continue;
          x[i] = space.bounds.clamp(x[best] + 0.5 * (x[i] - x[best]));
          fx[i] = f(x[i]);
        }
      }
    }
  }
  const auto best = static_cast<std::size_t>(std::min_element(fx.begin(), fx.end()) - fx.begin());
  return fitted_at(space, series, x[best], evaluations + 1);
}

}  // namespace mrd::tools
