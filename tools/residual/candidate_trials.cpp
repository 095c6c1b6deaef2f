#include "tools/residual/candidate_trials.hpp"

#include <algorithm>
#include <atomic>
#include <memory>
#include <numeric>
#include <string_view>

#include "tools/residual/base_identification.hpp"
#include "tools/residual/candidate_effects.hpp"
#include "tools/residual/joint_refinement.hpp"
#include "tools/text_format.hpp"

namespace mrd::tools::search {

namespace {

// One candidate's fit from one seed: its swarm (on the round's B unless it changes B), its
// reversal thresholds scanned, then the joint refinement; with its force and validation error.
struct CandidateFit {
  FittedModel fit;
  std::vector<double> force;  // on the fitting series
  double validation = 0.0;    // [N RMS]
};

// Candidate k's fit written into the round: its trial's figures on the whole run, its
// parameters, and kNotPhysical where the fit is implausible.
void record_trial(const Search& s, const model::EffectInfo& effect, CandidateFit&& c, int round_number, std::size_t k,
                  Round& round) {
  CandidateTrial& trial = round.trials[k];
  trial = CandidateTrial{};
  trial.effect = std::string(effect.name);
  trial.round = round_number;
  trial.validation_rms = c.validation;
  round.predicted[k] = std::move(c.force);
  std::vector<double> force;
  predict_force(c.fit.model, s.full, force);
  const ResidualRms on_full = residual_rms(s.full, force);
  trial.rms_after = on_full.all;
  trial.max_after = on_full.max;
  trial.parameters = effect.report(c.fit.model.effects);
  if (const auto why = effect.implausible(c.fit.model.effects, s.scales)) {
    trial.verdict = TrialVerdict::kNotPhysical;
    trial.explanation = "not physical: " + *why;
  }
  round.fits[k] = std::move(c.fit);
}

// The candidates of one round on one round model: each fitted on its own (thread-safe: every
// call works on its own copies), the results written into the round.
class RoundFitter {
 public:
  RoundFitter(Search& s, const model::DamperModel& current, const Effects& candidates, Round& round)
      : s_(s),
        current_(current),
        candidates_(candidates),
        round_(round),
        round_seed_(s.seed),
        induction_(std::make_shared<const InductionTrace>(current, s.fit_series)) {}

  // The round's model refined with no effect added: what each effect is weighed against.
  void fit_null() {
    std::int64_t spent = 0;
    const FittedModel refined = refine({}, current_, Point(0), induction_, spent);
    s_.evaluations += spent;
    std::vector<double> force;
    predict_force(refined.model, s_.fit_series, force);
    round_.null_validation = residual_rms(s_.fit_series, force).validation;
    round_.null_predicted = std::move(force);
  }

  [[nodiscard]] CandidateFit fit(std::size_t k, bool second) const {
    const model::EffectInfo& effect = *candidates_[k];
    const std::uint64_t seed = second ? (round_seed_ + k) ^ kSecondStartSeedMix : round_seed_ + k;
    ParameterSpace space = effect_space(effect, current_, s_.scales);
    // Those that change B explore on the runs' openings; the others need the whole history (a
    // slow drift does) and cost little on the round's B.
    if (!effect.changes_induction) space.induction = induction_;
    CandidateFit out;
    out.fit = fit_space(space, effect.changes_induction ? s_.swarm_series : s_.fit_series, nullptr, seed,
                        s_.options.evaluations_per_parameter);
    std::int64_t spent = out.fit.evaluations;
    if (has_reversal_threshold(effect))
      out.fit = scan_reversal_thresholds(effect, space, s_.fit_series, s_.scales, out.fit.theta, spent);
    out.fit = refine({&effect}, current_, out.fit.theta, induction_, spent);
    if (has_reversal_threshold(effect)) out.fit = rescan_thresholds(effect, std::move(out.fit), spent);
    s_.evaluations += spent;
    predict_force(out.fit.model, s_.fit_series, out.force);
    out.validation = residual_rms(s_.fit_series, out.force).validation;
    return out;
  }

  void record(std::size_t k, CandidateFit&& c, int round_number) const {
    record_trial(s_, *candidates_[k], std::move(c), round_number, k, round_);
  }

