#include "tools/residual/residual_search.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numeric>
#include <span>

#include "tools/report/fit_statistics.hpp"
#include "tools/residual/candidate_effects.hpp"
#include "tools/text_format.hpp"

namespace mrd::tools {

namespace {
std::vector<double> residual_of(const FitSeries& s, const std::vector<double>& predicted) {
  std::vector<double> r(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) r[i] = s.force[i] - predicted[i];
  return r;
}

// The residual's structure on the kept samples (the screening's spans are not the damper's).
ResidualStructure structure_of(const FitSeries& full, const std::vector<double>& predicted) {
  std::vector<double> residual = residual_of(full, predicted);
  if (full.excluded_samples() == 0) return analyse_residual(full, residual);
  std::vector<double> kept;
  const FitSeries kept_series = without_excluded(full, residual, kept);
  return analyse_residual(kept_series, kept);
}

std::vector<std::string> describe_base(const ParameterSpace& space, const FittedModel& fit,
                                       const model::DamperModel& start) {
  std::vector<std::string> lines;
  const model::DamperModel& m = fit.model;
  const model::BinghamDamper damper(m.geometry, m.fluid.viscosity, m.fluid.flow_index);
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
  // A coordinate on its range's edge: the run asks for more than the physical range allows.
  const Point theta = fit.theta;
  for (Eigen::Index i = 0; i < theta.size() && i < space.bounds.dimension(); ++i) {
    const double span = space.bounds.upper[i] - space.bounds.lower[i];
    const bool none_at_top = space.parameters[static_cast<std::size_t>(i)].starts_with("log10 yield saturation");
    if (theta[i] <= space.bounds.lower[i] + 1e-3 * span || (!none_at_top && theta[i] >= space.bounds.upper[i] - 1e-3 * span))
      lines.push_back(format("%s at the edge of its physical range [%.3g, %.3g]",
                             space.parameters[static_cast<std::size_t>(i)].c_str(), space.bounds.lower[i],
                             space.bounds.upper[i]));
  }
  return lines;
}

// What every step of the search shares: the series at its resolutions, the pool, the seed
// stream and the count of observer passes.
struct Search {
  Search(const FitSeries& series, const ResidualOptions& opts)
      : full(series),
        options(opts),
        fit_series(decimate(full, decimation_factor(full, opts.max_fit_samples), opts.min_fit_rate)),
        swarm_series(run_openings(fit_series, opts.max_swarm_samples)),
        scales(series_scales(fit_series)),
        pool(opts.threads),
        seed(opts.seed) {}

  const FitSeries& full;
  const ResidualOptions& options;
  const FitSeries fit_series;    // what the fits run on
  const FitSeries swarm_series;  // the runs' openings: where the swarms that move B explore
  const SeriesScales scales;
  WorkerPool pool;
  std::uint64_t seed;
  std::atomic<std::int64_t> evaluations{0};

