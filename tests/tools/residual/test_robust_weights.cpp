// The fits' robust loss: Huber weights against an independent noise draw, and a fault that no
// screening rule names (a load cell whose zero jumps for half a second) moving the fit little.
#include "tools/residual/robust_weights.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "tests/tools/residual/residual_test_support.hpp"
#include "tools/residual/residual_report.hpp"
#include "tools/signal/signal_scale.hpp"

namespace {

using namespace mrd::tools;

// The robust scales by hand: the median absolute deviation ignores the outlier, and a current
// varies only past 5 % of its largest magnitude.
TEST(SignalScale, MadSigmaAndVariesAgainstHandWorkedValues) {
  EXPECT_DOUBLE_EQ(mad_sigma({1.0, 2.0, 3.0, 4.0, 100.0}), 1.4826);  // median 3, deviations' median 1
  EXPECT_DOUBLE_EQ(mad_sigma({-5.0, -5.0, -5.0}), 0.0);
  EXPECT_DOUBLE_EQ(mad_sigma({}), 0.0);
  const std::vector<double> ripple{-1.0, -1.04}, steps{1.0, 0.94}, none{0.0, 0.0};
  EXPECT_FALSE(varies(ripple));
  EXPECT_TRUE(varies(steps));
  EXPECT_FALSE(varies(none));
  EXPECT_DOUBLE_EQ(largest_magnitude(ripple), 1.04);
}

// A series of n samples at 1 kHz whose force is Gaussian noise of sigma 1 N about a zero
// prediction, every sample fitting.
FitSeries noise_series(std::size_t n, std::uint32_t seed) {
  FitSeries s;
  s.sample_period = 1e-3;
  s.run_periods = {1e-3};
  s.run_starts = {0};
  s.run_names = {"noise.csv"};
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, 1.0);
  for (std::size_t i = 0; i < n; ++i) {
    s.time.push_back(10.0 + 1e-3 * static_cast<double>(i));
    s.force.push_back(noise(rng));
    s.displacement.push_back(0.0);
    s.velocity.push_back(0.0);
    s.current.push_back(0.0);
    s.role.push_back(SampleRole::kFitting);
  }
  return s;
}

TEST(RobustWeights, GaussianNoiseKeepsItsWeightBelowTheRefitShare) {
  const FitSeries s = noise_series(20000, 7);
  const std::vector<double> zero(s.size(), 0.0);
  const RobustWeights w = huber_weights(s, zero);
  EXPECT_NEAR(w.sigma, 1.0, 0.03);
  // E[1 - 3/|z|; |z| > 3] for a unit normal is 2.2e-4.
  EXPECT_LT(w.down_weighted_share, RobustLoss{}.refit_share);
  EXPECT_GT(w.down_weighted_share, 0.0);
  EXPECT_TRUE(down_weighted_spans(s, zero, w).empty());
}

TEST(RobustWeights, AnOffsetSpanWeighsTheKneeOverItsResidualAndIsNamedFirst) {
  FitSeries s = noise_series(20000, 11);
  for (std::size_t i = 5000; i < 5300; ++i) s.force[i] += 30.0;  // 0.3 s, 30 sigmas off
  for (std::size_t i = 12000; i < 12010; ++i) s.force[i] -= 10.0;
  s.role[5100] = SampleRole::kExcluded;
  const std::vector<double> zero(s.size(), 0.0);
  const RobustWeights w = huber_weights(s, zero);
  EXPECT_NEAR(w.sigma, 1.0, 0.05);  // the MAD ignores the 310 faulted samples
  EXPECT_NEAR(w.weight[5050], 3.0 * w.sigma / std::fabs(s.force[5050]), 1e-12);
  EXPECT_EQ(w.weight[5100], 1.0);  // excluded: not the loss's to weigh
  EXPECT_GT(w.down_weighted_share, 0.01);
  const auto spans = down_weighted_spans(s, zero, w);
  ASSERT_EQ(spans.size(), 2u);
  EXPECT_EQ(spans[0].run, "noise.csv");
  EXPECT_NEAR(spans[0].start_s, 15.0, 1e-9);
  EXPECT_NEAR(spans[0].end_s, 15.299, 1e-9);
  EXPECT_EQ(spans[0].samples, 299u);
  EXPECT_NEAR(spans[1].start_s, 22.0, 1e-9);
  EXPECT_GT(spans[0].lost_weight, spans[1].lost_weight);
  EXPECT_GT(spans[0].peak_residual, 30.0);
}

