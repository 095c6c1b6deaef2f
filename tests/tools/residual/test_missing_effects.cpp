// mrd-residual's answer on simulated runs that carry one undeclared effect, or none: the right
// effect is named, the error falls by the documented factor, and a clean run gives "none".
// Short runs (4 s at 1 kHz) keep this in the fast suite; the full table of
// docs/CLOSING-THE-LOOP.md is tools/residual/detection-study.sh.
#include <cmath>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <mutex>

#include <algorithm>
#include <string>
#include <tuple>

#include "tests/tools/residual/residual_test_support.hpp"
#include "tools/residual/residual_report.hpp"

namespace {

using namespace mrd::tools;

// The documented factor: with the right effect, the RMS error falls at least this much.
constexpr double kMinimumFactor = 3.0;

class UndeclaredEffect : public ::testing::TestWithParam<std::tuple<const char*, const char*>> {};

TEST_P(UndeclaredEffect, IsNamedFirstAndTheErrorFalls) {
  const auto [damper, effect] = GetParam();
  const mrd::record::RecordedRun run = residual_testing::simulated_recorded_run(RunProfile::kTable4, damper, {{effect, 1.0}}, 4.0);
  const ResidualResult r = residual_testing::analyse(run);
  ASSERT_FALSE(r.accepted.empty()) << residual_summary({run}, r);
  EXPECT_EQ(r.accepted.front(), effect) << residual_summary({run}, r);
  EXPECT_EQ(r.accepted.size(), 1u) << residual_summary({run}, r);
  EXPECT_GT(r.before.all / r.after.all, kMinimumFactor) << residual_summary({run}, r);
}

INSTANTIATE_TEST_SUITE_P(
    BothClasses, UndeclaredEffect,
    ::testing::Combine(::testing::Values("50kN", "1kN"),
                       ::testing::Values("coil_lag", "preyield_hysteresis", "gas_spring", "thermal_drift",
                                         "sensor_delay", "stroke_end_air")),
    [](const auto& test) { return std::string(std::get<0>(test.param)) + "_" + std::get<1>(test.param); });

class CleanRun : public ::testing::TestWithParam<const char*> {};

TEST_P(CleanRun, GivesNoneAndTheSameErrorAfter) {
  const mrd::record::RecordedRun run = residual_testing::simulated_recorded_run(RunProfile::kTable4, GetParam(), {}, 4.0);
  const ResidualResult r = residual_testing::analyse(run);
  EXPECT_TRUE(r.accepted.empty()) << residual_summary({run}, r);
  EXPECT_EQ(r.after.all, r.before.all);
  EXPECT_NE(r.unexplained.find("white, at the noise floor"), std::string::npos) << r.unexplained;
  const auto json = nlohmann::json::parse(residual_json(r));
  EXPECT_EQ(json["effect"], "none") << json.dump(2);
  EXPECT_TRUE(json["effects"].is_array() && json["effects"].empty()) << json.dump(2);
}

INSTANTIATE_TEST_SUITE_P(BothClasses, CleanRun, ::testing::Values("50kN", "1kN"));

// At constant current a coil lag shows only while the coil is switched on at the start, 10 ms
// of 4 s; that is enough, and the time constant comes out right.
TEST(MissingEffects, CoilLagOfAConstantCurrentRunFromItsSwitchOn) {
  const mrd::record::RecordedRun run = residual_testing::simulated_recorded_run(RunProfile::kSine, "1kN", {{"coil_lag", 2.0}}, 4.0);
  const ResidualResult r = residual_testing::analyse(run);
  ASSERT_EQ(r.accepted, std::vector<std::string>{"coil_lag"}) << residual_summary({run}, r);
  EXPECT_NEAR(r.final_model.effects.get<mrd::model::CoilLagEffect>().time_constant, 2.0 * 5.3e-3, 1e-3);
}

}  // namespace

namespace {

// What the search tells its progress sink, from the worker threads.
class ResidualProgressRecorder final : public mrd::tools::ProgressSink {
 public:
  void report(const mrd::tools::ProgressReport& r) override {
    const std::lock_guard lock(mutex_);
    seen.push_back({std::string(r.stage), r.round, std::string(r.candidate), r.done, r.total, r.best_error});
  }
  struct Seen {
    std::string stage;
    int round;
    std::string candidate;
    std::int64_t done, total;
    double best;
  };
  std::vector<Seen> seen;

 private:
  std::mutex mutex_;
};

}  // namespace

