#include "tools/residual/library_terms.hpp"

#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

#include "tools/residual/model_fit.hpp"
#include "tools/residual/term_discovery.hpp"
#include "tools/residual/term_rivalry.hpp"
#include "tools/text_format.hpp"

namespace mrd::tools::search {

namespace {

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
  out.discovery = discover_terms(s.fit_series, force, induction, fluid_of(m), s.options.minimum_reduction,
                                 {.pieces = &s.blocks, .noise_floor = s.noise_floor, .criterion = s.options.claim});
  std::erase_if(out.discovery.terms, [](const DiscoveredTerm& t) { return t.interference; });
  out.validation = validation;
  if (!out.discovery.has_terms()) return out;
  model::DamperModel with_terms = m;
  out.discovery.add_to(with_terms);
  out.validation = s.validation_rms(with_terms);
  for (const DiscoveredTerm& t : out.discovery.terms) out.names += (out.names.empty() ? "" : " + ") + t.term;
  return out;
}

}  // namespace

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

void discover(Search& s, model::DamperModel& model, ResidualResult& result) {
  std::vector<double> induction;
  predict_force_and_induction(model, s.full, result.predicted_after, induction);
  result.discovery = s.options.discover;
  if (!s.options.discover) return;
  // Weighed on the whole series' held-out pieces against the fitting series' noise floor: the
  // full rate's sample-to-sample differences understate the noise a load cell's filter smooths.
  const ValidationBlocks pieces = validation_blocks(s.full);
  const TermDiscovery discovery =
      discover_terms(s.full, result.predicted_after, induction, fluid_of(model), s.options.minimum_reduction,
                     {.pieces = &pieces, .noise_floor = s.noise_floor, .criterion = s.options.claim});
  result.discovered = discovery.terms;
  bool added = true;
  if (discovery.has_terms()) {
    // The regression weighs the terms on the residual; the model carries them through its own
    // states and scales (an effect's force, the parts the force scale multiplies). A model that
    // predicts worse with them than without keeps none of them, nor the refitted linear terms,
    // and the report says so.
    model::DamperModel with_terms = model;
    discovery.add_to(with_terms);
    std::vector<double> predicted;
    predict_force(with_terms, s.full, predicted);
    const double without = residual_rms(s.full, result.predicted_after).all;
    const double with = residual_rms(s.full, predicted).all;
    added = with < without;
    if (added) {
      model = std::move(with_terms);
      result.predicted_after = std::move(predicted);
    } else {
      std::string names;
      for (const DiscoveredTerm& t : result.discovered)
        if (!t.interference) names += (names.empty() ? "" : " + ") + t.term;
      std::erase_if(result.discovered, [](const DiscoveredTerm& t) { return !t.interference; });
      const std::string what = names.empty() ? "the refitted force scale and viscous term" : "the discovered terms " + names;
      result.revisions.push_back(
          format("%s not added: the model with them errs by %.4g N RMS, without them %.4g N", what.c_str(), with, without));
    }
  }
  // Groups among terms the model did not take would name a choice that was never made.
  if (added) {
    for (const auto& group : discovery.ambiguous) {
      result.ambiguous.push_back({.members = group,
                                  .separating_run = "to separate the terms " + group.front() + " and " + group[1] +
                                                    ", run: a motion at other frequencies and amplitudes (the terms "
                                                    "scale differently with them)"});
    }
  }
  for (std::size_t i = 0; i < s.full.size(); ++i) result.predicted_after[i] += discovery.interference[i];
}

}  // namespace mrd::tools::search
