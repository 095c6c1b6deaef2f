// The series the residual analysis fits: units, the held-out blocks, averaging down, the
// offline velocity, and clear errors for runs it cannot use.
#include "tools/residual/fit_series.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <numeric>

#include "record/csv.hpp"
#include "tools/replay/zero_phase_velocity.hpp"

namespace {

using namespace mrd::tools;

mrd::record::RecordedRun sine_run(double rate, double seconds, bool with_velocity) {
  mrd::record::RecordedRun run;
  run.name = "sine.csv";
  run.sample_rate = rate;
  const auto n = static_cast<std::size_t>(rate * seconds);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) / rate;
    run.time.push_back(t);
    run.displacement.push_back(0.02 * std::sin(2.0 * std::numbers::pi * t));
    run.coil.push_back(0.5);
    run.force.push_back(1000.0 * std::cos(2.0 * std::numbers::pi * t));
    if (with_velocity) run.velocity.push_back(0.02 * 2.0 * std::numbers::pi * std::cos(2.0 * std::numbers::pi * t));
  }
  return run;
}

TEST(FitSeries, HalfOfTheBlocksValidateAndEveryRunStartsAgain) {
  const FitSeries s = make_fit_series({sine_run(1000, 6, true), sine_run(200, 6, true)}, {});
  ASSERT_EQ(s.size(), 7200u);
  EXPECT_EQ(s.run_starts, (std::vector<std::size_t>{0, 6000}));
  EXPECT_DOUBLE_EQ(s.run_periods[0], 1e-3);
  EXPECT_DOUBLE_EQ(s.run_periods[1], 5e-3);
  EXPECT_DOUBLE_EQ(s.sample_period, 1e-3);
  const auto held_out = std::accumulate(s.validation.begin(), s.validation.begin() + 6000, 0);
  EXPECT_EQ(held_out, 3000);
  // Not alternate blocks: with 24 blocks a 1 s period would see only some phases in each half.
  int changes = 0;
  for (std::size_t i = 1; i < 6000; ++i) changes += s.validation[i] != s.validation[i - 1];
  EXPECT_LT(changes, 23);
}

TEST(FitSeries, DecimationPicksSamplesAndKeepsEachRunAboveTheMinimumRate) {
  const FitSeries s = make_fit_series({sine_run(1000, 6, true), sine_run(200, 6, true)}, {});
  const FitSeries d = decimate(s, 4, 200.0);
  EXPECT_EQ(d.run_starts, (std::vector<std::size_t>{0, 1500}));
  EXPECT_DOUBLE_EQ(d.run_periods[0], 4e-3);
  EXPECT_DOUBLE_EQ(d.run_periods[1], 5e-3);  // 200 Hz cannot go lower
  EXPECT_EQ(d.size(), 1500u + 1200u);
  EXPECT_EQ(d.force[1], s.force[6]);  // the middle of samples 4..7
  EXPECT_EQ(decimation_factor(s, 1000), 8u);
}

