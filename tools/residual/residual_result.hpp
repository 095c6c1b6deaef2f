#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "model/damper_model.hpp"
#include "tools/progress.hpp"
#include "tools/residual/claim_evidence.hpp"
#include "tools/residual/model_fit.hpp"
#include "tools/residual/model_uncertainty.hpp"
#include "tools/residual/residual_structure.hpp"
#include "tools/residual/robust_weights.hpp"
#include "tools/residual/screening.hpp"
#include "tools/residual/switch_timing.hpp"
#include "tools/residual/term_discovery.hpp"

// What find_missing_effects (residual_search.hpp) takes and gives: its options, its trials and
// its result; what the search's steps and the reports share.
namespace mrd::tools {

// The documented margin by which one explanation must beat another to tell them apart
// (ambiguity, the library's terms against an effect, the discovery's terms): a fraction of the
// validation RMS. An effect's acceptance is the claim criterion's (claim_evidence.hpp).
inline constexpr double kMinimumValidationReduction = 0.10;

struct ResidualOptions {
  // The damper the fit starts from: the config's, or the default. Effects enabled here were
  // declared by the config: they stay in the base model and are not candidates.
  model::DamperModel start;
  std::vector<std::string> candidates;  // default: every named candidate effect
  double minimum_reduction = kMinimumValidationReduction;
  ClaimCriterion claim;  // what an effect must show to be accepted or to stay in the set
  // The fits run on every k-th sample of the series, at most this many samples (never below
  // min_fit_rate); every reported error is evaluated on the full series.
  std::size_t max_fit_samples = 100000;
  double min_fit_rate = 200.0;  // [Hz]
  // The swarms whose trials move B (the base model's magnetics, coil_lag's) explore on at most
  // this many samples of the fitting series, the runs' openings (run_openings); the Nelder-Mead
  // after each refines on the whole fitting series.
  std::size_t max_swarm_samples = 24000;
  int evaluations_per_parameter = 40;
  // JilesAthertonSettings::jump_recall_tolerance for the searches (0: off, the default until the
  // studies are re-run with it; docs/CLOSING-THE-LOOP.md, "Timing").
  double jump_recall = 0.0;
  unsigned threads = 0;  // 0: every core
  std::uint64_t seed = 1;
  bool discover = true;  // step 7: regress what the named effects left on the library of terms
  // Step 6a (opt-in until the studies are re-run with it): the named set against the library's
  // terms with the base identified again beside them (docs/CLOSING-THE-LOOP.md, "Limits").
  bool terms_beside_base = false;
  // Step 3b (opt-in): a least-squares base that leaves a material share of weight to the robust
  // loss is identified again under it, and every later fit and judgement but the discovery's
  // regression runs under it. Off by
  // default: see docs/CLOSING-THE-LOOP.md, "Limits". The down-weighted spans are reported either way.
  bool robust_fit = false;
  RobustLoss robust;
  ProgressSink* progress = nullptr;  // the base fit, then each round's candidates as they finish
};

// What became of a candidate in its round (and after the set revision).
enum class TrialVerdict {
  kUndecided,           // not yet judged (no trial of a result is left so)
  kNotPhysical,         // its fitted parameters are implausible
  kBelowThreshold,      // fails the claim criterion: not significant, or too small a share
  kOutperformed,        // passes the criterion, but the accepted one lowers the error more
  kAmbiguous,           // passes, within the margin (minimum_reduction) of the accepted one
  kAccepted,            // the round's best
  kRevisedOut,          // accepted, then dropped or swapped out by the set revision
  kAcceptedInRevision,  // swapped in by the set revision
};

struct CandidateTrial {
  std::string effect;
  int round = 0;                   // 1 for the first greedy round
  double validation_before = 0.0;  // the round's model on the validation blocks [N RMS]
  double validation_rms = 0.0;     // with this effect added [N RMS]
  double rms_after = 0.0;          // on the whole run, with this effect added [N]
  double max_after = 0.0;          // [N]
  TrialVerdict verdict = TrialVerdict::kUndecided;
  ClaimEvidence evidence;  // against the round's model, on the paired validation blocks
  std::string explanation;  // the verdict in words, with its figures
  std::vector<std::pair<std::string, double>> parameters;

