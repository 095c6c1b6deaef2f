#include "tools/residual/base_identification.hpp"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <limits>

#include "tools/residual/joint_refinement.hpp"
#include "tools/residual/least_squares_refine.hpp"
#include "tools/text_format.hpp"

namespace mrd::tools::search {

namespace {

// Nelder-Mead from `from`, restarted from its best while that still pays: a simplex in eight
// coordinates collapses along the ridges that the material's shape and the yield law share.
FittedModel refine_with_restarts(Search& s, const ParameterSpace& space, const FitSeries& series, const Point& from) {
  const auto dimension = static_cast<int>(space.bounds.dimension());
  FittedModel best = refine_space(space, series, from, 20 + 30 * dimension, 0.05);
  s.evaluations += best.evaluations;
  for (int restart = 0; restart < 2; ++restart) {
    const FittedModel again = refine_space(space, series, best.theta, 20 + 30 * dimension, 0.05);
    s.evaluations += again.evaluations;
    const bool paid = again.fitting_rms < (1.0 - 1e-3) * best.fitting_rms;
    if (again.fitting_rms < best.fitting_rms) best = again;
    if (!paid) break;
  }
  return best;
}

// The effects of `model` whose parameters enter the force linearly: refitted among the linear
// terms while the base moves.
LinearEffects linear_effects_of(const model::DamperModel& model) {
  LinearEffects out;
  for (const model::EffectInfo& e : model::effect_infos()) {
    if (!e.linear.empty() && e.enabled(model.effects)) out.push_back(&e);
  }
  return out;
}

}  // namespace

namespace {

// The swarms on the runs' openings, a Levenberg-Marquardt chain from each swarm's best and from
// each of `chain_starts`, side by side, then the best polished on the whole fitting series;
// each step reported as a share of the whole.
FittedModel search_base_space(Search& s, const ParameterSpace& space, std::vector<Point> chain_starts, int swarms) {
  const FitSeries& openings = s.swarm_series;
  ParameterSpace exploring = space;
  exploring.origin.integration.max_substeps = std::min(exploring.origin.integration.max_substeps, kExploringSubsteps);
  swarms = std::max(swarms, 1);
  const bool on_openings = openings.size() != s.fit_series.size();
  const auto steps = static_cast<std::int64_t>(2 * swarms + static_cast<int>(chain_starts.size()) + (on_openings ? 1 : 0));
  std::atomic<std::int64_t> done{0};
  std::atomic<double> best_so_far{std::numeric_limits<double>::infinity()};
  const auto report = [&](double fitting_rms) {
    if (s.options.progress == nullptr) return;
    double seen = best_so_far.load();
    while (fitting_rms < seen && !best_so_far.compare_exchange_weak(seen, fitting_rms)) {
    }
    s.options.progress->report({.stage = "base fit", .done = ++done, .total = steps, .best_error = best_so_far.load(),
                                .unit = "N RMS (fitting)"});
  };
  std::vector<Point> starts;
  for (int k = 0; k < swarms; ++k) {
    const FittedModel swarm = fit_space(exploring, openings, &s.pool, s.seed++, 2 * s.options.evaluations_per_parameter);
    s.evaluations += swarm.evaluations;
    starts.push_back(swarm.theta);
    report(swarm.fitting_rms);
  }
  for (Point& p : chain_starts) starts.push_back(std::move(p));
  std::vector<FittedModel> refined(starts.size());
  const auto dimension = static_cast<int>(space.bounds.dimension());
  s.pool.run(starts.size(), [&](std::size_t k, unsigned /*worker*/) {
    refined[k] = refine_least_squares(space, openings, starts[k], 20 + 30 * dimension);
    s.evaluations += refined[k].evaluations;
    report(refined[k].fitting_rms);
  });
  FittedModel best = *std::ranges::min_element(refined, {}, &FittedModel::fitting_rms);
  if (!on_openings) return best;
  const FittedModel whole = refine_least_squares(space, s.fit_series, best.theta, 20 + 15 * dimension, &s.pool);
  s.evaluations += whole.evaluations;
  report(whole.fitting_rms);
  return whole;
}

}  // namespace

FittedModel identify_base(Search& s, const model::DamperModel& origin, ParameterSpace& space, bool from_origin,
                          int swarms, std::span<const Point> also_from) {
  space = base_space(origin, s.options.start, s.scales, Magnetics::kMaterial);
  space.linear = linear_effects_of(origin);
  std::vector<Point> chain_starts;
  if (from_origin) chain_starts.push_back(base_coordinates(origin, s.options.start, s.scales, Magnetics::kMaterial));
  chain_starts.insert(chain_starts.end(), also_from.begin(), also_from.end());
  return search_base_space(s, space, std::move(chain_starts), swarms);
}

FittedModel identify_base_with(Search& s, const model::DamperModel& origin, const Effects& effects, int swarms) {
  ParameterSpace joint = base_space(origin, s.options.start, s.scales, Magnetics::kMaterial);
  joint.linear = linear_effects_of(origin);
  for (const model::EffectInfo* e : effects) joint = combine(joint, effect_space(*e, origin, s.scales));
  const Point base_start = base_coordinates(origin, s.options.start, s.scales, Magnetics::kMaterial);
  const Point effect_start = effect_coordinates(effects, origin, s.scales);
  Point from(base_start.size() + effect_start.size());
  from << base_start, effect_start;
  // A second chain from the config's damper (the prior) with the effects as fitted: the basin the
  // first base fit left may be the one the effects needed.
  const Point prior_start = base_coordinates(s.options.start, s.options.start, s.scales, Magnetics::kMaterial);
  Point from_prior(prior_start.size() + effect_start.size());
  from_prior << prior_start, effect_start;
  return search_base_space(s, joint, {from, from_prior}, swarms);
}

FittedModel identify_base_with(Search& s, const model::DamperModel& origin, const model::EffectInfo& effect, int swarms) {
  return identify_base_with(s, origin, Effects{&effect}, swarms);
}

FittedModel identify_base_twice_if_short(Search& s, const model::DamperModel& origin, ParameterSpace& space,
                                         int swarms) {
  FittedModel first = identify_base(s, origin, space, true, swarms);
  if (!(first.fitting_rms > kSecondStartRatio * s.white_noise_of(s.predicted(first.model)))) return first;
  ParameterSpace again;
  FittedModel second = identify_base(s, origin, again, false, kSecondStartSwarms);
  if (!(second.fitting_rms < first.fitting_rms)) return first;
  space = std::move(again);
  return second;
}

FittedModel fit_base_model(Search& s, ParameterSpace& space) {
  return identify_base_twice_if_short(s, s.options.start, space, 2);
}

FittedModel refit_robustly(Search& s, ParameterSpace& space, FittedModel base, int& refits) {
  const RobustLoss& loss = s.options.robust;
  if (!s.options.robust_fit || !(loss.tuning > 0.0)) return base;
  const auto sigma_of = [&](const model::DamperModel& m) {
    std::vector<double> force;
    predict_force(m, s.fit_series, force);
    return huber_weights(s.fit_series, force, loss);
  };
  const auto set_loss = [&](FitLoss::Kind kind, double sigma) {
    s.fit_series.loss = s.swarm_series.loss = FitLoss{kind, loss.tuning * sigma};
  };
  const RobustWeights least_squares = sigma_of(base.model);
  if (least_squares.down_weighted_share < loss.refit_share) return base;
  set_loss(FitLoss::Kind::kCauchy, least_squares.sigma);
  base = identify_base(s, s.options.start, space, true, 2, std::span<const Point>(&base.theta, 1));
  const double sigma = sigma_of(base.model).sigma;
  set_loss(FitLoss::Kind::kCauchy, sigma);
  base = refine_with_restarts(s, space, s.fit_series, base.theta);
  set_loss(FitLoss::Kind::kHuber, sigma_of(base.model).sigma);
  refits = 1;
  return base;
}

FittedModel refit_on_every_sample(Search& s, const model::DamperModel& origin, const model::DamperModel& model) {
  FitSeries every = s.fit_series;
  for (SampleRole& role : every.role)
    if (role == SampleRole::kValidation) role = SampleRole::kFitting;
  ParameterSpace space = base_space(origin, s.options.start, s.scales, Magnetics::kMaterial);
  space.linear = linear_effects_of(origin);
  const Point from = base_coordinates(model, s.options.start, s.scales, Magnetics::kMaterial);
  const auto dimension = static_cast<int>(space.bounds.dimension());
  FittedModel refit = refine_least_squares(space, every, from, 20 + 15 * dimension, &s.pool);
  s.evaluations += refit.evaluations;
  std::vector<double> force;
  predict_force(model, every, force);
  if (!(refit.fitting_rms < residual_rms(every, force).fitting)) {
    refit.model = model;
    refit.fitting_rms = residual_rms(every, force).fitting;
  }
  return refit;
}

std::vector<std::string> describe_base(const ParameterSpace& space, const FittedModel& fit,
                                       const model::DamperModel& start, const SeriesScales& scales) {
  std::vector<std::string> lines;
  const model::DamperModel& m = fit.model;
  const model::BinghamDamper damper = fluid_of(m);
  lines.push_back(format("force scale %.4g of the starting damper (pole length %.4g m)",
                         fit.linear.force_scale, m.geometry.pole_length));
  lines.push_back(format("viscous coefficient c0 %.4g N s/m (viscosity %.4g Pa s), flow index n %.3g",
                         damper.viscous_coefficient(), m.fluid.viscosity, m.fluid.flow_index));
  lines.push_back(format("seal friction %.4g N", m.geometry.seal_friction));
  lines.push_back(format("sign velocity v_s %.4g m/s, sign shape %.3g (-1 atan, 0 tanh, 1 knee)",
                         m.geometry.sign_velocity_scale, m.geometry.sign_shape));
  const bool gain = std::ranges::find(space.parameters, std::string("log10 field gain [turns/m]")) != space.parameters.end();
  const bool material = std::ranges::find(space.parameters, std::string("J-A c")) != space.parameters.end();
  if (gain) {
    lines.push_back(format("field gain %.4g turns/m (%.4g x the starting coil's), yield exponent of B %.4g, "
                           "yield saturation B_s %.3g T (shape %.3g)",
                           m.circuit.turns / m.circuit.effective_length, m.circuit.turns / start.circuit.turns,
                           m.fluid.field_exponent, m.fluid.saturation_induction, m.fluid.saturation_shape));
  } else {
    lines.push_back("field gain, J-A material and yield exponent kept: the current does not vary, so they cannot be identified");
  }
  if (material) {
    const model::JilesAthertonParams& ja = m.jiles_atherton;
    lines.push_back(format("J-A material: k %.4g A/m, c %.3g, alpha %.4g (alpha Ms/3a %.3g); a %.4g A/m and Ms %.4g A/m "
                           "kept from the start (a force record fixes only H/a and the force scale)",
                           ja.k, ja.c, ja.alpha, ja.mean_field_gain(), ja.a, ja.Ms));
    if (!(start.jiles_atherton == model::JilesAthertonParams{}))
      lines.push_back(format("the config's J-A material (a prior): k %.4g A/m, c %.3g, alpha %.4g",
                             start.jiles_atherton.k, start.jiles_atherton.c, start.jiles_atherton.alpha));
  }
  for (std::string& edge : base_coordinates_at_edge(m, start, scales, Magnetics::kMaterial)) lines.push_back(std::move(edge));
  return lines;
}

}  // namespace mrd::tools::search
