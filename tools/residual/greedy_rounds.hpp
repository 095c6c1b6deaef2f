#pragma once

#include <vector>

#include "model/damper_model.hpp"
#include "tools/residual/accepted_set.hpp"
#include "tools/residual/residual_result.hpp"
#include "tools/residual/search_context.hpp"

namespace mrd::tools::search {

// Steps 4-5: each round fits every remaining candidate; the best that passes the threshold is
// accepted and polished, its rivals (those that also passed) are kept for the set revision, and
// those within the threshold of it form an ambiguous group (led by the winner). Every round's
// trials go to result.trials.
AcceptedSet greedy_rounds(Search& s, const model::DamperModel& base, ResidualResult& result,
                          std::vector<Effects>& ambiguous_groups);

// Step 5d, once per run: where a round claims nothing while the set named so far leaves more
// than kRebaseRatio times the noise on the validation blocks, its base is identified again with
// the set's effects searched beside it (identify_base_with, four swarms and chains from the set's
// model and from the config's damper). A set polished with its base can still sit in a basin its
// next effect cannot lead out of: the random-damper study's coil_lag+stroke_end_air-204 named
// the air at 427.6 N against 23.1 N of noise, where the lag fitted gained 4 N. Where that
// validates better (and every effect stays plausible), the set takes the new model, the
// revision is reported, and the round is tried again: a claim is then weighed as in any round.
// Whether the set took it.
bool rebase_the_set(Search& s, AcceptedSet& set, ResidualResult& result);

// After an acceptance, the model refined to convergence (all accepted effects and the base
// together), so the next round's candidates are not credited with what a longer refinement of
// this one would have found. Kept only if it validates at least as well: the polish minimises
// the fitting error.
//
// First the base is identified again with the effects in (identify_base): a base fitted without
// an effect bends its material, yield law and shapes to stand in for it, and the joint
// refinement alone, which keeps the magnetics, cannot climb back from there.
model::DamperModel polish_accepted(Search& s, const model::DamperModel& accepted, const Effects& effects,
                                   double& validation);

}  // namespace mrd::tools::search
