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
  int second_starts = 0;                  // candidates that took a second swarm
};

// Step 4: each candidate on its own worker (a swarm over its parameters on the round's model,
// its reversal thresholds scanned, then Nelder-Mead over those and the base parameters together,
// then the thresholds scanned again on the refined model and refined once more where it pays),
// and the null candidate: the round's model refined as a candidate that leaves B alone is, with
// no effect added. Those that change B go first: each is one long serial chain of J-A passes,
// which the other workers' candidates then fill around. A trial whose fit is implausible comes
// back kNotPhysical, every other kUndecided. Takes one seed per candidate off the search's stream.
// A physical candidate whose validation error ends above kCandidateRestartRatio times the round
// model's gets a second swarm, its seed the first's mixed with kSecondStartSeedMix, and keeps the
// fit that predicts the validation blocks better; each second start counts as one more comparison
// when the round is judged. (On the detection study's 50 kN telegraph run with stroke-end air, one
// swarm put the threshold 5 mm short: 633 N on the fitting blocks, 3,035 N on validation; the
// second 667 N and 163 N. The fitting blocks would have kept the first.) The round's leader (the
// physical candidate of least validation error) gets one too where it leaves that error above
// kSecondStartRatio times the noise floor: the next rounds build on what it explains.
inline constexpr double kCandidateRestartRatio = 1.05;
inline constexpr std::uint64_t kSecondStartSeedMix = 0x9E3779B97F4A7C15ULL;
Round try_candidates(Search& s, const model::DamperModel& current, double current_validation,
                     const Effects& candidates, int round_number);

// Step 5: each effect is credited only with what it adds to the same refinement without it
// (the better of the round's model and the null candidate), on the paired held-out blocks; the
// best physical candidate that passes the claim criterion (one of the round's comparisons, a
// trial each and a second start each) wins.
// Returns its index, or trials.size() when none passes.
std::size_t judge_round(const Search& s, Round& round, double current_validation);

// Step 5c, in the first round only, where no candidate passed while the base leaves more than
// kRebaseRatio times the noise on the validation blocks: the base may sit in a basin that only
// the missing effect leads out of (a lagged telegraph run's base without the lag lands anywhere
// from 190 to 350 N RMS, and the lag fitted on the worse one gains too little to be claimed).
// The candidate that changes B (the magnetics are where the base's basins and such an effect
// trade) and lowered the validation error most is identified together with the base
// (identify_base_with). The base is identified again alone with the same swarms and every start
// the effect's search had, and the claim is weighed against the best of that, the round's model
// and its null refinement; where it passes, the candidate is the round's winner (its trial says
// how it was found). The other candidates are not tried beside a new base, so no rival or
// ambiguity is weighed for it. Returns its index, or trials.size().
inline constexpr double kRebaseRatio = 3.0;
// Whether a validation RMS [N] is more than kRebaseRatio times the run's noise floor (false
// while the floor is unknown): the gate of steps 5c, 5d and 6d.
[[nodiscard]] inline bool far_above_noise(const Search& s, double validation_rms) {
  return s.noise_floor > 0.0 && validation_rms > kRebaseRatio * s.noise_floor;
}
std::size_t rebase_round_leader(Search& s, Round& round, const model::DamperModel& current, const Effects& candidates,
                                int round_number);

}  // namespace mrd::tools::search