  [[nodiscard]] bool accepted() const {
    return verdict == TrialVerdict::kAccepted || verdict == TrialVerdict::kAcceptedInRevision;
  }
  // Passed the threshold beside its round's winner: a rival for the set revision.
  [[nodiscard]] bool passed() const {
    return verdict == TrialVerdict::kOutperformed || verdict == TrialVerdict::kAmbiguous;
  }
};

// Candidates (or library terms) the run cannot tell apart.
struct AmbiguousGroup {
  std::vector<std::string> members;  // led by the one kept in the model
  std::string separating_run;        // the run that would separate them, in words
};

struct ResidualResult {
  std::size_t samples = 0;      // of the full series
  std::size_t fit_samples = 0;  // of the series the fits ran on
  std::size_t decimation = 1;
  std::vector<std::string> notes;  // how the series was made
  // Step 0: what the screening set aside, per run; every error is on the kept samples.
  std::vector<std::pair<std::string, Screening>> screenings;
  bool screened = false;
  std::vector<std::string> base_parameters;  // what the base fit found, one line each
  model::DamperModel base;
  model::DamperModel final_model;
  ResidualRms before;  // base model, whole run
  double noise_floor = 0.0;  // [N] of the base's residual: what the claims are weighed against
  ResidualRms after;   // with the accepted effects (the base when none)
  // NRMSE fit [%] of the base and the final model over the kept samples (nrmse_fit_percent).
  double fit_before_percent = 0.0;
  double fit_after_percent = 0.0;
  // The final model's core parameters with their standard deviations (model_uncertainty).
  std::vector<ParameterEstimate> parameters;
  // The final model's parameters on their physical range's edge or outside the model's bounds,
  // one line each: --write-config refuses them without --accept-unphysical.
  std::vector<std::string> unphysical;
  std::vector<std::string> accepted;  // in the order accepted, after the set revision
  // Candidates the run cannot tell apart: the others within the threshold of the kept one.
  std::vector<AmbiguousGroup> ambiguous;
  // Step 7: library terms the regression of the residual accepted (docs/CLOSING-THE-LOOP.md).
  std::vector<DiscoveredTerm> discovered;
  bool discovery = true;  // whether step 7 ran
  // What the set revision after the greedy rounds did (removals, swaps), one line each.
  std::vector<std::string> revisions;
  std::vector<CandidateTrial> trials;  // every round's
  ResidualStructure structure_before;
  ResidualStructure structure_after;
  std::string unexplained;
  // The robust loss: whether --robust-fit was asked and identified the base again (1) or not
  // (0), and against the final model the residual's robust sigma [N], the share of weight the
  // loss takes and where it takes most.
  bool robust_fit = false;
  double robust_tuning = 0.0;  // [robust sigmas], Huber's knee of robust_after
  int robust_refits = 0;
  RobustWeights robust_after;  // its weights: per sample of the full series
  std::vector<DownWeightedSpan> down_weighted;
  // Where in its row each step of the logged current happened, estimated against the final
  // model (switch_timing.hpp); the final fit and predicted_after use the timed current when applied.
  SwitchTiming switch_timing;
  std::vector<double> predicted_before;  // per sample of the full series [N]
  std::vector<double> predicted_after;
  std::int64_t evaluations = 0;  // observer passes over the fitting series
  double seconds = 0.0;  // wall time of the analysis
  // Where the time went: each step of the pipeline with its wall time and observer passes.
  struct StepCost {
    std::string step;
    double seconds = 0.0;
    std::int64_t evaluations = 0;
  };
  std::vector<StepCost> steps;
};

}  // namespace mrd::tools