TEST(FitSeries, SpreadWindowsStayInsideOneRunEachAndCoverTheSeriesEvenly) {
  const FitSeries s = make_fit_series({sine_run(1000, 30, true), sine_run(200, 30, true)}, {});  // 30,000 + 6,000
  EXPECT_EQ(spread_windows(s, s.size()).size(), s.size());  // short enough: the series itself
  const FitSeries w = spread_windows(s, 8000, 8);
  ASSERT_EQ(w.run_starts.size(), 8u);
  EXPECT_EQ(w.size(), 8000u);
  // Window centres at 1/16, 3/16, ... of 36,000 samples: only the last falls in the 200 Hz run.
  EXPECT_EQ(w.run_periods, (std::vector<double>{1e-3, 1e-3, 1e-3, 1e-3, 1e-3, 1e-3, 1e-3, 5e-3}));
  EXPECT_DOUBLE_EQ(w.sample_period, 1e-3);
  for (std::size_t r = 0; r < 8; ++r) EXPECT_EQ(w.run_starts[r], r * 1000);
  // Each window is a stretch of its source: the first starts 1,750 samples in (t = 1.75 s).
  EXPECT_DOUBLE_EQ(w.displacement[0], s.displacement[1750]);
  EXPECT_DOUBLE_EQ(w.displacement[999], s.displacement[2749]);
  EXPECT_EQ(w.validation[0], s.validation[1750]);
  // The last window's centre, sample 33,750, lies 3,750 into the second run.
  EXPECT_DOUBLE_EQ(w.force[7000], s.force[30000 + 3250]);
  // A window that would straddle the runs' boundary moves back into its centre's run: the
  // seventh of 2,000 samples around 29,250 ends at the first run's last sample.
  const FitSeries wide = spread_windows(s, 16000, 8);
  EXPECT_DOUBLE_EQ(wide.force[13999], s.force[29999]);
  EXPECT_DOUBLE_EQ(wide.force[12000], s.force[28000]);
}

TEST(FitSeries, VelocityFromTheDisplacementWhenTheRunHasNone) {
  const FitSeries s = make_fit_series({sine_run(1000, 6, false)}, {});
  double worst = 0.0;
  for (std::size_t i = 1000; i < 5000; ++i) {
    const double t = static_cast<double>(i) / 1000.0;
    worst = std::max(worst, std::fabs(s.velocity[i] - 0.04 * std::numbers::pi * std::cos(2.0 * std::numbers::pi * t)));
  }
  EXPECT_LT(worst, 2e-3 * 0.04 * std::numbers::pi);  // 0.2 % of the amplitude, no phase lag
  ASSERT_EQ(s.notes.size(), 1u);
  EXPECT_NE(s.notes[0].find("sine.csv: velocity from the displacement, zero-phase low-pass at 6.1"), std::string::npos)
      << s.notes[0];
}

TEST(ZeroPhaseVelocity, CutoffFollowsTheMotion) {
  const mrd::record::RecordedRun run = sine_run(1000, 8, false);
  // Five times 1.22 Hz: 4096 samples give bins of 0.244 Hz, and the Hann window spreads the
  // 1 Hz line so that 99 % of the power is reached at the fifth bin.
  EXPECT_NEAR(motion_velocity_cutoff(run.displacement, 1000.0), 6.10, 0.01);
  mrd::record::RecordedRun fast = sine_run(1000, 8, false);
  for (std::size_t i = 0; i < fast.size(); ++i) fast.displacement[i] = 1e-3 * std::sin(2.0 * std::numbers::pi * 30.0 * fast.time[i]);
  EXPECT_NEAR(motion_velocity_cutoff(fast.displacement, 1000.0), 150.0, 5.0);
}

TEST(FitSeries, RunsItCannotUseAreNamedWithTheReason) {
  mrd::record::RecordedRun no_force = sine_run(1000, 1, true);
  no_force.force.clear();
  EXPECT_THROW(
      {
        try {
          (void)make_fit_series({no_force}, {});
        } catch (const mrd::record::InputError& e) {
          EXPECT_STREQ(e.what(), "sine.csv: the run has no force column; a residual needs the measured force");
          throw;
        }
      },
      mrd::record::InputError);
  mrd::record::RecordedRun voltage = sine_run(1000, 1, true);
  voltage.coil_signal = mrd::record::CoilSignal::kCommandVoltage;
  EXPECT_THROW((void)make_fit_series({voltage}, {}), mrd::record::InputError);
  FitSeriesOptions with_gain;
  with_gain.amps_per_volt = 0.5;
  EXPECT_DOUBLE_EQ(make_fit_series({voltage}, with_gain).current[0], 0.25);
  EXPECT_THROW((void)make_fit_series({}, {}), mrd::record::InputError);
}

}  // namespace