// A switch-on transient the base cannot follow is evidence for an effect, not a fault: the
// samples within 0.1 s of a step of the coil current (the run's start counts as a step from
// 0 A) weigh as the loss says but do not count towards the share that triggers the robust refit.
TEST(RobustWeights, TheSettlingAfterACurrentSwitchDoesNotTriggerTheRefit) {
  mrd::record::RecordedRun run;
  run.name = "switched.csv";
  run.sample_rate = 1000.0;
  for (int i = 0; i < 4000; ++i) {
    const double t = 1e-3 * i;
    run.time.push_back(t);
    run.displacement.push_back(0.02 * std::sin(2.0 * M_PI * t));
    run.velocity.push_back(0.04 * M_PI * std::cos(2.0 * M_PI * t));
    run.coil.push_back(i < 2000 ? 1.0 : 0.4);  // energised from the start, one switch at 2 s
    run.force.push_back(0.0);
  }
  FitSeriesOptions options;
  options.screen = false;
  FitSeries s = make_fit_series({run}, options);
  ASSERT_EQ(s.after_switch.size(), s.size());
  const auto marked = [&](std::size_t from, std::size_t to) {
    return std::count(s.after_switch.begin() + static_cast<std::ptrdiff_t>(from),
                      s.after_switch.begin() + static_cast<std::ptrdiff_t>(to), 1);
  };
  EXPECT_EQ(marked(0, 100), 100);      // the first 0.1 s: the core starts at 0 A
  EXPECT_EQ(marked(100, 2000), 0);
  EXPECT_EQ(marked(2000, 2100), 100);  // 0.1 s after the switch
  EXPECT_EQ(marked(2100, 4000), 0);
  // Noise, and a transient of 40 sigmas over the 50 ms after each switch.
  std::mt19937 rng(5);
  std::normal_distribution<double> noise(0.0, 1.0);
  for (std::size_t i = 0; i < s.size(); ++i) s.force[i] = noise(rng) + (i % 2000 < 50 ? 40.0 : 0.0);
  const std::vector<double> zero(s.size(), 0.0);
  const RobustWeights at_switches = huber_weights(s, zero);
  EXPECT_LT(at_switches.down_weighted_share, RobustLoss{}.refit_share);
  EXPECT_LT(at_switches.weight[10], 0.1);  // the loss still weighs them
  // The same transient where no current switched is a fault: it triggers.
  for (std::size_t i = 0; i < s.size(); ++i) s.force[i] = noise(rng) + (i >= 1000 && i < 1100 ? 40.0 : 0.0);
  EXPECT_GT(huber_weights(s, zero).down_weighted_share, 10.0 * RobustLoss{}.refit_share);
}

// Each loss's weight is rho'(r) / 2r (by central differences), rho reads r^2 well inside the
// knee, and beyond it Huber's grows linearly and Cauchy's logarithmically.
TEST(FitLoss, WeightsAreTheLossSlopeOverTwiceTheResidual) {
  for (const FitLoss::Kind kind : {FitLoss::Kind::kSquares, FitLoss::Kind::kHuber, FitLoss::Kind::kCauchy}) {
    const FitLoss loss{kind, 6.0};
    for (const double r : {-400.0, -9.0, -0.5, 0.3, 5.9, 6.1, 60.0, 3000.0}) {
      const double h = 1e-5 * std::max(1.0, std::fabs(r));
      const double slope = (loss.rho(r + h) - loss.rho(r - h)) / (2.0 * h);
      EXPECT_NEAR(loss.weight(r), slope / (2.0 * r), 1e-6) << static_cast<int>(kind) << " r " << r;
    }
    EXPECT_NEAR(loss.rho(0.06), 0.0036, 1e-6);
  }
  const FitLoss huber{FitLoss::Kind::kHuber, 6.0}, cauchy{FitLoss::Kind::kCauchy, 6.0};
  EXPECT_DOUBLE_EQ(huber.rho(600.0), 2.0 * 6.0 * 600.0 - 36.0);
  EXPECT_DOUBLE_EQ(cauchy.rho(600.0), 36.0 * std::log(1.0 + 1e4));
  EXPECT_TRUE(FitLoss{}.squares());
  EXPECT_TRUE((FitLoss{FitLoss::Kind::kHuber, 0.0}.squares()));  // no knee: least squares
}

