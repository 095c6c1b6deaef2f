#include "tools/residual/library_terms.hpp"

#include <algorithm>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "tools/residual/base_identification.hpp"
#include "tools/residual/candidate_trials.hpp"
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
  // A group led by a term left out (a mains line) names a choice the model does not carry.
  std::erase_if(out.discovery.ambiguous, [&](const std::vector<std::string>& group) {
    return std::ranges::none_of(out.discovery.terms, [&](const DiscoveredTerm& t) { return t.term == group.front(); });
  });
  out.validation = validation;
  if (!out.discovery.has_terms()) return out;
  model::DamperModel with_terms = m;
  out.discovery.add_to(with_terms);
  out.validation = s.validation_rms(with_terms);
  for (const DiscoveredTerm& t : out.discovery.terms) out.names += (out.names.empty() ? "" : " + ") + t.term;
  return out;
}

// Whether a term is the own physics of an effect in `effects` (a gas spring's k x).
bool own_physics_of_any(const Effects& effects, const std::string& term) {
  return std::ranges::any_of(effects, [&](const model::EffectInfo* e) {
    return std::ranges::find(e->term_forms, term) != e->term_forms.end();
  });
}

bool names_own_physics(const TermDiscovery& d, const Effects& effects) {
  return std::ranges::any_of(d.terms, [&](const DiscoveredTerm& t) { return own_physics_of_any(effects, t.term); });
}

// The base identified again with the terms the regression found on it riding in the model (the
// force scale scales them), then the terms regressed again on what the new base leaves: a force
// the base has no form for bends a base fitted without it, and no regression on that base's
// residual undoes the bend.
struct TermsBesideBase {
  model::DamperModel with_terms;  // the base identified beside the terms, carrying them
  double validation = 0.0;
  std::vector<DiscoveredTerm> terms;  // those of both regressions, once each
  std::vector<std::vector<std::string>> ambiguous;  // the groups of the regressions taken
  std::string names;
  bool own_physics = false;  // a term is a named effect's own form
};
TermsBesideBase identify_base_beside_terms(Search& s, const model::DamperModel& base, const TermDiscovery& first,
                                           const Effects& named) {
  model::DamperModel riding = base;
  first.add_to(riding);
  ParameterSpace space;
  const FittedModel again = identify_base_twice_if_short(s, riding, space, 1);
  TermsBesideBase out;
  out.with_terms = again.model;
  out.validation = s.validation_rms(again.model);
  const WithTerms more = with_damper_terms(s, again.model, out.validation);
  // The second regression's terms count only where the model takes them.
  const bool more_taken = more.discovery.has_terms() && more.validation < out.validation;
  if (more_taken) {
    more.discovery.add_to(out.with_terms);
    out.validation = more.validation;
  }
  out.own_physics = names_own_physics(first, named) || (more_taken && names_own_physics(more.discovery, named));
  out.terms = first.terms;
  out.ambiguous = first.ambiguous;
  if (more_taken) {
    for (const DiscoveredTerm& t : more.discovery.terms)
      if (std::ranges::none_of(out.terms, [&](const DiscoveredTerm& u) { return u.term == t.term; }))
        out.terms.push_back(t);
    for (const auto& group : more.discovery.ambiguous)
      if (std::ranges::find(out.ambiguous, group) == out.ambiguous.end()) out.ambiguous.push_back(group);
  }
  for (const DiscoveredTerm& t : out.terms) out.names += (out.names.empty() ? "" : " + ") + t.term;
  return out;
}

// The set becomes the base identified beside the terms, carrying them (step 7 lists them).
void carry_terms(AcceptedSet& set, TermsBesideBase terms) {
  set.model = std::move(terms.with_terms);
  set.validation = terms.validation;
  set.terms_in_model = std::move(terms.terms);
  set.terms_ambiguous = std::move(terms.ambiguous);
}

}  // namespace

bool weigh_set_against_terms_beside_base(Search& s, AcceptedSet& set, const model::DamperModel& base,
                                         ResidualResult& result) {
  if (!s.options.discover || !s.options.terms_beside_base || set.effects.empty()) return false;
  const double threshold = s.options.minimum_reduction;
  const WithTerms on_base = with_damper_terms(s, base, s.validation_rms(base));
  if (!on_base.discovery.has_terms() || names_own_physics(on_base.discovery, set.effects)) return false;
  const TermsBesideBase terms = identify_base_beside_terms(s, base, on_base.discovery, set.effects);
  if (terms.own_physics || !(terms.validation < (1.0 - threshold) * set.validation)) return false;
  const double beside = with_damper_terms(s, set.model, set.validation).validation;
  if (weigh_terms_against_effect(set.validation, terms.validation, beside, threshold) != TermRivalry::kTermsReplace)
    return false;
  std::string named;
  for (const model::EffectInfo* e : set.effects) named += (named.empty() ? "" : " + ") + std::string(e->name);
  result.revisions.push_back(format(
      "replaced %s by the terms %s beside the base identified again with them: validation RMS %.4g -> %.4g N "
      "(the set with the terms %.4g N)",
      named.c_str(), terms.names.c_str(), set.validation, terms.validation, beside));
  set.effects.clear();
  set.rivals.clear();
  set.without.clear();
  carry_terms(set, terms);
  return true;
}