 private:
  // (A candidate that changes B is refined with the gain jointly and more evaluations; on a
  // model without such an effect it is judged against this lighter null refinement.)
  FittedModel refine(const Effects& effects, const model::DamperModel& origin, const Point& from,
                     std::shared_ptr<const InductionTrace> induction, std::int64_t& spent) const {
    static constexpr RefinePass kFirst{15, 0.02, 12}, kSecond{8, 0.02};
    return refine_jointly(s_, origin, effects, from, {kFirst, kSecond}, spent, std::move(induction));
  }

  // The thresholds scanned again on the refined model, and refined from there where that pays:
  // the first scan read the reversals with the swarm's other parameters, and the refinement
  // cannot move a threshold across a reversal (the error is flat between them).
  FittedModel rescan_thresholds(const model::EffectInfo& effect, FittedModel refined, std::int64_t& spent) const {
    ParameterSpace around = effect_space(effect, refined.model, s_.scales);
    if (!effect.changes_induction)
      around.induction = std::make_shared<const InductionTrace>(refined.model, s_.fit_series);
    const FittedModel scanned = scan_reversal_thresholds(effect, around, s_.fit_series, s_.scales,
                                                         effect_coordinates(effect, refined.model, s_.scales), spent);
    if (!(scanned.fitting_rms < refined.fitting_rms)) return refined;
    FittedModel again = refine({&effect}, refined.model, scanned.theta, around.induction, spent);
    return again.fitting_rms < refined.fitting_rms ? again : refined;
  }

