#include "tools/residual/ambiguity_naming.hpp"

#include <algorithm>
#include <string>

#include "tools/residual/candidate_effects.hpp"
#include "tools/text_format.hpp"

namespace mrd::tools::search {

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

}  // namespace mrd::tools::search
