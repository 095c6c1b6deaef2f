#include "tools/residual/residual_search.hpp"

#include <chrono>
#include <cmath>
#include <vector>

#include "tools/report/fit_statistics.hpp"
#include "tools/residual/accepted_set.hpp"
#include "tools/residual/ambiguity_naming.hpp"
#include "tools/residual/base_identification.hpp"
#include "tools/residual/candidate_effects.hpp"
#include "tools/residual/greedy_rounds.hpp"
#include "tools/residual/joint_refinement.hpp"
#include "tools/residual/library_terms.hpp"
#include "tools/residual/search_context.hpp"
#include "tools/residual/set_revision.hpp"
#include "tools/residual/switch_timing.hpp"

// The orchestration of docs/CLOSING-THE-LOOP.md's steps; each step lives in its own file, in
// mrd::tools::search.
namespace mrd::tools {

namespace {

// Rounds of switch timing and refit at most, each kept while it lowers the fitting RMS by kTimingRoundGain.
constexpr int kTimingRounds = 5;
constexpr double kTimingRoundGain = 0.02;

std::vector<double> residual_of(const FitSeries& s, const std::vector<double>& predicted) {
  std::vector<double> r(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) r[i] = s.force[i] - predicted[i];
  return r;
}

// The residual's structure on the kept samples (the screening's spans are not the damper's).
ResidualStructure structure_of(const FitSeries& full, const std::vector<double>& predicted) {
  std::vector<double> residual = residual_of(full, predicted);
  if (full.excluded_samples() == 0) return analyse_residual(full, residual);
  std::vector<double> kept;
  const FitSeries kept_series = without_excluded(full, residual, kept);
  return analyse_residual(kept_series, kept);
}

// What keeps the final model from being written as a config: a base coordinate on its range's
// edge, a parameter outside the model's own bounds, or one the fit took outside what real dampers
// show (model/typical_ranges.hpp; a value the starting config already had is the user's).
std::vector<std::string> unphysical_parameters(const model::DamperModel& m, const model::DamperModel& start,
                                               const SeriesScales& scales) {
  std::vector<std::string> out = base_coordinates_at_edge(m, start, scales, Magnetics::kMaterial, true);
  const ValidationReport report = model::validate(m);
  const ValidationReport given = model::validate(start);
  for (const ValidationIssue& issue : report.issues()) {
    const bool fitted_outside = issue.severity == ValidationIssue::Severity::kWarning && !given.mentions(issue.field);
    if (issue.severity == ValidationIssue::Severity::kError || fitted_outside) out.push_back(issue.field + ": " + issue.message);
  }
  return out;
}

// Where the time went: each step's wall time and observer passes since the step before.
class StepClock {
 public:
  StepClock(const search::Search& s, std::vector<ResidualResult::StepCost>& steps)
      : search_(s), steps_(steps), started_(std::chrono::steady_clock::now()), step_started_(started_) {}
  void done(const char* step) {
    const auto now = std::chrono::steady_clock::now();
    const std::int64_t evaluations = search_.evaluations;
    steps_.push_back({step, std::chrono::duration<double>(now - step_started_).count(), evaluations - evaluations_});
    step_started_ = now;
    evaluations_ = evaluations;
  }
  [[nodiscard]] double total_seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
  }

 private:
  const search::Search& search_;
  std::vector<ResidualResult::StepCost>& steps_;
  std::chrono::steady_clock::time_point started_;
  std::chrono::steady_clock::time_point step_started_;
  std::int64_t evaluations_ = 0;
};

// The final model's figures on the full series' kept samples: its error, the residual's
// structure, what the robust loss says of it, and both models' NRMSE fit.
void describe_final_residual(const FitSeries& full, const ResidualOptions& options, ResidualResult& result) {
  result.after = residual_rms(full, result.predicted_after);
  result.structure_after = structure_of(full, result.predicted_after);
  result.robust_after = huber_weights(full, result.predicted_after, options.robust);
  result.down_weighted = down_weighted_spans(full, result.predicted_after, result.robust_after);
  std::vector<bool> kept(full.size());
  for (std::size_t i = 0; i < full.size(); ++i) kept[i] = full.role[i] != SampleRole::kExcluded;
  result.fit_before_percent = nrmse_fit_percent(full.force, result.predicted_before, kept);
  result.fit_after_percent = nrmse_fit_percent(full.force, result.predicted_after, kept);
  result.unexplained = describe(result.structure_after);
}

// Step 7b's rounds (switch_timing.hpp): each times the steps against the model, then identifies
// the model again under that timing (the model the search found took every step at its previous
// row, and gives that up a round at a time), while a round lowers the RMS by kTimingRoundGain.
// The best round is kept; `report` says what was written. Whether the phases were.
bool timing_rounds(search::Search& s, const search::Effects& set_effects, model::DamperModel& model,
                   SwitchTiming& report) {
  const std::vector<double> logged = s.fit_series.current;
  SwitchTiming timing = time_current_steps(model, s.fit_series);
  report = timing;
  if (!timing.applied) return false;
  struct Round {
    double rms;
    std::vector<double> current;
    model::DamperModel model;
    SwitchTiming timing;
  };
  Round best{timing.rms_before, logged, model, timing};
  model::DamperModel refitted = model;
  for (int round = 0; round < kTimingRounds; ++round) {
    if (round > 0) {
      s.fit_series.current = logged;
      timing = time_current_steps(refitted, s.fit_series, {.chance_multiple = 0.0});
      if (!timing.applied) break;
    }
    std::int64_t spent = 0;
    refitted = search::refine_jointly(s, refitted, set_effects,
                                      search::effect_coordinates(set_effects, refitted, s.scales),
                                      {{15, 0.02, 12}, {8, 0.02}}, spent)
                   .model;
    s.evaluations += spent;
    const double now = residual_rms(s.fit_series, s.predicted(refitted)).fitting;
    const bool paid = now < (1.0 - kTimingRoundGain) * best.rms;
    if (now < best.rms) best = {now, s.fit_series.current, refitted, timing};
    if (!paid) break;
  }
  s.fit_series.current = best.current;
  model = best.model;
  const double rms_logged = report.rms_before;
  report = best.timing;
  report.rms_before = rms_logged;
  report.rms_after = best.rms;
  report.applied = best.current != logged;
  return report.applied;
}

// The logged current's steps timed within their rows against the final model, on the fitting
// series and the full one alike (so only where the fits run on every sample). The model coming
// in was refitted on every kept sample (refit_on_every_sample): the rounds refit and compare on
// every kept sample too, or a refit on the fitting blocks alone would look like a gain.
bool time_steps_within_rows(search::Search& s, const search::Effects& set_effects, model::DamperModel& model,
                            ResidualResult& result) {
  if (s.fit_series.size() != s.full.size()) return false;
  const std::vector<SampleRole> roles = s.fit_series.role;
  for (SampleRole& role : s.fit_series.role)
    if (role == SampleRole::kValidation) role = SampleRole::kFitting;
  const bool timed = timing_rounds(s, set_effects, model, result.switch_timing);
  s.fit_series.role = roles;
  if (timed) s.full.current = s.fit_series.current;
  return timed;
}

}  // namespace

