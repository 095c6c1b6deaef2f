#include "tools/residual/greedy_rounds.hpp"

#include <algorithm>
#include <cstdint>
#include <string>

#include "tools/residual/ambiguity_naming.hpp"
#include "tools/residual/base_identification.hpp"
#include "tools/residual/candidate_effects.hpp"
#include "tools/residual/candidate_trials.hpp"
#include "tools/residual/joint_refinement.hpp"
#include "tools/text_format.hpp"

namespace mrd::tools::search {

namespace {

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

}  // namespace

bool rebase_the_set(Search& s, AcceptedSet& set, ResidualResult& result) {
  if (!far_above_noise(s, set.validation)) return false;
  const FittedModel again = identify_base_with(s, set.model, set.effects, kSecondStartSwarms);
  for (const model::EffectInfo* e : set.effects)
    if (e->implausible(again.model.effects, s.scales)) return false;
  const double validation = s.validation_rms(again.model);
  if (!(validation < set.validation)) return false;
  std::string names;
  for (const model::EffectInfo* e : set.effects) names += (names.empty() ? "" : ", ") + std::string(e->name);
  result.revisions.push_back(format("after a round that claimed nothing, the base identified again with %s searched "
                                    "beside it: validation RMS %.4g -> %.4g N; the round tried again",
                                    names.c_str(), set.validation, validation));
  set.model = again.model;
  set.validation = validation;
  return true;
}

model::DamperModel polish_accepted(Search& s, const model::DamperModel& accepted, const Effects& effects,
                                   double& validation) {
  ParameterSpace space;
  FittedModel rebased = identify_base_twice_if_short(s, accepted, space, 1);
  if (rebased.fitting_rms > kSecondStartRatio * s.white_noise_of(s.predicted(rebased.model)) &&
      effect_space(*effects.back(), accepted, s.scales).bounds.dimension() > 0) {
    FittedModel joint = identify_base_with(s, accepted, *effects.back(), kSecondStartSwarms);
    if (joint.fitting_rms < rebased.fitting_rms) rebased = std::move(joint);
  }
  std::int64_t spent = 0;
  const model::DamperModel polished =
      refine_jointly(s, rebased.model, effects, effect_coordinates(effects, rebased.model, s.scales),
                     {{20, 0.02, 20}, {20, 0.005}, {20, 0.005}}, spent)
          .model;
  s.evaluations += spent;
  const double polished_validation = s.validation_rms(polished);
  const bool keep = polished_validation <= validation;
  validation = std::min(polished_validation, validation);
  return keep ? polished : accepted;
}

AcceptedSet greedy_rounds(Search& s, const model::DamperModel& base, ResidualResult& result,
                          std::vector<Effects>& ambiguous_groups) {
  Effects candidates = candidate_effects(s.options);
  AcceptedSet set;
  set.model = base;
  set.validation = s.validation_rms(set.model);
  bool set_rebased = false;  // once: rebase_the_set
  for (int round_number = 1; !candidates.empty(); ++round_number) {
    Round round = try_candidates(s, set.model, set.validation, candidates, round_number);
    std::size_t best = judge_round(s, round, set.validation);
    if (best == round.trials.size() && set.effects.empty())
      best = rebase_round_leader(s, round, set.model, candidates, round_number);
    if (best == round.trials.size() && !set_rebased && !set.effects.empty()) {
      set_rebased = true;
      if (rebase_the_set(s, set, result)) {
        result.trials.insert(result.trials.end(), round.trials.begin(), round.trials.end());
        continue;  // the round again, on the set's new base
      }
    }
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

}  // namespace mrd::tools::search
