#include "tools/residual/candidate_trials.hpp"

#include <algorithm>
#include <atomic>
#include <memory>
#include <numeric>
#include <string_view>

#include "tools/residual/candidate_effects.hpp"
#include "tools/residual/joint_refinement.hpp"
#include "tools/text_format.hpp"

namespace mrd::tools::search {

Round try_candidates(Search& s, const model::DamperModel& current, double current_validation,
                     const Effects& candidates, int round_number) {
  Round round;
  round.trials.resize(candidates.size());
  round.fits.resize(candidates.size());
  round.predicted.resize(candidates.size());
  round.null_validation = current_validation;
  round.current_predicted = s.predicted(current);
  round.null_predicted = round.current_predicted;
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
      round.null_predicted = force;
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
    round.predicted[k] = force;
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

std::size_t judge_round(const Search& s, Round& round, double current_validation) {
  const bool null_better = round.null_validation < current_validation;
  const double baseline = null_better ? round.null_validation : current_validation;
  const std::vector<double>& baseline_force = null_better ? round.null_predicted : round.current_predicted;
  const int comparisons = static_cast<int>(round.trials.size());
  for (std::size_t k = 0; k < round.trials.size(); ++k) {
    CandidateTrial& trial = round.trials[k];
    trial.validation_before = baseline;
    trial.evidence = s.weigh(baseline_force, round.predicted[k], comparisons);
    if (trial.verdict != TrialVerdict::kUndecided || trial.evidence.passes()) continue;
    trial.verdict = TrialVerdict::kBelowThreshold;
    const char* why = !trial.evidence.weighable()     ? "too few held-out pieces to weigh"
                      : !trial.evidence.significant() ? "not significant"
                                                      : "too small against the noise and the model's form";
    trial.explanation = format("%s: validation RMS %.4g -> %.4g N; %s", why, baseline, trial.validation_rms,
                               trial.evidence.describe().c_str());
  }
  std::size_t best = round.trials.size();
  for (std::size_t i = 0; i < round.trials.size(); ++i) {
    if (round.trials[i].verdict != TrialVerdict::kUndecided) continue;
    if (best == round.trials.size() || round.trials[i].validation_rms < round.trials[best].validation_rms) best = i;
  }
  if (best == round.trials.size()) return best;
  CandidateTrial& winner = round.trials[best];
  winner.verdict = TrialVerdict::kAccepted;
  winner.explanation = format("accepted: validation RMS %.4g -> %.4g N; %s", winner.validation_before,
                              winner.validation_rms, winner.evidence.describe().c_str());
  for (CandidateTrial& trial : round.trials) {
    if (trial.verdict != TrialVerdict::kUndecided) continue;
    trial.verdict = TrialVerdict::kOutperformed;
    trial.explanation = format("passes, but %s lowers the validation error more", winner.effect.c_str());
  }
  return best;
}

}  // namespace mrd::tools::search