// Step 6d's passes after the first: each regresses the terms afresh and is kept while it lowers
// the validation RMS by kTermPassGain.
constexpr int kMoreTermPasses = 3;
constexpr double kTermPassGain = 0.02;

bool identify_base_beside_terms_where_nothing_is_named(Search& s, AcceptedSet& set, const model::DamperModel& base,
                                                       ResidualResult& result) {
  if (!s.options.discover || !set.is_the_base() || !far_above_noise(s, set.validation)) return false;
  const WithTerms on_base = with_damper_terms(s, base, set.validation);
  if (!on_base.discovery.has_terms() || !(on_base.validation < set.validation)) return false;
  // The terms regressed on `m`'s residual, then the base identified again beside them.
  const auto beside_terms_of = [&](const model::DamperModel& m) -> std::optional<TermsBesideBase> {
    const WithTerms regressed = with_damper_terms(s, m, s.validation_rms(m));
    if (!regressed.discovery.has_terms()) return std::nullopt;
    return identify_base_beside_terms(s, m, regressed.discovery, {});
  };
  TermsBesideBase terms = identify_base_beside_terms(s, base, on_base.discovery, {});
  const char* seed = "the base as fitted";
  // The config's damper, which the force never bent, as a second seed: terms regressed on the
  // bent base can hold it bent (the 2 t mass's cubic and linear terms did).
  if (auto from_start = beside_terms_of(s.options.start); from_start && from_start->validation < terms.validation) {
    terms = std::move(*from_start);
    seed = "the config's damper";
  }
  if (!(terms.validation < on_base.validation)) return false;
  int passes = 1;
  for (int more = 0; more < kMoreTermPasses; ++more) {
    std::optional<TermsBesideBase> next = beside_terms_of(without_terms(terms.with_terms));
    if (!next || !(next->validation < (1.0 - kTermPassGain) * terms.validation)) break;
    terms = std::move(*next);
    ++passes;
  }
  result.revisions.push_back(format(
      "nothing named, and the base left %.4g N on the validation blocks (%.3g times the noise): the base identified "
      "again beside the terms %s (regressed first on %s; %d pass%s), %.4g N (the terms on the base as fitted: %.4g N)",
      set.validation, set.validation / s.noise_floor, terms.names.c_str(), seed, passes, passes == 1 ? "" : "es",
      terms.validation, on_base.validation));
  carry_terms(set, std::move(terms));
  return true;
}

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

void weigh_set_and_effects_against_terms(Search& s, AcceptedSet& set, const model::DamperModel& base,
                                         ResidualResult& result) {
  if (set.effects.empty()) {
    identify_base_beside_terms_where_nothing_is_named(s, set, base, result);
    return;
  }
  if (!weigh_set_against_terms_beside_base(s, set, base, result)) weigh_effects_against_terms(s, set, base, result);
}

namespace {

// The terms step 6a or 6d put in the model, ahead of step 7's, each at the model's final coefficient.
void list_carried_terms(const model::DamperModel& model, const std::vector<DiscoveredTerm>& carried,
                        std::vector<DiscoveredTerm>& discovered) {
  std::vector<DiscoveredTerm> listed;
  for (DiscoveredTerm t : carried) {
    t.coefficient = carried_coefficient(model, t.term);
    listed.push_back(std::move(t));
  }
  for (DiscoveredTerm& t : discovered)
    if (std::ranges::none_of(listed, [&](const DiscoveredTerm& u) { return u.term == t.term; }))
      listed.push_back(std::move(t));
  discovered = std::move(listed);
}

}  // namespace

void discover(Search& s, model::DamperModel& model, ResidualResult& result, const std::vector<DiscoveredTerm>& carried,
              const std::vector<std::vector<std::string>>& carried_ambiguous) {
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
  const auto report_ambiguous = [&](const std::vector<std::vector<std::string>>& groups) {
    for (const auto& group : groups) {
      if (std::ranges::find(result.ambiguous, group, &AmbiguousGroup::members) != result.ambiguous.end()) continue;
      result.ambiguous.push_back({.members = group,
                                  .separating_run = "to separate the terms " + group.front() + " and " + group[1] +
                                                    ", run: a motion at other frequencies and amplitudes (the terms "
                                                    "scale differently with them)"});
    }
  };
  report_ambiguous(carried_ambiguous);
  // Groups among terms the model did not take would name a choice that was never made.
  if (added) report_ambiguous(discovery.ambiguous);
  list_carried_terms(model, carried, result.discovered);
  for (std::size_t i = 0; i < s.full.size(); ++i) result.predicted_after[i] += discovery.interference[i];
}

}  // namespace mrd::tools::search
