#pragma once

#include "model/damper_model.hpp"
#include "tools/residual/accepted_set.hpp"
#include "tools/residual/residual_result.hpp"
#include "tools/residual/search_context.hpp"
#include "tools/residual/term_discovery.hpp"

namespace mrd::tools::search {

// Step 6a (--terms-beside-base): the whole named set against the library's terms, the base
// identified again beside the terms the regression finds on `base` (then the terms regressed
// again on what it leaves). Where they validate better than the set by more than the threshold
// and the set beside them earns less than that, with no term a named effect's own form (a gas
// spring's k x), the set goes and `set.model` becomes the base identified beside the terms,
// carrying the terms (step 7 lists them). Returns whether it replaced the set.
bool weigh_set_against_terms_beside_base(Search& s, AcceptedSet& set, const model::DamperModel& base,
                                         ResidualResult& result);

// Step 6b: each named effect against the library's terms, the model without it with the damper
// terms the regression accepts in its place. Terms led by the effect's own physics (its
// descriptor's kTermForms: a gas spring is a k x) are not rivals. The terms replace the effect
// when they validate better than it by more than the threshold and, beside the terms, the
// effect's removal costs less than the threshold (step 7 then finds them). Within the threshold
// of each other the run cannot decide: the named effect stays, since its parameters mean
// something physical, and both are reported. `base` is the base model (the rest of a set of one).
void weigh_effects_against_terms(Search& s, AcceptedSet& set, const model::DamperModel& base,
                                 ResidualResult& result);

// Step 6d, where nothing was named: a force no candidate has a form for bends the base (the
// 2 t mass of the non-candidate study, m a = -m w^2 x on a sine, took the flow index to its edge
// and left 220 N against 26 N of noise), and step 7's regression on the bent base's residual
// cannot undo the bend. Where the base leaves more than kRebaseRatio times the noise on the
// validation blocks and the regression finds damper terms that lower it, the base is identified
// again beside them (as in step 6a), and again beside the terms regressed on the config's damper
// (which the force never bent; the terms of the bent base can hold it bent). The better is kept
// if it validates better than the terms on the base as fitted; then, up to kMoreTermPasses
// times, the terms are regressed afresh on the new base and the base identified beside those,
// while that pays. `set.model` then carries the terms (step 7 lists them). A run at its noise
// never reaches it; each pass costs a base identification. Returns whether it acted.
bool identify_base_beside_terms_where_nothing_is_named(Search& s, AcceptedSet& set, const model::DamperModel& base,
                                                       ResidualResult& result);

// Step 6d where nothing was named; else step 6a, then, where it kept the set, step 6b.
void weigh_set_and_effects_against_terms(Search& s, AcceptedSet& set, const model::DamperModel& base,
                                         ResidualResult& result);

// Step 7: what the named effects left, regressed on the library of terms; damper terms join
// `model` (learned_terms), mains lines are taken off the measurement. Leaves the prediction
// after in result.predicted_after. Terms the model carries from step 6a or 6d (`carried`) are listed
// first, each at the final model's coefficient, and the groups their regression could not tell
// apart (`carried_ambiguous`) are reported as step 7's own.
void discover(Search& s, model::DamperModel& model, ResidualResult& result,
              const std::vector<DiscoveredTerm>& carried = {},
              const std::vector<std::vector<std::string>>& carried_ambiguous = {});

}  // namespace mrd::tools::search
