// mrd-residual's answer on simulated runs that carry one undeclared effect, or none: the right
// effect is named, the error falls by the documented factor, and a clean run gives "none".
// Short runs (4 s at 1 kHz) keep this in the fast suite; the full table of
// docs/CLOSING-THE-LOOP.md is tools/residual/detection-study.sh.
#include <gtest/gtest.h>

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
  const std::string json = residual_json(r);
  EXPECT_NE(json.find("\"effect\": \"none\""), std::string::npos) << json;
  EXPECT_NE(json.find("\"effects\": []"), std::string::npos) << json;
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

// The threshold guards acceptance: the same small gas spring is accepted under a threshold below
// what it gains and rejected under one above it, with the verdict saying by how much it fell.
TEST(MissingEffects, ACandidateBelowTheThresholdIsRejected) {
  const mrd::record::RecordedRun run =
      residual_testing::simulated_recorded_run(RunProfile::kTelegraph, "1kN", {{"gas_spring", 0.3}}, 4.0);
  ResidualOptions options;
  options.threads = 2;
  options.candidates = {"gas_spring"};
  const FitSeries series = make_fit_series({run}, {});
  const ResidualResult lenient = find_missing_effects(series, options);
  ASSERT_EQ(lenient.accepted, std::vector<std::string>{"gas_spring"}) << residual_summary({run}, lenient);
  const CandidateTrial& trial = lenient.trials.front();
  const double gain = 1.0 - trial.validation_rms / trial.validation_before;
  ASSERT_GT(gain, 0.15);
  options.minimum_reduction = gain + 0.05;
  const ResidualResult strict = find_missing_effects(series, options);
  EXPECT_TRUE(strict.accepted.empty()) << residual_summary({run}, strict);
  EXPECT_NE(strict.trials.front().verdict.find("below the"), std::string::npos) << strict.trials.front().verdict;
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
