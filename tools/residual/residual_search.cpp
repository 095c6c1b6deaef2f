#include "tools/residual/residual_search.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "tools/residual/candidate_effects.hpp"
#include "tools/text_format.hpp"

namespace mrd::tools {

namespace {

std::vector<double> residual_of(const FitSeries& s, const std::vector<double>& predicted) {
  std::vector<double> r(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) r[i] = s.force[i] - predicted[i];
  return r;
}

std::vector<std::string> describe_base(const ParameterSpace& space, const FittedModel& fit,
                                       const model::DamperModel& start) {
  std::vector<std::string> lines;
  const model::DamperModel& m = fit.model;
  const model::BinghamDamper damper(m.geometry, m.fluid.viscosity);
  lines.push_back(format("force scale %.4g of the starting damper (pole length %.4g m)",
                         fit.linear.force_scale, m.geometry.pole_length));
  lines.push_back(format("viscous coefficient c0 %.4g N s/m (viscosity %.4g Pa s)",
                         damper.viscous_coefficient(), m.fluid.viscosity));
  lines.push_back(format("sign velocity v_s %.4g m/s", m.geometry.sign_velocity_scale));
  if (space.bounds.dimension() == 2)
    lines.push_back(format("field gain %.4g turns/m (%.4g x the starting coil's)",
                           m.circuit.turns / m.circuit.effective_length,
                           m.circuit.turns / start.circuit.turns));
  else
    lines.push_back("field gain kept: the current does not vary, so it cannot be identified");
  return lines;
}

struct RefinePass {
  int evaluations_per_coordinate;
  double step;  // Nelder-Mead's first simplex, as a fraction of each coordinate's range
};

// Nelder-Mead over the base coordinates and those of `effects` together (an effect changes
// what the base absorbed, as a coil lag does the field gain), once per pass, each pass from the
// last one's model, so that its linear terms come close to identity and what the search saw is
// what the observer runs (the linear terms scale the viscous force past a thermal or stroke-end
// factor only approximately). The first pass starts on `origin` at `effect_start`; its theta
// holds the effects' coordinates.
FittedModel refine_jointly(const model::DamperModel& origin, const std::vector<std::string>& effects,
                           const Point& effect_start, std::initializer_list<RefinePass> passes,
                           const model::DamperModel& start, const SeriesScales& scales, const FitSeries& series,
                           std::int64_t& evaluations) {
  FittedModel fit;
  fit.model = origin;
  fit.theta = effect_start;
  for (const RefinePass& pass : passes) {
    ParameterSpace joint = base_space(fit.model, start, scales);
    for (const auto& name : effects) joint = combine(joint, effect_space(name, fit.model, scales));
    const Point base = base_coordinates(fit.model, scales);
    Point from(joint.bounds.dimension());
    from << base, fit.theta;
    const auto dimension = static_cast<int>(joint.bounds.dimension());
    fit = refine_space(joint, series, from, 10 + pass.evaluations_per_coordinate * dimension, pass.step);
    evaluations += fit.evaluations;
    fit.theta = fit.theta.tail(fit.theta.size() - base.size()).eval();
  }
  return fit;
}

// The coordinates of every effect of `names` in `model`, in that order.
Point effect_coordinates(const std::vector<std::string>& names, const model::DamperModel& model,
                         const SeriesScales& scales) {
  Point all(0);
  for (const auto& name : names) {
    const Point more = effect_coordinates(name, model, scales);
    Point both(all.size() + more.size());
    both << all, more;
    all = both;
  }
  return all;
}

}  // namespace

ResidualResult find_missing_effects(const FitSeries& full, const ResidualOptions& options) {
  const auto started = std::chrono::steady_clock::now();
  ResidualResult result;
  result.samples = full.size();
  result.notes = full.notes;
  result.decimation = decimation_factor(full, options.max_fit_samples);
  const FitSeries fit_series = decimate(full, result.decimation, options.min_fit_rate);
  result.fit_samples = fit_series.size();
  const SeriesScales scales = series_scales(fit_series);
  WorkerPool pool(options.threads);
  std::uint64_t seed = options.seed;

  // 1. The base model.
  const model::DamperModel& start = options.start;
  const ParameterSpace base_fit_space = base_space(start, start, scales);
  const FittedModel swarm = fit_space(base_fit_space, fit_series, &pool, seed++, 2 * options.evaluations_per_parameter);
  const FittedModel base = refine_space(base_fit_space, fit_series, swarm.theta, 60, 0.02);
  std::atomic<std::int64_t> evaluations = swarm.evaluations + base.evaluations;
  result.base = base.model;
  result.base_parameters = describe_base(base_fit_space, base, options.start);
  predict_force(result.base, full, result.predicted_before);
  result.before = residual_rms(full, result.predicted_before);
  result.structure_before = analyse_residual(full, residual_of(full, result.predicted_before));

  // 2-4. Greedy rounds over the candidates.
  std::vector<std::string> candidates = options.candidates;
  if (candidates.empty()) candidates.assign(model::kEffectNames.begin(), model::kEffectNames.end());
  std::erase_if(candidates, [&](const std::string& name) { return model::is_enabled(options.start.effects, name); });

  model::DamperModel current = base.model;
  std::vector<double> scratch;
  predict_force(current, fit_series, scratch);
  double current_validation = residual_rms(fit_series, scratch).validation;
  for (int round = 1; !candidates.empty(); ++round) {
    // Each candidate on its own worker: a swarm over its parameters on the round's model,
    // then Nelder-Mead over those and the base parameters together (an effect can change what
    // the base fit absorbed, as a coil lag does the field gain).
    std::vector<CandidateTrial> trials(candidates.size());
    std::vector<FittedModel> fits(candidates.size());
    const std::uint64_t round_seed = seed;
    seed += candidates.size();
    // The round model's B: every candidate but coil_lag leaves it as it is during its swarm.
    const auto round_induction = std::make_shared<const InductionTrace>(current, fit_series);
    pool.run(candidates.size(), [&](std::size_t k, unsigned /*worker*/) {
      const std::string& name = candidates[k];
      ParameterSpace effect = effect_space(name, current, scales);
      effect.induction = round_induction;
      const FittedModel alone =
          fit_space(effect, fit_series, nullptr, round_seed + k, options.evaluations_per_parameter);
      std::int64_t spent = alone.evaluations;
      FittedModel fit = alone;
      if (name == "stroke_end_air") fit = scan_stroke_threshold(effect, fit_series, scales, alone.theta, spent);
      fit = refine_jointly(current, {name}, fit.theta, {{15, 0.02}, {8, 0.02}}, options.start, scales, fit_series,
                           spent);
      std::vector<double> force;
      CandidateTrial& trial = trials[k];
      trial.effect = name;
      trial.round = round;
      trial.validation_before = current_validation;
      predict_force(fit.model, fit_series, force);
      trial.validation_rms = residual_rms(fit_series, force).validation;
      evaluations += spent;
      predict_force(fit.model, full, force);
      const ResidualRms on_full = residual_rms(full, force);
      trial.rms_after = on_full.all;
      trial.max_after = on_full.max;
      trial.parameters = effect_parameters(name, fit.model.effects);
      const double reduction = 1.0 - trial.validation_rms / std::max(current_validation, 1e-300);
      if (const auto why = implausible(name, fit, scales))
        trial.verdict = "not physical: " + *why;
      else if (reduction < options.minimum_reduction)
        trial.verdict = format("validation RMS falls %.1f%%, below the %.0f%% threshold", 100.0 * reduction,
                               100.0 * options.minimum_reduction);
      fits[k] = std::move(fit);
    });
    // The best passing candidate by validation error.
    std::size_t best = trials.size();
    for (std::size_t i = 0; i < trials.size(); ++i) {
      if (!trials[i].verdict.empty()) continue;
      if (best == trials.size() || trials[i].validation_rms < trials[best].validation_rms) best = i;
    }
    if (best < trials.size()) {
      trials[best].accepted = true;
      trials[best].verdict = format("accepted: validation RMS %.4g -> %.4g N", current_validation,
                                    trials[best].validation_rms);
      result.accepted.push_back(trials[best].effect);
      // The next round compares its candidates with this model refined to convergence, so
      // no candidate is credited with what a longer refinement of this one would have found.
      // Kept only if it validates at least as well: the polish minimises the fitting error.
      std::int64_t polish_evaluations = 0;
      const model::DamperModel& accepted = fits[best].model;
      const model::DamperModel polished =
          refine_jointly(accepted, result.accepted, effect_coordinates(result.accepted, accepted, scales),
                         {{20, 0.02}, {20, 0.005}, {20, 0.005}}, start, scales, fit_series, polish_evaluations)
              .model;
      evaluations += polish_evaluations;
      predict_force(polished, fit_series, scratch);
      const double polished_validation = residual_rms(fit_series, scratch).validation;
      current = polished_validation <= trials[best].validation_rms ? polished : accepted;
      current_validation = std::min(polished_validation, trials[best].validation_rms);
      std::erase(candidates, trials[best].effect);
    }
    for (std::size_t i = 0; i < trials.size(); ++i) {
      if (trials[i].verdict.empty())
        trials[i].verdict = format("passes, but %s lowers the validation error more", trials[best].effect.c_str());
    }
    result.trials.insert(result.trials.end(), trials.begin(), trials.end());
    if (best == trials.size()) break;
  }

  result.final_model = current;
  result.evaluations = evaluations;
  predict_force(current, full, result.predicted_after);
  result.after = residual_rms(full, result.predicted_after);
  result.structure_after = analyse_residual(full, residual_of(full, result.predicted_after));
  result.unexplained = describe(result.structure_after);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return result;
}

}  // namespace mrd::tools