  Search& s_;
  const model::DamperModel& current_;
  const Effects& candidates_;
  Round& round_;
  std::uint64_t round_seed_;
  std::shared_ptr<const InductionTrace> induction_;  // the round model's B
};

// The physical candidate of least validation error, or candidates.size().
std::size_t round_leader(const Round& round) {
  std::size_t leader = round.trials.size();
  for (std::size_t k = 0; k < round.trials.size(); ++k) {
    if (round.trials[k].verdict != TrialVerdict::kUndecided) continue;
    if (leader == round.trials.size() || round.trials[k].validation_rms < round.trials[leader].validation_rms)
      leader = k;
  }
  return leader;
}

}  // namespace

Round try_candidates(Search& s, const model::DamperModel& current, double current_validation,
                     const Effects& candidates, int round_number) {
  Round round;
  round.trials.resize(candidates.size());
  round.fits.resize(candidates.size());
  round.predicted.resize(candidates.size());
  round.null_validation = current_validation;
  round.current_predicted = s.predicted(current);
  round.null_predicted = round.current_predicted;
  RoundFitter fitter(s, current, candidates, round);
  s.seed += candidates.size();
  std::vector<std::size_t> order(candidates.size() + 1);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::ranges::stable_partition(
      order, [&](std::size_t k) { return k < candidates.size() && candidates[k]->changes_induction; });
  std::atomic<std::int64_t> finished{0};
  std::atomic<int> second_starts{0};
  std::vector<char> restarted(candidates.size(), 0);
  const auto report = [&](std::string_view candidate) {
    if (s.options.progress == nullptr) return;
    s.options.progress->report({.stage = "round", .round = round_number, .candidate = candidate,
                                .done = ++finished, .total = static_cast<std::int64_t>(order.size()),
                                .best_error = current_validation, .unit = "N RMS (validation)"});
  };
  s.pool.run(order.size(), [&](std::size_t slot, unsigned /*worker*/) {
    const std::size_t k = order[slot];
    if (k == candidates.size()) {
      fitter.fit_null();
      report("no effect");
      return;
    }
    const model::EffectInfo& effect = *candidates[k];
    CandidateFit c = fitter.fit(k, false);
    // The candidate holds the round's model (its effect at nothing), so ending worse than it is
    // the swarm's landing, not the effect's verdict: one more swarm of another seed. Not for a
    // fit already outside physics: its effect wants to vanish.
    if (c.validation > kCandidateRestartRatio * current_validation && !effect.implausible(c.fit.model.effects, s.scales)) {
      ++second_starts;
      restarted[k] = 1;
      if (CandidateFit again = fitter.fit(k, true); again.validation < c.validation) c = std::move(again);
    }
    fitter.record(k, std::move(c), round_number);
    report(effect.name);
  });
  // The round's leader, where it leaves the validation error well above the noise: a second
  // swarm too, since the next rounds build on what it explains.
  const std::size_t leader = round_leader(round);
  if (leader < candidates.size() && restarted[leader] == 0 &&
      round.trials[leader].validation_rms > kSecondStartRatio * s.noise_floor) {
    ++second_starts;
    if (CandidateFit again = fitter.fit(leader, true); again.validation < round.trials[leader].validation_rms)
      fitter.record(leader, std::move(again), round_number);
  }
  round.second_starts = second_starts.load();
  return round;
}

std::size_t judge_round(const Search& s, Round& round, double current_validation) {
  const bool null_better = round.null_validation < current_validation;
  const double baseline = null_better ? round.null_validation : current_validation;
  const std::vector<double>& baseline_force = null_better ? round.null_predicted : round.current_predicted;
  const int comparisons = static_cast<int>(round.trials.size()) + round.second_starts;
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

std::size_t rebase_round_leader(Search& s, Round& round, const model::DamperModel& current, const Effects& candidates,
                                int round_number) {
  const std::size_t none = round.trials.size();
  std::size_t leader = none;
  for (std::size_t k = 0; k < round.trials.size(); ++k) {
    if (round.trials[k].verdict != TrialVerdict::kBelowThreshold || !candidates[k]->changes_induction) continue;
    if (leader == none || round.trials[k].validation_rms < round.trials[leader].validation_rms) leader = k;
  }
  if (leader == none) return none;
  const CandidateTrial& trial = round.trials[leader];
  if (!far_above_noise(s, trial.validation_before) || !(trial.validation_rms < trial.validation_before)) return none;
  const model::EffectInfo& effect = *candidates[leader];
  if (effect_space(effect, round.fits[leader].model, s.scales).bounds.dimension() == 0) return none;
  FittedModel beside = identify_base_with(s, round.fits[leader].model, effect, kSecondStartSwarms);
  if (effect.implausible(beside.model.effects, s.scales)) return none;
  // The base alone gets every start the effect's search had (the config's damper, and the base
  // it found beside the effect) besides its own, and the same swarms; the round's own models
  // (as it came, refined with no effect) stand too: the claim is weighed against the best.
  model::DamperModel found_base = beside.model;
  effect.disable(found_base.effects);
  const Point extra[] = {base_coordinates(s.options.start, s.options.start, s.scales, Magnetics::kMaterial),
                         base_coordinates(found_base, s.options.start, s.scales, Magnetics::kMaterial)};
  ParameterSpace space;
  const FittedModel alone = identify_base(s, current, space, true, kSecondStartSwarms, extra);
  std::vector<double> baseline_force = s.predicted(alone.model);
  double baseline = residual_rms(s.fit_series, baseline_force).validation;
  for (auto [validation, force] : {std::pair{round.null_validation, &round.null_predicted},
                                   std::pair{trial.validation_before, &round.current_predicted}}) {
    if (validation < baseline && !force->empty()) {
      baseline = validation;
      baseline_force = *force;
    }
  }
  std::vector<double> beside_force = s.predicted(beside.model);
  const double beside_validation = residual_rms(s.fit_series, beside_force).validation;
  const int comparisons = static_cast<int>(round.trials.size()) + round.second_starts + 1;
  const ClaimEvidence evidence = s.weigh(baseline_force, beside_force, comparisons);
  if (!evidence.passes()) return none;
  record_trial(s, effect, {.fit = std::move(beside), .force = std::move(beside_force), .validation = beside_validation},
               round_number, leader, round);
  CandidateTrial& rebased = round.trials[leader];
  rebased.validation_before = baseline;
  rebased.evidence = evidence;
  rebased.verdict = TrialVerdict::kAccepted;
  rebased.explanation =
      format("accepted with the base identified again beside it: validation RMS %.4g (the best base without it) "
             "-> %.4g N; %s",
             baseline, beside_validation, evidence.describe().c_str());
  return leader;
}

}  // namespace mrd::tools::search