TEST(RobustWeights, TuningZeroIsLeastSquares) {
  FitSeries s = noise_series(2000, 3);
  s.force[100] = 1e3;
  const RobustWeights w = huber_weights(s, std::vector<double>(s.size(), 0.0), RobustLoss{.tuning = 0.0});
  EXPECT_TRUE(std::ranges::all_of(w.weight, [](double x) { return x == 1.0; }));
}

// A load cell whose zero jumps by half the peak force for 0.5 s, while the rod moves: no
// screening rule names it. Least squares bends the damper to pay for it; the robust fit
// (--robust-fit) leaves the other samples' error where the unfaulted run has it; both name the span.
TEST(RobustFit, AZeroJumpNoRuleNamesMovesTheFitLittleAndIsReported) {
  const auto clean = residual_testing::simulated_recorded_run(RunProfile::kTable4, "1kN", {}, 6.0);
  auto faulted = clean;
  const auto [lo, hi] = std::minmax_element(clean.force.begin(), clean.force.end());
  const double jump = 0.5 * std::max(*hi, -*lo);
  const double from = clean.time.front() + 3.0, to = from + 0.5;
  for (std::size_t i = 0; i < faulted.size(); ++i)
    if (faulted.time[i] >= from && faulted.time[i] < to) faulted.force[i] += jump;
  ResidualOptions options;
  options.threads = 2;
  options.discover = false;
  ResidualOptions squares = options;
  squares.robust_fit = false;
  options.robust_fit = true;
  const ResidualResult reference = find_missing_effects(make_fit_series({clean}, {}), options);
  const ResidualResult robust = find_missing_effects(make_fit_series({faulted}, {}), options);
  const ResidualResult plain = find_missing_effects(make_fit_series({faulted}, {}), squares);
  ASSERT_EQ(robust.screenings.size(), 1u);
  EXPECT_EQ(robust.screenings[0].second.excluded_samples, 0u);  // no rule names it
  // The error against the clean force, on the samples outside the jump.
  const auto outside_rms = [&](const ResidualResult& r) {
    double sum = 0.0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < clean.size(); ++i) {
      if (clean.time[i] >= from - 0.05 && clean.time[i] < to + 0.05) continue;
      sum += std::pow(clean.force[i] - r.predicted_after[i], 2);
      ++n;
    }
    return std::sqrt(sum / static_cast<double>(n));
  };
  const double clean_rms = outside_rms(reference);
  std::printf("outside the jump: unfaulted %.4g N, robust %.4g N, least squares %.4g N\n", clean_rms,
              outside_rms(robust), outside_rms(plain));
  EXPECT_LT(outside_rms(robust), 1.1 * clean_rms) << residual_summary({faulted}, robust);
  EXPECT_GT(outside_rms(plain), 1.5 * clean_rms) << residual_summary({faulted}, plain);
  EXPECT_GE(robust.robust_refits, 1);
  EXPECT_EQ(plain.robust_refits, 0);
  // Least squares reports the span all the same: it is what its fit could not explain.
  ASSERT_FALSE(plain.down_weighted.empty());
  EXPECT_LE(plain.down_weighted[0].start_s, from + 0.05);
  EXPECT_EQ(robust.accepted, reference.accepted) << residual_summary({faulted}, robust);
  ASSERT_FALSE(robust.down_weighted.empty());
  EXPECT_LE(robust.down_weighted[0].start_s, from + 0.05);
  EXPECT_GE(robust.down_weighted[0].end_s, to - 0.05);
  const auto json = nlohmann::json::parse(residual_json(robust));
  EXPECT_EQ(json["robust"]["spans"].size(), robust.down_weighted.size());
  EXPECT_EQ(json["robust"]["base_refits"], robust.robust_refits);
}

}  // namespace