// The claim criterion guards acceptance: the same small gas spring is accepted by default, with
// its t statistic past the one required, and rejected as too small when asked for twice the fall
// of the held-out mean square it shows, the verdict saying why.
// The lenient run's progress: the base fit, then round 1's candidate and null refinement, each
// once, with the round model's validation error.
TEST(MissingEffects, ACandidateBelowTheClaimCriterionIsRejected) {
  const mrd::record::RecordedRun run =
      residual_testing::simulated_recorded_run(RunProfile::kTelegraph, "1kN", {{"gas_spring", 0.3}}, 4.0);
  ResidualOptions options;
  options.threads = 2;
  options.candidates = {"gas_spring"};
  const FitSeries series = make_fit_series({run}, {});
  ResidualProgressRecorder progress;
  options.progress = &progress;
  const ResidualResult lenient = find_missing_effects(series, options);
  options.progress = nullptr;
  ASSERT_EQ(lenient.accepted, std::vector<std::string>{"gas_spring"}) << residual_summary({run}, lenient);
  const CandidateTrial& trial = lenient.trials.front();
  ASSERT_GE(progress.seen.size(), 3u);
  EXPECT_EQ(progress.seen.front().stage, "base fit");
  // The first base fit counts its steps (swarms, chains, the whole-series polish) towards a
  // known total, with the best fitting error so far never rising.
  const std::int64_t base_steps = progress.seen.front().total;
  EXPECT_GE(base_steps, 4);
  for (std::size_t i = 0; i < static_cast<std::size_t>(base_steps) && i < progress.seen.size(); ++i) {
    const auto& step = progress.seen[i];
    EXPECT_EQ(step.stage, "base fit");
    EXPECT_EQ(step.total, base_steps);
    EXPECT_EQ(step.done, static_cast<std::int64_t>(i + 1));
    EXPECT_TRUE(std::isfinite(step.best));
    if (i > 0) {
      EXPECT_LE(step.best, progress.seen[i - 1].best);
    }
  }
  std::vector<std::string> round_one;
  for (const auto& s : progress.seen) {
    if (s.stage != "round" || s.round != 1) continue;
    round_one.push_back(s.candidate);
    EXPECT_EQ(s.total, 2);
    EXPECT_EQ(s.done, static_cast<std::int64_t>(round_one.size()));
    EXPECT_GE(s.best, trial.validation_before);  // the round model's error, before the null refinement
  }
  std::ranges::sort(round_one);
  EXPECT_EQ(round_one, (std::vector<std::string>{"gas_spring", "no effect"}));
  ASSERT_TRUE(trial.evidence.passes());
  EXPECT_GT(trial.evidence.t, trial.evidence.t_required);
  // Asked for twice the fall it showed, against the noise's variance: refused as too small.
  const double floor = lenient.noise_floor;
  ASSERT_GT(floor, 0.0);
  options.claim.noise_share = 2.0 * trial.evidence.reduction / (floor * floor);
  const ResidualResult strict = find_missing_effects(series, options);
  EXPECT_TRUE(strict.accepted.empty()) << residual_summary({run}, strict);
  EXPECT_EQ(strict.trials.front().verdict, TrialVerdict::kBelowThreshold);
  EXPECT_TRUE(strict.trials.front().evidence.significant());
  EXPECT_NE(strict.trials.front().explanation.find("too small"), std::string::npos) << strict.trials.front().explanation;
}

// At the noise floor an effect must be worth a quarter of the noise's variance: on the same
// 1 kN telegraph run a gas spring worth about 0.15 sigma^2 is not named (significant, not
// material), one worth about 0.32 sigma^2 is, and that fit ends at the noise.
TEST(MissingEffects, AtTheNoiseFloorAnEffectNeedsAQuarterOfTheNoisesVariance) {
  const auto analysed = [](double scale) {
    const mrd::record::RecordedRun run =
        residual_testing::simulated_recorded_run(RunProfile::kTelegraph, "1kN", {{"gas_spring", scale}}, 4.0);
    ResidualOptions options;
    options.threads = 2;
    options.candidates = {"gas_spring"};
    return find_missing_effects(make_fit_series({run}, {}), options);
  };
  const ResidualResult small = analysed(0.01);
  ASSERT_EQ(small.trials.size(), 1u);
  const ClaimEvidence& weak = small.trials.front().evidence;
  const double variance = small.noise_floor * small.noise_floor;
  EXPECT_TRUE(small.accepted.empty()) << weak.describe();
  EXPECT_TRUE(weak.significant()) << weak.describe();
  EXPECT_LT(weak.reduction, 0.25 * variance);
  EXPECT_GT(weak.reduction, 0.1 * variance);
  const ResidualResult larger = analysed(0.015);
  ASSERT_EQ(larger.accepted, std::vector<std::string>{"gas_spring"}) << larger.trials.front().explanation;
  EXPECT_GT(larger.trials.front().evidence.reduction, 0.25 * variance);
  EXPECT_LT(larger.after.all, 1.1 * larger.noise_floor);
}

