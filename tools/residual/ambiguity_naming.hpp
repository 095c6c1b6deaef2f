#pragma once

#include <cstddef>
#include <vector>

#include "tools/residual/accepted_set.hpp"
#include "tools/residual/candidate_trials.hpp"
#include "tools/residual/residual_result.hpp"
#include "tools/residual/search_context.hpp"

namespace mrd::tools::search {

// Step 5b: the candidates that passed but came within the threshold of the winner: on this run
// they explain the residual as well as it does, so the run cannot decide between them. Their
// trials become kAmbiguous.
Effects ambiguous_with_winner(Round& round, const Effects& candidates, std::size_t best, double threshold);

// The groups of candidates the run could not separate, less those whose members ended up in
// the model together (both were needed, so the run did separate them).
void name_ambiguities(const AcceptedSet& set, const std::vector<Effects>& groups, ResidualResult& result);

// Step 6c: an accepted effect that acts only after reversals beyond a threshold, on a run whose
// every reversal lies beyond it: the run cannot tell it from an effect that acts at every
// reversal, so the best rival that passed in its round is named beside it (the effect is kept:
// it validated better). Reads the accepted trials, so it runs after mark_final_set.
void name_unplaced_thresholds(const Search& s, const AcceptedSet& set, ResidualResult& result);

}  // namespace mrd::tools::search