ResidualResult find_missing_effects(const FitSeries& full, const ResidualOptions& given) {
  // The searches integrate J-A with sub-steps that grow in saturation; what the result reports
  // of its models comes from the models' own integration (the start's).
  ResidualOptions options = given;
  const model::JilesAthertonSettings integration = given.start.integration;
  if (!(integration.field_step_growth > 0.0)) options.start.integration.field_step_growth = kSearchFieldStepGrowth;
  options.start.integration.jump_recall_tolerance = given.jump_recall;
  const auto reported = [&](model::DamperModel m) {
    m.integration = integration;
    return m;
  };
  search::Search s(full, options);
  ResidualResult result;
  StepClock clock(s, result.steps);
  result.samples = full.size();
  result.notes = full.notes;
  result.screenings = full.screenings;
  result.screened = full.screened;
  result.robust_fit = options.robust_fit;
  result.robust_tuning = options.robust.tuning;
  result.fit_samples = s.fit_series.size();
  result.decimation = static_cast<std::size_t>(
      std::lround(static_cast<double>(full.size()) / static_cast<double>(s.fit_series.size())));

  // 1-3. The base model (3b: under the robust loss, with --robust-fit) and its residual.
  ParameterSpace base_fit_space;
  const FittedModel identified = search::fit_base_model(s, base_fit_space);
  clock.done("base fit");
  const FittedModel base = search::refit_robustly(s, base_fit_space, identified, result.robust_refits);
  if (result.robust_refits > 0) clock.done("robust base fit");
  // 3c. What is reported of it: refit on every kept sample (the search goes on with the base of
  // the fitting blocks, which the held-out blocks judge).
  const FittedModel base_on_every_sample = search::refit_on_every_sample(s, options.start, base.model);
  result.base = reported(base_on_every_sample.model);
  result.base_parameters = search::describe_base(base_fit_space, base_on_every_sample, options.start, s.scales);
  predict_force(result.base, full, result.predicted_before);
  result.before = residual_rms(full, result.predicted_before);
  result.structure_before = structure_of(full, result.predicted_before);
  // On the series the claims are weighed on: a load cell's filter ties neighbouring samples of
  // the full rate, and their differences would understate the noise of the decimated samples.
  s.noise_floor = s.white_noise_of(s.predicted(base.model));
  result.noise_floor = s.noise_floor;

  // 4-5. Greedy rounds over the candidates; 6. the set revised as a whole, and what the run
  // cannot decide.
  std::vector<search::Effects> ambiguous_groups;
  search::AcceptedSet set = search::greedy_rounds(s, base.model, result, ambiguous_groups);
  clock.done("greedy rounds");
  search::revise_set(s, set, result);
  clock.done("set revision");
  search::weigh_set_and_effects_against_terms(s, set, base.model, result);
  search::name_ambiguities(set, ambiguous_groups, result);
  for (const model::EffectInfo* e : set.effects) result.accepted.emplace_back(e->name);
  search::mark_final_set(result);
  search::name_unplaced_thresholds(s, set, result);
  clock.done("effects against terms");
  // 6b. The named model refit on every kept sample (the base's refit when nothing was named and
  // step 6d carried no terms);
  // 7. discovery on what it leaves.
  model::DamperModel current =
      set.is_the_base() ? result.base : reported(search::refit_on_every_sample(s, set.model, set.model).model);
  if (time_steps_within_rows(s, set.effects, current, result)) {
    current = reported(current);
    clock.done("switch timing");
  }
  search::discover(s, current, result, set.terms_in_model, set.terms_ambiguous);
  clock.done("discovery");
  result.final_model = current;
  result.evaluations = s.evaluations;
  describe_final_residual(s.full, options, result);
  // Its Jacobian with the searches' J-A sub-steps: a difference quotient, not a reported figure.
  model::DamperModel linearised = result.final_model;
  linearised.integration = options.start.integration;
  result.parameters = model_uncertainty(linearised, s.fit_series, free_magnetics(s.scales, Magnetics::kMaterial));
  result.unphysical = unphysical_parameters(result.final_model, options.start, s.scales);
  clock.done("uncertainty");
  result.seconds = clock.total_seconds();
  return result;
}

}  // namespace mrd::tools