// Two effects in one run: both named, neither revised away, and no ambiguity claimed between
// effects the run needed together.
TEST(MissingEffects, APairOfEffectsIsNamedAsASet) {
  const mrd::record::RecordedRun run = residual_testing::simulated_recorded_run(
      RunProfile::kTelegraph, "1kN", {{"coil_lag", 2.0}, {"gas_spring", 2.0}}, 4.0);
  const ResidualResult r = residual_testing::analyse(run);
  std::vector<std::string> named = r.accepted;
  std::ranges::sort(named);
  EXPECT_EQ(named, (std::vector<std::string>{"coil_lag", "gas_spring"})) << residual_summary({run}, r);
  EXPECT_TRUE(r.ambiguous.empty()) << residual_summary({run}, r);
}

// The Table 4 run is one sine: every reversal lies beyond the air's threshold, so the run shows
// a force lost after every reversal and cannot say whether the air acts only at the stroke
// ends. The air is kept (it fits the shape far better) and named beside pre-yield, with the
// run that would separate them.
TEST(MissingEffects, AirWhoseEveryReversalIsBeyondItsThresholdIsAmbiguousWithPreyield) {
  const mrd::record::RecordedRun run =
      residual_testing::simulated_recorded_run(RunProfile::kTable4, "1kN", {{"stroke_end_air", 1.0}}, 4.0);
  const ResidualResult r = residual_testing::analyse(run);
  ASSERT_EQ(r.accepted, std::vector<std::string>{"stroke_end_air"}) << residual_summary({run}, r);
  const std::vector<std::string> group{"stroke_end_air", "preyield_hysteresis"};
  const auto it = std::ranges::find(r.ambiguous, group, &AmbiguousGroup::members);
  ASSERT_NE(it, r.ambiguous.end()) << residual_summary({run}, r);
  const std::string& test = it->separating_run;
  EXPECT_NE(test.find("every reversal of the run lies beyond"), std::string::npos) << test;
  EXPECT_NE(test.find("reversals both inside and beyond"), std::string::npos) << test;
}

// Band-limited motion reverses inside and beyond the threshold: the run places it, and no
// ambiguity is claimed.
TEST(MissingEffects, AirWithReversalsInsideAndBeyondItsThresholdIsNamedAlone) {
  const mrd::record::RecordedRun run =
      residual_testing::simulated_recorded_run(RunProfile::kTelegraph, "1kN", {{"stroke_end_air", 2.0}}, 4.0);
  const ResidualResult r = residual_testing::analyse(run);
  ASSERT_EQ(r.accepted, std::vector<std::string>{"stroke_end_air"}) << residual_summary({run}, r);
  EXPECT_TRUE(r.ambiguous.empty()) << residual_summary({run}, r);
}

// A spring with no preload is exactly the library's `displacement` term: the gas spring's own
// physics (its descriptor's term forms), not a rival, so no ambiguity is claimed between them.
TEST(MissingEffects, AGasSpringIsNotAmbiguousWithItsOwnDisplacementTerm) {
  mrd::record::RecordedRun run = residual_testing::simulated_recorded_run(RunProfile::kTelegraph, "1kN", {}, 4.0);
  constexpr double kStiffness = 3000.0;  // [N/m]: about 45 N at the stroke, 20 times the noise
  for (std::size_t i = 0; i < run.force.size(); ++i) run.force[i] += kStiffness * run.displacement[i];
  const ResidualResult r = residual_testing::analyse(run);
  ASSERT_EQ(r.accepted, std::vector<std::string>{"gas_spring"}) << residual_summary({run}, r);
  EXPECT_NEAR(r.final_model.effects.get<mrd::model::GasSpringEffect>().stiffness, kStiffness, 0.1 * kStiffness);
  EXPECT_TRUE(r.ambiguous.empty()) << residual_summary({run}, r);
}

// Step 6b's rule, at its edges (threshold 10 %).
TEST(MissingEffects, TermsReplaceAnEffectOnlyWhenClearlyBetterAndItAddsNothingBesideThem) {
  using enum TermRivalry;
  EXPECT_EQ(weigh_terms_against_effect(10.0, 8.0, 7.5, 0.1), kTermsReplace);   // better by 20 %; both 6 % less
  EXPECT_EQ(weigh_terms_against_effect(10.0, 8.0, 7.0, 0.1), kEffectStays);    // beside them it still gains 12.5 %
  EXPECT_EQ(weigh_terms_against_effect(10.0, 9.5, 0.0, 0.1), kAmbiguous);      // terms 5 % better
  EXPECT_EQ(weigh_terms_against_effect(10.0, 10.5, 0.0, 0.1), kAmbiguous);     // effect 4.8 % better
  EXPECT_EQ(weigh_terms_against_effect(10.0, 11.5, 0.0, 0.1), kEffectStays);   // effect 13 % better
  EXPECT_EQ(weigh_terms_against_effect(10.0, 9.05, 0.0, 0.1), kAmbiguous);     // 9.5 % better: within
  EXPECT_EQ(weigh_terms_against_effect(10.0, 8.95, 8.5, 0.1), kTermsReplace);  // 10.5 % better
}
