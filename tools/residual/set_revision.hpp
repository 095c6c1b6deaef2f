#pragma once

#include "model/damper_model.hpp"
#include "tools/residual/accepted_set.hpp"
#include "tools/residual/residual_result.hpp"
#include "tools/residual/search_context.hpp"

namespace mrd::tools::search {

// The accepted set without `dropped`, refined: what the others explain on their own.
Reduced without_effect(Search& s, const model::DamperModel& current, const Effects& accepted,
                       const model::EffectInfo* dropped);

// The candidates that passed in effect k's round and are not in the set: what k may be swapped
// for (one accepted in a later round is in the set already).
Effects rivals_outside_the_set(const AcceptedSet& set, std::size_t k);

// Step 6: with two or more accepted, each is reconsidered beside the others: it is swapped for a
// candidate that passed in its round when that one now validates better, and dropped when the
// set no longer earns the claim criterion over the set without it. Each swap and drop goes to
// result.revisions.
void revise_set(Search& s, AcceptedSet& set, ResidualResult& result);

// The trials' verdicts follow the revised set (result.accepted): a dropped or swapped-out
// effect's trial is no longer accepted, and a swapped-in effect's last trial is.
void mark_final_set(ResidualResult& result);

}  // namespace mrd::tools::search