  [[nodiscard]] double validation_rms(const model::DamperModel& m) const {
    std::vector<double> force;
    predict_force(m, fit_series, force);
    return residual_rms(fit_series, force).validation;
  }
};

struct RefinePass {
  int evaluations_per_coordinate;
  double step;  // Nelder-Mead's first simplex, as a fraction of each coordinate's range
  // After the pass, Nelder-Mead over the field gain alone with this many evaluations, when the
  // gain is not among the pass's coordinates (0: none).
  int gain_evaluations = 0;
};

using Effects = std::vector<const model::EffectInfo*>;

// Nelder-Mead over the base coordinates and those of `effects` together (an effect changes
// what the base absorbed), once per pass, each pass from the last one's model, so that its
// linear terms come close to identity and what the search saw is what the observer runs (the
// linear terms scale the viscous force past some effects' factors only approximately). The
// first pass starts on `origin` at `effect_start`; its theta holds the effects' coordinates.
//
// The field gain: an effect that changes B (a coil lag) changes what the gain absorbed, so the
// gain joins its coordinates, as it does whenever the model already has such an effect (it and
// the gain shape B together, and an effect's best fit then moves both). Other effects on such a
// model leave B alone: their trials share one B trace, and the gain is refined on its own
// between passes, since such an effect can still take over force the gain had absorbed (on the
// Table 4 schedule the current follows the displacement, so a spring's k x looks like a field).
// `induction`, when given, is a B trace the first pass may already use.
FittedModel refine_jointly(const Search& s, const model::DamperModel& origin, const Effects& effects,
                           const Point& effect_start, std::initializer_list<RefinePass> passes,
                           std::int64_t& evaluations, std::shared_ptr<const InductionTrace> induction = nullptr) {
  const model::DamperModel& start = s.options.start;
  const SeriesScales& scales = s.scales;
  const FitSeries& series = s.fit_series;
  const bool shapes_induction =
      std::ranges::any_of(effects, [](const model::EffectInfo* e) { return e->changes_induction; }) ||
      std::ranges::any_of(model::effect_infos(), [&](const model::EffectInfo& e) {
        return e.changes_induction && e.enabled(origin.effects);
      });
  const Magnetics gain = free_magnetics(scales, shapes_induction ? Magnetics::kGain : Magnetics::kKept);
  FittedModel fit;
  fit.model = origin;
  fit.theta = effect_start;
  for (const RefinePass& pass : passes) {
    ParameterSpace joint = base_space(fit.model, start, scales, gain);
    for (const model::EffectInfo* e : effects) joint = combine(joint, effect_space(*e, fit.model, scales));
    if (gain == Magnetics::kKept) {
      // A new trace only when the gain step moved the magnetics.
      if (!induction || !induction->serves(fit.model))
        induction = std::make_shared<const InductionTrace>(fit.model, series);
      joint.induction = induction;
    }
    const Point base = base_coordinates(fit.model, start, scales, gain);
    Point from(joint.bounds.dimension());
    from << base, fit.theta;
    const auto dimension = static_cast<int>(joint.bounds.dimension());
    fit = refine_space(joint, series, from, 10 + pass.evaluations_per_coordinate * dimension, pass.step);
    evaluations += fit.evaluations;
    fit.theta = fit.theta.tail(fit.theta.size() - base.size()).eval();
    if (gain == Magnetics::kKept && pass.gain_evaluations > 0 && scales.current_varies) {
      const Point effects_theta = fit.theta;
      fit = refine_space(field_gain_space(fit.model, start), series,
                         base_coordinates(fit.model, start, scales, Magnetics::kGain).head(1),
                         pass.gain_evaluations, pass.step);
      evaluations += fit.evaluations;
      fit.theta = effects_theta;
    }
  }
  return fit;
}

// The coordinates of every effect of `effects` in `model`, in that order.
Point effect_coordinates(const Effects& effects, const model::DamperModel& model, const SeriesScales& scales) {
  Point all(0);
  for (const model::EffectInfo* e : effects) {
    const Point more = effect_coordinates(*e, model, scales);
    Point both(all.size() + more.size());
    both << all, more;
    all = both;
  }
  return all;
}

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

// The base identified on `origin` (its effects kept, their linear parameters refitted among the
// linear terms): the improved PSO over every base coordinate on the runs' openings, J-A's
// sub-steps capped at 64 a sample while it explores (a trial at 30x the field gain and a
// twentieth of the pinning would otherwise take 600x the sub-steps of the origin); Nelder-Mead
// with restarts there from the swarm's best and, with `from_origin`, from the origin's
// coordinates (the config's damper, a prior, or a model already fitted), the two chains side by
// side; then Nelder-Mead on the whole fitting series from the better. `space` is the whole space.
FittedModel identify_base(Search& s, const model::DamperModel& origin, ParameterSpace& space, bool from_origin) {
  const model::DamperModel& start = s.options.start;
  const FitSeries& openings = s.swarm_series;
  space = base_space(origin, start, s.scales, Magnetics::kMaterial);
  space.linear = linear_effects_of(origin);
  ParameterSpace exploring = space;
  exploring.origin.integration.max_substeps = std::min(exploring.origin.integration.max_substeps, 64);
  const FittedModel swarm = fit_space(exploring, openings, &s.pool, s.seed++, 2 * s.options.evaluations_per_parameter);
  s.evaluations += swarm.evaluations;
  // The two chains, each serial, side by side.
  std::vector<Point> starts{swarm.theta};
  if (from_origin) starts.push_back(base_coordinates(origin, start, s.scales, Magnetics::kMaterial));
  std::vector<FittedModel> refined(starts.size());
  s.pool.run(starts.size(), [&](std::size_t k, unsigned /*worker*/) {
    refined[k] = refine_with_restarts(s, space, openings, starts[k]);
  });
  FittedModel best = *std::ranges::min_element(refined, {}, &FittedModel::fitting_rms);
  if (openings.size() == s.fit_series.size()) return best;
  const auto dimension = static_cast<int>(space.bounds.dimension());
  const FittedModel whole = refine_space(space, s.fit_series, best.theta, 20 + 15 * dimension, 0.01);
  s.evaluations += whole.evaluations;
  return whole;
}

// Step 2: the base model from the start's damper.
FittedModel fit_base_model(Search& s, ParameterSpace& space) {
  if (s.options.progress != nullptr) s.options.progress->report({.stage = "base fit"});
  return identify_base(s, s.options.start, space, true);
}

// The candidates: the options' names (default: every effect), less those the start declares.
Effects candidate_effects(const ResidualOptions& options) {
  Effects out;
  for (const model::EffectInfo& e : model::effect_infos()) {
    const bool listed = options.candidates.empty() ||
                        std::ranges::find(options.candidates, e.name) != options.candidates.end();
    if (listed && e.named_candidate && !e.enabled(options.start.effects)) out.push_back(&e);
  }
  return out;
}

struct Round {
  std::vector<CandidateTrial> trials;  // one per candidate
  std::vector<FittedModel> fits;
  double null_validation = 0.0;  // the round's model refined with no effect added [N RMS]
};

// Step 4: each candidate on its own worker (a swarm over its parameters on the round's model,
// its reversal thresholds scanned, then Nelder-Mead over those and the base parameters together),
// and the null candidate: the round's model refined as a candidate that leaves B alone is, with
// no effect added. Those that change B go first: each is one long serial chain of J-A passes,
// which the other workers' candidates then fill around.
Round try_candidates(Search& s, const model::DamperModel& current, double current_validation,
                     const Effects& candidates, int round_number) {
  Round round;
  round.trials.resize(candidates.size());
  round.fits.resize(candidates.size());
  round.null_validation = current_validation;
  const std::uint64_t round_seed = s.seed;
  s.seed += candidates.size();
  // The round model's B: every candidate that leaves B alone shares it during its swarm.
  const auto round_induction = std::make_shared<const InductionTrace>(current, s.fit_series);
  // (A candidate that changes B is refined with the gain jointly and more evaluations; on a
  // model without such an effect it is judged against this lighter null refinement.)
  const RefinePass kCandidatePasses[] = {{15, 0.02, 12}, {8, 0.02}};
  const auto refine_candidate = [&](const Effects& effects, const Point& from, std::int64_t& spent) {
    return refine_jointly(s, current, effects, from, {kCandidatePasses[0], kCandidatePasses[1]}, spent,
                          round_induction);
  };
  std::vector<std::size_t> order(candidates.size() + 1);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::ranges::stable_partition(
      order, [&](std::size_t k) { return k < candidates.size() && candidates[k]->changes_induction; });
  std::atomic<std::int64_t> finished{0};
  const auto report = [&](std::string_view candidate) {
    if (s.options.progress == nullptr) return;
    s.options.progress->report({.stage = "round", .round = round_number, .candidate = candidate,
                                .done = ++finished, .total = static_cast<std::int64_t>(order.size()),
                                .best_error = current_validation, .unit = "N RMS (validation)"});
  };
  s.pool.run(order.size(), [&](std::size_t slot, unsigned /*worker*/) {
    const std::size_t k = order[slot];
    std::vector<double> force;
    if (k == candidates.size()) {
      std::int64_t spent = 0;
      const FittedModel refined = refine_candidate({}, Point(0), spent);
      s.evaluations += spent;
      predict_force(refined.model, s.fit_series, force);
      round.null_validation = residual_rms(s.fit_series, force).validation;
      report("no effect");
      return;
    }
    const model::EffectInfo& effect = *candidates[k];
    ParameterSpace space = effect_space(effect, current, s.scales);
    // Those that change B explore on the runs' openings; the others need the whole history (a slow
    // drift does) and cost little on the round's B.
    if (!effect.changes_induction) space.induction = round_induction;
    const FittedModel alone = fit_space(space, effect.changes_induction ? s.swarm_series : s.fit_series, nullptr,
                                        round_seed + k, s.options.evaluations_per_parameter);
    std::int64_t spent = alone.evaluations;
    FittedModel fit = alone;
    if (has_reversal_threshold(effect)) {
      fit = scan_reversal_thresholds(effect, space, s.fit_series, s.scales, alone.theta, spent);
    }
    fit = refine_candidate({&effect}, fit.theta, spent);
    CandidateTrial& trial = round.trials[k];
    trial.effect = std::string(effect.name);
    trial.round = round_number;
    predict_force(fit.model, s.fit_series, force);
    trial.validation_rms = residual_rms(s.fit_series, force).validation;
    s.evaluations += spent;
    predict_force(fit.model, s.full, force);
    const ResidualRms on_full = residual_rms(s.full, force);
    trial.rms_after = on_full.all;
    trial.max_after = on_full.max;
    trial.parameters = effect.report(fit.model.effects);
    if (const auto why = effect.implausible(fit.model.effects, s.scales)) {
      trial.verdict = TrialVerdict::kNotPhysical;
      trial.explanation = "not physical: " + *why;
    }
    round.fits[k] = std::move(fit);
    report(effect.name);
  });
  return round;
}

// Step 5: each effect is credited only with what it adds to the same refinement without it
// (the better of the round's model and the null candidate); the best physical candidate that
// passes the threshold wins. Returns its index, or trials.size() when none passes.
std::size_t judge_round(Round& round, double current_validation, double threshold) {
  const double baseline = std::min(current_validation, round.null_validation);
  for (CandidateTrial& trial : round.trials) {
    trial.validation_before = baseline;
    const double reduction = 1.0 - trial.validation_rms / std::max(baseline, 1e-300);
    if (trial.verdict == TrialVerdict::kUndecided && reduction < threshold) {
      trial.verdict = TrialVerdict::kBelowThreshold;
      trial.explanation = format("validation RMS falls %.1f%%, below the %.0f%% threshold", 100.0 * reduction,
                                 100.0 * threshold);
    }
  }
  std::size_t best = round.trials.size();
  for (std::size_t i = 0; i < round.trials.size(); ++i) {
    if (round.trials[i].verdict != TrialVerdict::kUndecided) continue;
    if (best == round.trials.size() || round.trials[i].validation_rms < round.trials[best].validation_rms) best = i;
  }
  if (best == round.trials.size()) return best;
  CandidateTrial& winner = round.trials[best];
  winner.verdict = TrialVerdict::kAccepted;
  winner.explanation = format("accepted: validation RMS %.4g -> %.4g N", winner.validation_before, winner.validation_rms);
  for (CandidateTrial& trial : round.trials) {
    if (trial.verdict != TrialVerdict::kUndecided) continue;
    trial.verdict = TrialVerdict::kOutperformed;
    trial.explanation = format("passes, but %s lowers the validation error more", winner.effect.c_str());
  }
  return best;
}

// Step 5b: the candidates that passed but came within the threshold of the winner: on this run
// they explain the residual as well as it does, so the run cannot decide between them.
Effects ambiguous_with_winner(Round& round, const Effects& candidates, std::size_t best, double threshold) {
  Effects alike;
  const CandidateTrial& winner = round.trials[best];
  for (std::size_t i = 0; i < round.trials.size(); ++i) {
    CandidateTrial& trial = round.trials[i];
    if (i == best || trial.verdict != TrialVerdict::kOutperformed) continue;
    const double margin = 1.0 - winner.validation_rms / std::max(trial.validation_rms, 1e-300);
    if (margin >= threshold) continue;
    trial.verdict = TrialVerdict::kAmbiguous;
    trial.explanation = format("ambiguous with %s: validation RMS %.4g N, within %.1f%% of it (threshold %.0f%%)",
                               winner.effect.c_str(), trial.validation_rms, 100.0 * margin, 100.0 * threshold);
    alike.push_back(candidates[i]);
  }
  return alike;
}

// After an acceptance, the model refined to convergence (all accepted effects and the base
// together), so the next round's candidates are not credited with what a longer refinement of
// this one would have found. Kept only if it validates at least as well: the polish minimises
// the fitting error.
//
// First the base is identified again with the effects in (identify_base): a base fitted without
// an effect bends its material, yield law and shapes to stand in for it, and the joint
// refinement alone, which keeps the magnetics, cannot climb back from there.
model::DamperModel polish_accepted(Search& s, const model::DamperModel& accepted, const Effects& effects,
                                   double& validation) {
  ParameterSpace space;
  const model::DamperModel rebased = identify_base(s, accepted, space, true).model;
  std::int64_t spent = 0;
  const model::DamperModel polished =
      refine_jointly(s, rebased, effects, effect_coordinates(effects, rebased, s.scales),
                     {{20, 0.02, 20}, {20, 0.005}, {20, 0.005}}, spent)
          .model;
  s.evaluations += spent;
  const double polished_validation = s.validation_rms(polished);
  const bool keep = polished_validation <= validation;
  validation = std::min(polished_validation, validation);
  return keep ? polished : accepted;
}

// The accepted set without `dropped`, refined: what the others explain on their own.
struct Reduced {
  model::DamperModel model;
  double validation = 0.0;
};
Reduced without_effect(Search& s, const model::DamperModel& current, const Effects& accepted,
                       const model::EffectInfo* dropped) {
  Effects rest;
  for (const model::EffectInfo* e : accepted)
    if (e != dropped) rest.push_back(e);
  model::DamperModel origin = current;
  dropped->disable(origin.effects);
  std::int64_t spent = 0;
  Reduced out;
  out.model = refine_jointly(s, origin, rest, effect_coordinates(rest, origin, s.scales), {{15, 0.02, 12}, {8, 0.02}},
                             spent)
                  .model;
  s.evaluations += spent;
  out.validation = s.validation_rms(out.model);
  return out;
}

// Step 6: with two or more accepted, each is reconsidered beside the others: it is swapped for a
// candidate that passed in its round when that one now validates better, and dropped when
// removing it costs less than the threshold. The greedy rounds alone never revisit an early pick.
struct AcceptedSet {
  Effects effects;
  std::vector<Effects> rivals;  // per effect: the candidates that also passed in its round
  model::DamperModel model;
  double validation = 0.0;
  // Per effect, the others refined without it, as the last revision pass left them (empty when
  // the set never had two effects).
  std::vector<Reduced> without;
};

void revise_set(Search& s, AcceptedSet& set, ResidualResult& result) {
  const double threshold = s.options.minimum_reduction;
  for (std::size_t k = 0; set.effects.size() >= 2 && k < set.effects.size(); ++k) {
    if (set.rivals[k].empty()) continue;
    const model::EffectInfo* held = set.effects[k];
    const Reduced rest = without_effect(s, set.model, set.effects, held);
    Round round = try_candidates(s, rest.model, rest.validation, set.rivals[k], 0);
    std::size_t best = set.rivals[k].size();
    for (std::size_t i = 0; i < round.trials.size(); ++i) {
      if (round.trials[i].verdict == TrialVerdict::kNotPhysical) continue;
      if (best == set.rivals[k].size() || round.trials[i].validation_rms < round.trials[best].validation_rms) best = i;
    }
    if (best == set.rivals[k].size() || !(round.trials[best].validation_rms < set.validation)) continue;
    result.revisions.push_back(format("swapped %s for %s: validation RMS %.4g -> %.4g N beside the others",
                                      std::string(held->name).c_str(), round.trials[best].effect.c_str(),
                                      set.validation, round.trials[best].validation_rms));
    set.effects[k] = set.rivals[k][best];
    set.rivals[k].erase(set.rivals[k].begin() + static_cast<std::ptrdiff_t>(best));
    set.rivals[k].push_back(held);
    set.validation = round.trials[best].validation_rms;
    set.model = polish_accepted(s, round.fits[best].model, set.effects, set.validation);
  }
  while (set.effects.size() >= 2) {
    std::size_t weakest = set.effects.size();
    double weakest_cost = threshold;
    std::vector<Reduced> rests;
    for (std::size_t k = 0; k < set.effects.size(); ++k) {
      rests.push_back(without_effect(s, set.model, set.effects, set.effects[k]));
      const double cost = 1.0 - set.validation / std::max(rests.back().validation, 1e-300);
      if (cost < weakest_cost) {
        weakest = k;
        weakest_cost = cost;
      }
    }
    if (weakest == set.effects.size()) {
      set.without = std::move(rests);
      break;
    }
    Reduced& weakest_rest = rests[weakest];
    result.revisions.push_back(format("dropped %s: without it the validation RMS rises only %.1f%% (%.4g -> %.4g N)",
                                      std::string(set.effects[weakest]->name).c_str(), 100.0 * weakest_cost,
                                      set.validation, weakest_rest.validation));
    set.effects.erase(set.effects.begin() + static_cast<std::ptrdiff_t>(weakest));
    set.rivals.erase(set.rivals.begin() + static_cast<std::ptrdiff_t>(weakest));
    set.model = std::move(weakest_rest.model);
    set.validation = weakest_rest.validation;
  }
}

model::BinghamDamper fluid_of(const model::DamperModel& m) {
  return model::BinghamDamper(m.geometry, m.fluid.viscosity, m.fluid.flow_index);
}

// The model with the damper terms the residual regression accepts on it (step 7's regression on
// the fitting series, mains lines left out), and its validation RMS.
struct WithTerms {
  TermDiscovery discovery;
  double validation = 0.0;
  std::string names;  // "a + b"
};
WithTerms with_damper_terms(const Search& s, const model::DamperModel& m, double validation) {
  std::vector<double> force, induction;
  predict_force_and_induction(m, s.fit_series, force, induction);
  WithTerms out;
  out.discovery = discover_terms(s.fit_series, force, induction, fluid_of(m), s.options.minimum_reduction);
  std::erase_if(out.discovery.terms, [](const DiscoveredTerm& t) { return t.interference; });
  out.validation = validation;
  if (!out.discovery.has_terms()) return out;
  model::DamperModel with_terms = m;
  out.discovery.add_to(with_terms);
  out.validation = s.validation_rms(with_terms);
  for (const DiscoveredTerm& t : out.discovery.terms) out.names += (out.names.empty() ? "" : " + ") + t.term;
  return out;
}

// Step 6b: each named effect against the library's terms, the model without it with the damper
// terms the regression accepts in its place. Terms led by the effect's own physics (its
// descriptor's kTermForms: a gas spring is a k x) are not rivals. The terms replace the effect
// when they validate better than it by more than the threshold and, beside the terms, the
// effect's removal costs less than the threshold (step 7 then finds them). Within the threshold
// of each other the run cannot decide: the named effect stays, since its parameters mean
// something physical, and both are reported.
void weigh_effects_against_terms(Search& s, AcceptedSet& set, const model::DamperModel& base,
                                 ResidualResult& result) {
  if (!s.options.discover) return;
  const double threshold = s.options.minimum_reduction;
  for (std::size_t k = 0; k < set.effects.size(); ++k) {
    const model::EffectInfo& effect = *set.effects[k];
    Reduced rest;
    if (set.effects.size() == 1) {
      rest.model = base;
      rest.validation = s.validation_rms(base);
    } else if (k < set.without.size()) {
      rest = set.without[k];
    } else {
      continue;
    }
    const WithTerms instead = with_damper_terms(s, rest.model, rest.validation);
    if (!instead.discovery.has_terms()) continue;
    // The first term carries most; those after it often correct what the base fit had absorbed.
    const bool own_physics =
        std::ranges::find(effect.term_forms, instead.discovery.terms.front().term) != effect.term_forms.end();
    if (own_physics) continue;
    const double terms_validation = instead.validation;
    const char* terms = instead.names.c_str();
    const bool terms_better = terms_validation < (1.0 - threshold) * set.validation;
    const double beside = terms_better ? with_damper_terms(s, set.model, set.validation).validation : 0.0;
    const TermRivalry verdict = weigh_terms_against_effect(set.validation, terms_validation, beside, threshold);
    if (verdict == TermRivalry::kEffectStays) continue;
    if (verdict == TermRivalry::kTermsReplace) {
      result.revisions.push_back(format(
          "replaced %s by the terms %s: validation RMS %.4g -> %.4g N (with both %.4g N)",
          std::string(effect.name).c_str(), terms, set.validation, terms_validation, beside));
      set.effects.erase(set.effects.begin() + static_cast<std::ptrdiff_t>(k));
      set.rivals.erase(set.rivals.begin() + static_cast<std::ptrdiff_t>(k));
      set.model = std::move(rest.model);
      set.validation = rest.validation;
      return;  // the other effects' rests included this one: no longer valid
    }
    const double margin = 1.0 - std::min(terms_validation, set.validation) / std::max(terms_validation, set.validation);
    AmbiguousGroup group{.members = {std::string(effect.name)}};
    for (const DiscoveredTerm& t : instead.discovery.terms) group.members.push_back(t.term);
    group.separating_run = format(
        "%s (validation RMS %.4g N) and the terms %s in its place (%.4g N) are within %.1f%% of each other; "
        "to separate them, run: %s",
        std::string(effect.name).c_str(), set.validation, terms, terms_validation, 100.0 * margin,
        std::string(effect.separated_by).c_str());
    result.ambiguous.push_back(std::move(group));
  }
}

// The trials' accepted flags follow the revised set: a dropped or swapped-out effect's trial is
// no longer accepted, and a swapped-in effect's last trial is.
void mark_final_set(ResidualResult& result) {
  for (auto it = result.trials.rbegin(); it != result.trials.rend(); ++it) {
    const bool in_set = std::ranges::find(result.accepted, it->effect) != result.accepted.end();
    if (it->accepted() && !in_set) {
      it->verdict = TrialVerdict::kRevisedOut;
      it->explanation += "; revised out of the set";
    }
  }
  for (const std::string& name : result.accepted) {
    const bool flagged = std::ranges::any_of(result.trials, [&](const CandidateTrial& t) { return t.accepted() && t.effect == name; });
    if (flagged) continue;
    for (auto it = result.trials.rbegin(); it != result.trials.rend(); ++it) {
      if (it->effect != name) continue;
      it->verdict = TrialVerdict::kAcceptedInRevision;
      it->explanation = "accepted in the set revision (" + it->explanation + ")";
      break;
    }
  }
}

// The groups of candidates the run could not separate, less those whose members ended up in
// the model together (both were needed, so the run did separate them).
void name_ambiguities(const AcceptedSet& set, const std::vector<Effects>& groups, ResidualResult& result) {
  for (const Effects& group : groups) {
    const model::EffectInfo* kept = nullptr;
    for (const model::EffectInfo* e : group)
      if (std::ranges::find(set.effects, e) != set.effects.end() && kept == nullptr) kept = e;
    if (kept == nullptr) continue;  // the whole group was revised away
    std::vector<std::string> names{std::string(kept->name)};
    std::string tests = "to separate ";
    for (const model::EffectInfo* e : group) {
      if (e == kept || std::ranges::find(set.effects, e) != set.effects.end()) continue;
      names.emplace_back(e->name);
    }
    if (names.size() < 2) continue;
    for (std::size_t i = 0; i < names.size(); ++i) tests += (i ? (i + 1 == names.size() ? " and " : ", ") : "") + names[i];
    tests += ", run: " + std::string(kept->separated_by);
    for (const model::EffectInfo* e : group)
      if (e != kept) tests += "; or " + std::string(e->separated_by);
    result.ambiguous.push_back({.members = std::move(names), .separating_run = std::move(tests)});
  }
}

// Step 6c: an accepted effect that acts only after reversals beyond a threshold, on a run whose
// every reversal lies beyond it: the run cannot tell it from an effect that acts at every
// reversal, so the best rival that passed in its round is named beside it (the effect is kept:
// it validated better). Reads the accepted trials, so it runs after mark_final_set.
void name_unplaced_thresholds(const Search& s, const AcceptedSet& set, ResidualResult& result) {
  const std::vector<double> amplitudes = reversal_amplitudes(s.fit_series, s.scales);
  if (amplitudes.empty()) return;
  for (const model::EffectInfo* effect : set.effects) {
    std::vector<double> x(effect->search.size());
    effect->coordinates(set.model.effects, s.scales, x);
    for (std::size_t k = 0; k < effect->search.size(); ++k) {
      if (effect->search[k].kind != model::SearchCoordinate::Kind::kReversalThreshold) continue;
      const double threshold = x[k] * s.scales.stroke;
      if (amplitudes.front() <= threshold) continue;  // a reversal inside it places the threshold
      const auto won = std::ranges::find_if(result.trials, [&](const CandidateTrial& t) {
        return t.accepted() && t.effect == effect->name;
      });
      if (won == result.trials.end()) continue;
      const CandidateTrial* rival = nullptr;
      for (const CandidateTrial& t : result.trials) {
        if (t.round != won->round || t.effect == won->effect) continue;
        if (!t.passed()) continue;
        if (rival == nullptr || t.validation_rms < rival->validation_rms) rival = &t;
      }
      if (rival == nullptr) continue;
      std::vector<std::string> group{std::string(effect->name), rival->effect};
      if (std::ranges::find(result.ambiguous, group, &AmbiguousGroup::members) != result.ambiguous.end()) continue;
      const std::string separating_run = format(
          "every reversal of the run lies beyond %s's threshold (%.3g mm; the smallest reversal at %.3g mm), so "
          "the run cannot tell it from %s, which acts at every reversal (validation RMS %.4g N against %.4g N); "
          "to separate them, run: %s",
          won->effect.c_str(), 1e3 * threshold, 1e3 * amplitudes.front(), rival->effect.c_str(),
          rival->validation_rms, won->validation_rms, std::string(effect->separated_by).c_str());
      result.ambiguous.push_back({.members = std::move(group), .separating_run = separating_run});
    }
  }
}

// Steps 4-5: each round fits every remaining candidate; the best that passes the threshold is
// accepted and polished, its rivals (those that also passed) are kept for the set revision, and
// those within the threshold of it form an ambiguous group.
AcceptedSet greedy_rounds(Search& s, const model::DamperModel& base, ResidualResult& result,
                          std::vector<Effects>& ambiguous_groups) {
  Effects candidates = candidate_effects(s.options);
  AcceptedSet set;
  set.model = base;
  set.validation = s.validation_rms(set.model);
  for (int round_number = 1; !candidates.empty(); ++round_number) {
    Round round = try_candidates(s, set.model, set.validation, candidates, round_number);
    const std::size_t best = judge_round(round, set.validation, s.options.minimum_reduction);
    if (best < round.trials.size()) {
      Effects alike = ambiguous_with_winner(round, candidates, best, s.options.minimum_reduction);
      Effects rivals;
      for (std::size_t i = 0; i < round.trials.size(); ++i)
        if (i != best && round.trials[i].passed())
          rivals.push_back(candidates[i]);
      if (!alike.empty()) {
        alike.insert(alike.begin(), candidates[best]);
        ambiguous_groups.push_back(std::move(alike));
      }
      set.effects.push_back(candidates[best]);
      set.rivals.push_back(std::move(rivals));
      set.validation = round.trials[best].validation_rms;
      set.model = polish_accepted(s, round.fits[best].model, set.effects, set.validation);
      candidates.erase(candidates.begin() + static_cast<std::ptrdiff_t>(best));
    }
    result.trials.insert(result.trials.end(), round.trials.begin(), round.trials.end());
    if (best == round.trials.size()) break;
  }
  return set;
}

// Step 7: what the named effects left, regressed on the library of terms; damper terms join
// `model` (learned_terms), mains lines are taken off the measurement. Leaves the prediction
// after in result.predicted_after.
void discover(Search& s, model::DamperModel& model, ResidualResult& result) {
  std::vector<double> induction;
  predict_force_and_induction(model, s.full, result.predicted_after, induction);
  result.discovery = s.options.discover;
  if (!s.options.discover) return;
  const TermDiscovery discovery = discover_terms(s.full, result.predicted_after, induction,
                                                 fluid_of(model), s.options.minimum_reduction);
  result.discovered = discovery.terms;
  for (const auto& group : discovery.ambiguous) {
    result.ambiguous.push_back({.members = group,
                                .separating_run = "to separate the terms " + group.front() + " and " + group[1] +
                                                  ", run: a motion at other frequencies and amplitudes (the terms "
                                                  "scale differently with them)"});
  }
  if (discovery.has_terms()) {
    discovery.add_to(model);
    predict_force(model, s.full, result.predicted_after);
  }
  for (std::size_t i = 0; i < s.full.size(); ++i) result.predicted_after[i] += discovery.interference[i];
}

}  // namespace

TermRivalry weigh_terms_against_effect(double effect_validation, double terms_validation, double both_validation,
                                       double threshold) {
  if (terms_validation < (1.0 - threshold) * effect_validation) {
    const double removal_cost = 1.0 - both_validation / std::max(terms_validation, 1e-300);
    return removal_cost < threshold ? TermRivalry::kTermsReplace : TermRivalry::kEffectStays;
  }
  const double margin = 1.0 - std::min(terms_validation, effect_validation) / std::max(terms_validation, effect_validation);
  return margin < threshold ? TermRivalry::kAmbiguous : TermRivalry::kEffectStays;
}

ResidualResult find_missing_effects(const FitSeries& full, const ResidualOptions& given) {
  const auto started = std::chrono::steady_clock::now();
  // The searches integrate J-A with sub-steps that grow in saturation; what the result reports
  // of its models comes from the models' own integration (the start's).
  ResidualOptions options = given;
  const model::JilesAthertonSettings integration = given.start.integration;
  if (!(integration.field_step_growth > 0.0)) options.start.integration.field_step_growth = kSearchFieldStepGrowth;
  const auto reported = [&](model::DamperModel m) {
    m.integration = integration;
    return m;
  };
  Search s(full, options);
  ResidualResult result;
  result.samples = full.size();
  result.notes = full.notes;
  result.screenings = full.screenings;
  result.screened = full.screened;
  result.fit_samples = s.fit_series.size();
  result.decimation = static_cast<std::size_t>(
      std::lround(static_cast<double>(full.size()) / static_cast<double>(s.fit_series.size())));

  // 1-3. The base model and its residual.
  ParameterSpace base_fit_space;
  const FittedModel base = fit_base_model(s, base_fit_space);
  result.base = reported(base.model);
  result.base_parameters = describe_base(base_fit_space, base, options.start);
  predict_force(result.base, full, result.predicted_before);
  result.before = residual_rms(full, result.predicted_before);
  result.structure_before = structure_of(full, result.predicted_before);

  // 4-5. Greedy rounds over the candidates; 6. the set revised as a whole, and what the run
  // cannot decide.
  std::vector<Effects> ambiguous_groups;
  AcceptedSet set = greedy_rounds(s, base.model, result, ambiguous_groups);
  revise_set(s, set, result);
  weigh_effects_against_terms(s, set, base.model, result);
  name_ambiguities(set, ambiguous_groups, result);
  for (const model::EffectInfo* e : set.effects) result.accepted.emplace_back(e->name);
  mark_final_set(result);
  name_unplaced_thresholds(s, set, result);
  // 7. Discovery on what the named effects left.
  model::DamperModel current = reported(set.model);
  discover(s, current, result);
  result.final_model = current;
  result.evaluations = s.evaluations;
  result.after = residual_rms(full, result.predicted_after);
  result.structure_after = structure_of(full, result.predicted_after);
  std::vector<bool> kept(full.size());
  for (std::size_t i = 0; i < full.size(); ++i) kept[i] = full.role[i] != SampleRole::kExcluded;
  result.fit_before_percent = nrmse_fit_percent(full.force, result.predicted_before, kept);
  result.fit_after_percent = nrmse_fit_percent(full.force, result.predicted_after, kept);
  // Its Jacobian with the searches' J-A sub-steps: a difference quotient, not a reported figure.
  model::DamperModel linearised = result.final_model;
  linearised.integration = options.start.integration;
  result.parameters = model_uncertainty(linearised, s.fit_series, free_magnetics(s.scales, Magnetics::kMaterial));
  result.unexplained = describe(result.structure_after);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return result;
}

}  // namespace mrd::tools
