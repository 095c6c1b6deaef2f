#include "tools/residual/residual_search.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numeric>

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
  // After the pass, Nelder-Mead over the field gain alone with this many evaluations, when the
  // gain is not among the pass's coordinates (0: none).
  int gain_evaluations = 0;
};

// Nelder-Mead over the base coordinates and those of `effects` together (an effect changes
// what the base absorbed), once per pass, each pass from the last one's model, so that its
// linear terms come close to identity and what the search saw is what the observer runs (the
// linear terms scale the viscous force past a thermal or stroke-end factor only
// approximately). The first pass starts on `origin` at `effect_start`; its theta holds the
// effects' coordinates.
//
// The field gain: an effect that changes B (a coil lag) changes what the gain absorbed, so the
// gain joins its coordinates, as it does whenever the model already lags its current (the lag
// and the gain shape B together, and an effect's best fit then moves both). Other effects on a
// model without a lag leave B alone: their trials share one B trace, and the gain is refined
// on its own between passes, since such an effect can still take over force the gain had
// absorbed (on the Table 4 schedule the current follows the displacement, so a spring's k x
// looks like a field). `induction`, when given, is a B trace the first pass may already use.
FittedModel refine_jointly(const model::DamperModel& origin, const std::vector<std::string>& effects,
                           const Point& effect_start, std::initializer_list<RefinePass> passes,
                           const model::DamperModel& start, const SeriesScales& scales, const FitSeries& series,
                           std::int64_t& evaluations, std::shared_ptr<const InductionTrace> induction = nullptr) {
  const auto lags = [&](std::string_view name) {
    return changes_induction(name) && model::is_enabled(origin.effects, name);
  };
  const bool shapes_induction =
      std::ranges::any_of(effects, changes_induction) || std::ranges::any_of(model::kEffectNames, lags);
  const FieldGain gain = shapes_induction ? FieldGain::kFitted : FieldGain::kKept;
  FittedModel fit;
  fit.model = origin;
  fit.theta = effect_start;
  for (const RefinePass& pass : passes) {
    ParameterSpace joint = base_space(fit.model, start, scales, gain);
    for (const auto& name : effects) joint = combine(joint, effect_space(name, fit.model, scales));
    if (gain == FieldGain::kKept) {
      // A new trace only when the gain step moved the magnetics.
      if (!induction || !induction->serves(fit.model))
        induction = std::make_shared<const InductionTrace>(fit.model, series);
      joint.induction = induction;
    }
    const Point base = base_coordinates(fit.model, scales, gain);
    Point from(joint.bounds.dimension());
    from << base, fit.theta;
    const auto dimension = static_cast<int>(joint.bounds.dimension());
    fit = refine_space(joint, series, from, 10 + pass.evaluations_per_coordinate * dimension, pass.step);
    evaluations += fit.evaluations;
    fit.theta = fit.theta.tail(fit.theta.size() - base.size()).eval();
    if (gain == FieldGain::kKept && pass.gain_evaluations > 0 && scales.current_varies) {
      const Point effects_theta = fit.theta;
      fit = refine_space(field_gain_space(fit.model, start), series, base_coordinates(fit.model, scales).head(1),
                         pass.gain_evaluations, pass.step);
      evaluations += fit.evaluations;
      fit.theta = effects_theta;
    }
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
  const FitSeries fit_series =
      decimate(full, decimation_factor(full, options.max_fit_samples), options.min_fit_rate);
  result.fit_samples = fit_series.size();
  result.decimation = static_cast<std::size_t>(
      std::lround(static_cast<double>(full.size()) / static_cast<double>(fit_series.size())));
  const FitSeries swarm_series = spread_windows(fit_series, options.max_swarm_samples);
  const SeriesScales scales = series_scales(fit_series);
  WorkerPool pool(options.threads);
  std::uint64_t seed = options.seed;

  // 1. The base model.
  const model::DamperModel& start = options.start;
  const ParameterSpace base_fit_space = base_space(start, start, scales);
  const FittedModel swarm =
      fit_space(base_fit_space, swarm_series, &pool, seed++, 2 * options.evaluations_per_parameter);
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
    // Those that change B first: each is one long serial chain of J-A passes, which the other
    // workers' candidates then fill around. The last task is the null candidate: the round's
    // model refined as a candidate that leaves B alone is, with no effect added. (coil_lag's
    // refinement moves the gain jointly with more evaluations; on a model without a lag it is
    // judged against this lighter refinement.)
    const RefinePass kCandidatePasses[] = {{15, 0.02, 12}, {8, 0.02}};
    const auto refine_candidate = [&](const std::vector<std::string>& effects, const Point& from,
                                      std::int64_t& spent) {
      return refine_jointly(current, effects, from, {kCandidatePasses[0], kCandidatePasses[1]}, options.start,
                            scales, fit_series, spent, round_induction);
    };
    std::vector<std::size_t> order(candidates.size() + 1);
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::ranges::stable_partition(order, [&](std::size_t k) {
      return k < candidates.size() && changes_induction(candidates[k]);
    });
    double null_validation = current_validation;
    pool.run(order.size(), [&](std::size_t slot, unsigned /*worker*/) {
      const std::size_t k = order[slot];
      std::vector<double> force;
      if (k == candidates.size()) {
        std::int64_t spent = 0;
        const FittedModel refined = refine_candidate({}, Point(0), spent);
        evaluations += spent;
        predict_force(refined.model, fit_series, force);
        null_validation = residual_rms(fit_series, force).validation;
        return;
      }
      const std::string& name = candidates[k];
      ParameterSpace effect = effect_space(name, current, scales);
      // Those that change B explore on windows; the others need the whole history (a thermal
      // drift does) and cost little on the round's B.
      const bool magnetic = changes_induction(name);
      if (!magnetic) effect.induction = round_induction;
      const FittedModel alone = fit_space(effect, magnetic ? swarm_series : fit_series, nullptr, round_seed + k,
                                          options.evaluations_per_parameter);
      std::int64_t spent = alone.evaluations;
      FittedModel fit = alone;
      if (name == "stroke_end_air") fit = scan_stroke_threshold(effect, fit_series, scales, alone.theta, spent);
      fit = refine_candidate({name}, fit.theta, spent);
      CandidateTrial& trial = trials[k];
      trial.effect = name;
      trial.round = round;
      predict_force(fit.model, fit_series, force);
      trial.validation_rms = residual_rms(fit_series, force).validation;
      evaluations += spent;
      predict_force(fit.model, full, force);
      const ResidualRms on_full = residual_rms(full, force);
      trial.rms_after = on_full.all;
      trial.max_after = on_full.max;
      trial.parameters = effect_parameters(name, fit.model.effects);
      if (const auto why = implausible(name, fit, scales)) trial.verdict = "not physical: " + *why;
      fits[k] = std::move(fit);
    });
    // An effect is credited only with what it adds to the same refinement without it.
    const double baseline = std::min(current_validation, null_validation);
    for (CandidateTrial& trial : trials) {
      trial.validation_before = baseline;
      const double reduction = 1.0 - trial.validation_rms / std::max(baseline, 1e-300);
      if (trial.verdict.empty() && reduction < options.minimum_reduction)
        trial.verdict = format("validation RMS falls %.1f%%, below the %.0f%% threshold", 100.0 * reduction,
                               100.0 * options.minimum_reduction);
    }
    // The best passing candidate by validation error.
    std::size_t best = trials.size();
    for (std::size_t i = 0; i < trials.size(); ++i) {
      if (!trials[i].verdict.empty()) continue;
      if (best == trials.size() || trials[i].validation_rms < trials[best].validation_rms) best = i;
    }
    if (best < trials.size()) {
      trials[best].accepted = true;
      trials[best].verdict = format("accepted: validation RMS %.4g -> %.4g N", trials[best].validation_before,
                                    trials[best].validation_rms);
      result.accepted.push_back(trials[best].effect);
      // The next round compares its candidates with this model refined to convergence, so
      // no candidate is credited with what a longer refinement of this one would have found.
      // Kept only if it validates at least as well: the polish minimises the fitting error.
      std::int64_t polish_evaluations = 0;
      const model::DamperModel& accepted = fits[best].model;
      const model::DamperModel polished =
          refine_jointly(accepted, result.accepted, effect_coordinates(result.accepted, accepted, scales),
                         {{20, 0.02, 20}, {20, 0.005}, {20, 0.005}}, start, scales, fit_series,
                         polish_evaluations)
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
