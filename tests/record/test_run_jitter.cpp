// Timestamps that jitter (a USB logger's uneven steps) against ones a time column rounded: the
// first are resampled onto the even grid, the second left as they are.
#include "record/run_jitter.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numbers>

#include "record/run_gaps.hpp"

namespace {

using mrd::record::RecordedRun;

// Deterministic uniform numbers in [-1, 1] (a generator that shares nothing with the code).
struct Uniform {
  std::uint32_t state = 2026u;
  double operator()() {
    state = state * 1664525u + 1013904223u;
    return static_cast<double>(state >> 8) / 8388608.0 - 1.0;
  }
};

// A damper force with a yield knee: it turns over within a few milliseconds at each reversal,
// where a sample taken 0.3 ms off its grid time is up to 50 N off.
double force_at(double t) {
  const double v = 0.02 * 2.0 * std::numbers::pi * std::cos(2.0 * std::numbers::pi * t);
  return 1000.0 * std::tanh(v / 0.005) + 2000.0 * v;
}

// 2 s at `rate`, each sample taken `jitter` periods (uniform, +-) off its grid time; the times
// written at `resolution` [s].
RecordedRun sampled(double rate, double jitter, double resolution) {
  RecordedRun run;
  run.name = "jitter.csv";
  Uniform u;
  for (int k = 0; k < static_cast<int>(2.0 * rate); ++k) {
    const double taken = (k + jitter * u()) / rate;
    const double t = resolution > 0.0 ? std::round(taken / resolution) * resolution : taken;
    run.time.push_back(t);
    run.displacement.push_back(0.02 * std::sin(2.0 * std::numbers::pi * taken));
    run.coil.push_back(0.5);
    run.force.push_back(force_at(taken));
  }
  run.sample_rate = mrd::record::nominal_sample_rate(run.time);
  return run;
}

double rms_force_error(const RecordedRun& run) {
  double sum = 0.0;
  for (std::size_t i = 0; i < run.size(); ++i) sum += std::pow(run.force[i] - force_at(run.time[i]), 2);
  return std::sqrt(sum / static_cast<double>(run.size()));
}

TEST(RunJitter, ARoundedTimeColumnIsNotJitterButAnUnevenLoggerIs) {
  // The Dyke file: 3004.8 Hz written to 0.1 ms wanders up to its resolution and no further.
  const auto dyke = mrd::record::measure_jitter(sampled(3004.8, 0.0, 1e-4).time);
  EXPECT_NEAR(dyke.resolution, 1e-4, 1e-9);
  EXPECT_LE(dyke.wander, dyke.resolution);
  EXPECT_FALSE(dyke.uneven(1.0 / 3004.8));
  // An even logger written to the microsecond.
  EXPECT_FALSE(mrd::record::measure_jitter(sampled(1000.0, 0.0, 1e-6).time).uneven(1e-3));
  // 10 % and 30 % of a period, to the microsecond; 2 % still, but not 0.5 %.
  for (const double jitter : {0.3, 0.1, 0.02}) {
    const auto j = mrd::record::measure_jitter(sampled(1000.0, jitter, 1e-6).time);
    EXPECT_TRUE(j.uneven(1e-3)) << jitter;
    EXPECT_GT(j.wander, 0.5 * jitter * 1e-3) << jitter;
  }
  EXPECT_FALSE(mrd::record::measure_jitter(sampled(1000.0, 0.005, 1e-6).time).uneven(1e-3));
}

TEST(RunJitter, AJitteredRunResampledIsTheEvenRunAgain) {
  const RecordedRun even = sampled(1000.0, 0.0, 1e-6);
  for (const double jitter : {0.1, 0.3}) {
    const RecordedRun uneven = sampled(1000.0, jitter, 1e-6);
    // As recorded, the sample k taken as if at k / rate: the knee makes that tens of newtons.
    RecordedRun as_if_even = uneven;
    as_if_even.time = even.time;
    const double unresampled = rms_force_error(as_if_even);
    EXPECT_GT(unresampled, 1.0 * jitter / 0.1) << jitter;
    const mrd::record::GapFilledRun resampled = mrd::record::fill_gaps(uneven);
    EXPECT_TRUE(resampled.gaps.empty()) << jitter;
    ASSERT_GE(resampled.run.size(), even.size() - 1);
    for (std::size_t k = 1; k < resampled.run.size(); ++k)
      ASSERT_NEAR(resampled.run.time[k] - resampled.run.time[k - 1], 1.0 / uneven.sample_rate, 1e-12);
    // On the grid, the force is the knee's to a linear interpolation's error.
    EXPECT_LT(rms_force_error(resampled.run), 0.2 * unresampled) << jitter;
    EXPECT_NE(resampled.run.notes.back().find("resampled"), std::string::npos);
    EXPECT_EQ(resampled.timing, mrd::record::RunTiming::kResampled) << jitter;
  }
  EXPECT_EQ(mrd::record::fill_gaps(even).timing, mrd::record::RunTiming::kEven);
}

TEST(RunJitter, AGapInAJitteredRunIsFilledAndFlagged) {
  RecordedRun run = sampled(1000.0, 0.3, 1e-6);
  // 100 ms lost from 1 s on.
  const auto from = static_cast<std::ptrdiff_t>(1000), to = static_cast<std::ptrdiff_t>(1100);
  for (std::vector<double>* c : {&run.time, &run.displacement, &run.coil, &run.force}) c->erase(c->begin() + from, c->begin() + to);
  run.sample_rate = mrd::record::nominal_sample_rate(run.time);
  run.set_aside_rows.push_back({"duplicate", 7, 1500, ""});
  const mrd::record::GapFilledRun filled = mrd::record::fill_gaps(run);
  ASSERT_EQ(filled.gaps.size(), 1u);
  const double first = filled.run.time[filled.gaps[0].first], last = filled.run.time[filled.gaps[0].second];
  EXPECT_NEAR(first, 1.0, 2e-3);
  EXPECT_NEAR(last, 1.1, 2e-3);
  std::size_t flagged = 0;
  for (const auto f : filled.filled) flagged += f;
  EXPECT_EQ(flagged, filled.gaps[0].second - filled.gaps[0].first + 1);
  // The row set aside before the recorded sample 1500 (1.6 s) points at the grid's 1.6 s.
  EXPECT_NEAR(filled.run.time[filled.run.set_aside_rows[0].next_sample], run.time[1500], 1e-3);
}

// Kept at its recorded times (for a tool that steps each sample by its own interval): every
// logged sample stays as it was, force included, and only the gap gets samples, at the nominal
// period and flagged; a run without a gap comes back whole.
TEST(RunJitter, AJitteredRunKeptAtItsTimesFillsOnlyItsGap) {
  const RecordedRun whole = sampled(1000.0, 0.3, 1e-6);
  const mrd::record::GapFilledRun kept_whole = mrd::record::fill_gaps(whole, mrd::record::UnevenTimes::kKeep);
  EXPECT_EQ(kept_whole.timing, mrd::record::RunTiming::kRecorded);
  EXPECT_EQ(kept_whole.run.time, whole.time);
  EXPECT_EQ(kept_whole.run.force, whole.force);
  EXPECT_TRUE(kept_whole.gaps.empty());
  EXPECT_NE(kept_whole.run.notes.back().find("recorded time"), std::string::npos);

  RecordedRun run = whole;
  const auto from = static_cast<std::ptrdiff_t>(1000), to = static_cast<std::ptrdiff_t>(1100);
  for (std::vector<double>* c : {&run.time, &run.displacement, &run.coil, &run.force}) c->erase(c->begin() + from, c->begin() + to);
  run.set_aside_rows.push_back({"duplicate", 7, 1500, ""});
  const mrd::record::GapFilledRun kept = mrd::record::fill_gaps(run, mrd::record::UnevenTimes::kKeep);
  // The row set aside before the recorded sample 1500 points at that same sample.
  EXPECT_EQ(kept.run.time[kept.run.set_aside_rows[0].next_sample], run.time[1500]);
  EXPECT_GT(kept.gap_step, 1.5e-3);
  ASSERT_EQ(kept.gaps.size(), 1u);
  const auto [first, last] = kept.gaps[0];
  EXPECT_EQ(first, 1000u);
  EXPECT_NEAR(static_cast<double>(last - first + 1), 100.0, 1.0);
  std::vector<double> logged_times;
  for (std::size_t i = 0; i < kept.run.size(); ++i) {
    if (kept.filled[i] != 0) {
      ASSERT_NEAR(kept.run.time[i] - kept.run.time[i - 1], 1e-3, 2e-5) << i;
      continue;
    }
    logged_times.push_back(kept.run.time[i]);
  }
  EXPECT_EQ(logged_times, run.time);
}

}  // namespace
