#pragma once

#include <cstddef>
#include <vector>

#include "model/damper_model.hpp"
#include "tools/residual/model_fit.hpp"
#include "tools/residual/residual_result.hpp"
#include "tools/residual/search_context.hpp"

namespace mrd::tools::search {

struct Round {
  std::vector<CandidateTrial> trials;  // one per candidate
  std::vector<FittedModel> fits;
  std::vector<std::vector<double>> predicted;  // per candidate, its force on the fitting series
  double null_validation = 0.0;  // the round's model refined with no effect added [N RMS]
  std::vector<double> null_predicted;
  std::vector<double> current_predicted;  // the round's model as it came
};

// Step 4: each candidate on its own worker (a swarm over its parameters on the round's model,
// its reversal thresholds scanned, then Nelder-Mead over those and the base parameters together),
// and the null candidate: the round's model refined as a candidate that leaves B alone is, with
// no effect added. Those that change B go first: each is one long serial chain of J-A passes,
// which the other workers' candidates then fill around. A trial whose fit is implausible comes
// back kNotPhysical, every other kUndecided. Takes one seed per candidate off the search's stream.
Round try_candidates(Search& s, const model::DamperModel& current, double current_validation,
                     const Effects& candidates, int round_number);

// Step 5: each effect is credited only with what it adds to the same refinement without it
// (the better of the round's model and the null candidate), on the paired held-out blocks; the
// best physical candidate that passes the claim criterion (one of the round's comparisons) wins.
// Returns its index, or trials.size() when none passes.
std::size_t judge_round(const Search& s, Round& round, double current_validation);

}  // namespace mrd::tools::search
