// The series the residual analysis fits: units, the held-out blocks, averaging down, the
// offline velocity, and clear errors for runs it cannot use.
#include "tools/residual/fit_series.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include <random>

#include "record/csv.hpp"
#include "tools/residual/residual_structure.hpp"
#include "tools/signal/zero_phase_velocity.hpp"

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
  const auto held_out = std::count(s.role.begin(), s.role.begin() + 6000, SampleRole::kValidation);
  EXPECT_EQ(held_out, 3000);
  // Not alternate blocks: with 24 blocks a 1 s period would see only some phases in each half.
  int changes = 0;
  for (std::size_t i = 1; i < 6000; ++i) changes += s.role[i] != s.role[i - 1];
  EXPECT_LT(changes, 23);
}

// Two runs, a 1 kHz one with a white residual and a 200 Hz one whose residual is a 20 Hz line:
// each run's spectrum is read at its own period, so the line is found at 20 Hz (the first run's
// spectrum alone has none; both at 1 kHz would put it at 100 Hz).
TEST(FitSeries, TheResidualSpectrumOfEachRunIsReadAtItsOwnRate) {
  const FitSeries s = make_fit_series({sine_run(1000, 6, true), sine_run(200, 6, true)}, {});
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0.0, 1.0);
  std::vector<double> residual(s.size());
  for (std::size_t i = 0; i < 6000; ++i) residual[i] = noise(rng);
  for (std::size_t i = 6000; i < s.size(); ++i)
    residual[i] = 10.0 * std::sin(2.0 * std::numbers::pi * 20.0 * 5e-3 * static_cast<double>(i - 6000)) + noise(rng);
  const ResidualStructure r = analyse_residual(s, residual);
  EXPECT_NEAR(r.peak_frequency, 20.0, 0.5);
  EXPECT_GT(r.peak_power_share, 0.8);
  EXPECT_NEAR(r.motion_frequency, 1.0, 0.2);  // that run's own 1 Hz motion
}

// The plots' time axis: a 6 s run at 200 Hz after a 6 s run at 1 kHz spans 6 s, not 1.2 s of
// sample index x the shorter period.
TEST(FitSeries, EachRunKeepsItsOwnSecondsOnThePlotsTimeAxis) {
  const FitSeries s = make_fit_series({sine_run(1000, 6, true), sine_run(200, 6, true)}, {});
  const std::vector<double> t = series_time(s);
  ASSERT_EQ(t.size(), s.size());
  EXPECT_DOUBLE_EQ(t[0], 0.0);
  EXPECT_NEAR(t[5999], 5.999, 1e-12);
  EXPECT_NEAR(t[6000], 6.0, 1e-12);  // a period after the first run's last sample
  EXPECT_NEAR(t.back() - t[6000], 5.995, 1e-12);
  EXPECT_NEAR(t[6001] - t[6000], 5e-3, 1e-12);
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

TEST(FitSeries, RunOpeningsShareTheSamplesAndStartWhereEachRunStarts) {
  // 2,000 + 30,000 + 6,000 samples.
  const FitSeries s =
      make_fit_series({sine_run(200, 10, true), sine_run(1000, 30, true), sine_run(1000, 6, true)}, {});
  EXPECT_EQ(run_openings(s, s.size()).size(), s.size());
  // 9,000 in equal shares of 3,000: the first run whole, its 1,000 left to the other two.
  const FitSeries open = run_openings(s, 9000);
  ASSERT_EQ(open.size(), 9000u);
  EXPECT_EQ(open.run_starts, (std::vector<std::size_t>{0, 2000, 5500}));
  EXPECT_EQ(open.run_periods, (std::vector<double>{5e-3, 1e-3, 1e-3}));
  EXPECT_DOUBLE_EQ(open.sample_period, 1e-3);
  EXPECT_DOUBLE_EQ(open.force[1999], s.force[1999]);
  EXPECT_DOUBLE_EQ(open.force[2000], s.force[2000]);              // the second run's first sample
  EXPECT_DOUBLE_EQ(open.displacement[5499], s.displacement[5499]);
  EXPECT_DOUBLE_EQ(open.displacement[5500], s.displacement[32000]);  // the third run's first
  EXPECT_EQ(open.role[8999], s.role[32000 + 3499]);
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

// Samples taken up to 30 % of a period off their grid times (a USB logger's) stay at their
// times, force unmoved; the velocity is the zero-phase filter's on the even grid, read back at
// each sample's time: 0.08 % of the amplitude at worst. Filtered as if the samples were even,
// the same displacement gives 0.25 %.
TEST(FitSeries, SamplesTakenUnevenlyKeepTheirTimesAndTheirVelocity) {
  mrd::record::RecordedRun run = sine_run(1000, 6, false);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> off(-0.3e-3, 0.3e-3);
  for (std::size_t i = 0; i < run.size(); ++i) {
    const double t = run.time[i] + off(rng);
    run.time[i] = t;
    run.displacement[i] = 0.02 * std::sin(2.0 * std::numbers::pi * t);
    run.force[i] = 1000.0 * std::cos(2.0 * std::numbers::pi * t);
  }
  FitSeriesOptions options;
  options.velocity_cutoff = 6.0;  // the same cutoff for both below
  const FitSeries s = make_fit_series({run}, options);
  ASSERT_EQ(s.run_timing, std::vector<mrd::record::RunTiming>{mrd::record::RunTiming::kRecorded});
  EXPECT_EQ(s.time, run.time);
  EXPECT_EQ(s.force, run.force);
  const auto worst_velocity_error = [&](const std::vector<double>& v) {
    double worst = 0.0;
    for (std::size_t i = 1000; i < 5000; ++i)
      worst = std::max(worst, std::fabs(v[i] - 0.04 * std::numbers::pi * std::cos(2.0 * std::numbers::pi * run.time[i])));
    return worst;
  };
  EXPECT_LT(worst_velocity_error(s.velocity), 1e-3 * 0.04 * std::numbers::pi);
  const std::vector<double> as_if_even = zero_phase_velocity(run.displacement, 1000.0, 6.0);
  EXPECT_GT(worst_velocity_error(as_if_even), 2.0 * worst_velocity_error(s.velocity));
}

// A record that starts and ends in motion keeps its velocity at the ends: the filter's passes
// run in on the pads, not on the record. Measured: within 0.1-1.0 % of the amplitude in the first
// and last 0.5 s; with passes started at rest, up to the whole amplitude (the sign of the last
// reversal could flip); with a plain odd reflection (curvature flipped), 10 %.
TEST(ZeroPhaseVelocity, TheRecordsEdgesKeepTheirVelocity) {
  for (const double phase : {0.0, 1.0, 2.5}) {
    std::vector<double> x;
    for (std::size_t i = 0; i < 6000; ++i) x.push_back(0.02 * std::sin(2.0 * std::numbers::pi * (static_cast<double>(i) / 1000.0) + phase));
    const std::vector<double> v = zero_phase_velocity(x, 1000.0, 6.1);
    const double amplitude = 0.04 * std::numbers::pi;
    double edge = 0.0, inside = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
      const double error = std::fabs(v[i] - amplitude * std::cos(2.0 * std::numbers::pi * (static_cast<double>(i) / 1000.0) + phase));
      (i < 500 || i >= 5500 ? edge : inside) = std::max(i < 500 || i >= 5500 ? edge : inside, error);
    }
    EXPECT_LT(edge, 0.015 * amplitude) << "phase " << phase;
    EXPECT_LT(inside, 2e-3 * amplitude) << "phase " << phase;
  }
}

// A logging gap costs only the gap: its samples are filled at the nominal period and set aside,
// the rate is the logger's, and the velocity on either side never runs across its straight bridge.
TEST(FitSeries, ALoggingGapCostsOnlyTheGap) {
  mrd::record::RecordedRun run = sine_run(1000, 8, false);
  for (std::vector<double>* c : {&run.time, &run.displacement, &run.coil, &run.force})
    c->erase(c->begin() + 4000, c->begin() + 4300);  // 0.3 s lost
  run.sample_rate = mrd::record::nominal_sample_rate(run.time);
  EXPECT_DOUBLE_EQ(run.sample_rate, 1000.0);  // the gap is missing samples, not a slower logger
  const FitSeries s = make_fit_series({run}, {});
  ASSERT_EQ(s.size(), 8000u);
  EXPECT_DOUBLE_EQ(s.sample_period, 1e-3);
  ASSERT_EQ(s.screenings.size(), 1u);
  const Screening& screening = s.screenings[0].second;
  ASSERT_EQ(screening.spans.size(), 2u);
  EXPECT_EQ(screening.spans[0].reason, ScreenReason::kGap);
  // The filled samples and a margin of 5-6 ms (5 ms, rounded up) on either side, then the
  // settling until the rod has travelled 5 % of its stroke (0.02 sin 2 pi t from 0.01902 m at
  // 4.3 s down to 0.01702 m: 4.3380 s), nothing else.
  EXPECT_GE(screening.spans[0].first, 3994u);
  EXPECT_LE(screening.spans[0].first, 3995u);
  EXPECT_GE(screening.spans[0].last, 4304u);
  EXPECT_LE(screening.spans[0].last, 4305u);
  EXPECT_EQ(screening.spans[1].reason, ScreenReason::kSettling);
  EXPECT_EQ(screening.spans[1].first, 4300u);
  EXPECT_EQ(screening.spans[1].last, 4337u);
  EXPECT_LE(screening.excluded_samples, 344u);
  const double amplitude = 0.04 * std::numbers::pi;
  double worst = 0.0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s.role[i] == SampleRole::kExcluded) continue;
    const double t = static_cast<double>(i) / 1000.0;
    worst = std::max(worst, std::fabs(s.velocity[i] - amplitude * std::cos(2.0 * std::numbers::pi * t)));
  }
  EXPECT_LT(worst, 0.015 * amplitude);
  // Without screening the gap is set aside all the same, and the series says it was not screened.
  FitSeriesOptions unscreened;
  unscreened.screen = false;
  const FitSeries u = make_fit_series({run}, unscreened);
  EXPECT_FALSE(u.screened);
  ASSERT_EQ(u.screenings.size(), 1u);
  EXPECT_EQ(u.screenings[0].second.excluded_samples, screening.excluded_samples);
  EXPECT_TRUE(s.screened);
}

// Spans set aside may reach the record's ends: they take the chord's slope, and the filter runs
// on what lies between.
TEST(ZeroPhaseVelocity, UnmeasuredSpansAtTheRecordsEndsTakeTheChord) {
  std::vector<double> x, t;
  for (int i = 0; i < 1000; ++i) {
    t.push_back(i * 1e-3);
    x.push_back(0.01 * t.back());
  }
  std::vector<std::uint8_t> unmeasured(1000, 0);
  std::fill(unmeasured.begin(), unmeasured.begin() + 50, 1);
  std::fill(unmeasured.end() - 100, unmeasured.end(), 1);
  const std::vector<double> v = zero_phase_velocity_by_stretch(x, t, 1000.0, 5.0, unmeasured);
  ASSERT_EQ(v.size(), 1000u);
  for (const std::size_t i : {0u, 49u, 500u, 900u, 999u}) EXPECT_NEAR(v[i], 0.01, 1e-6) << i;
  EXPECT_EQ(zero_phase_velocity_by_stretch(x, t, 1000.0, 5.0, std::vector<std::uint8_t>(1000, 1)), std::vector<double>(1000, 0.01));
}

// A span whose displacement was faulted (an LVDT stuck at its stop for a third of a second) with
// motion measured on both sides: the motion is bridged between the two and filtered through, so
// the kept samples beside it keep their velocity, where a reversal's timing depends on it.
TEST(ZeroPhaseVelocity, ASpanWithMotionOnBothSidesIsBridgedNotSplit) {
  const double rate = 1000.0, amplitude = 0.02 * 2.0 * std::numbers::pi;
  std::vector<double> x, t;
  for (int i = 0; i < 8000; ++i) {
    t.push_back(i / rate);
    x.push_back(0.02 * std::sin(2.0 * std::numbers::pi * t.back()));
  }
  std::vector<std::uint8_t> unmeasured(x.size(), 0);
  const std::vector<double> whole = zero_phase_velocity_by_stretch(x, t, rate, 3.0, unmeasured);
  std::fill(unmeasured.begin() + 4100, unmeasured.begin() + 4470, 1);
  std::fill(x.begin() + 4100, x.begin() + 4470, 0.0199);  // the stuck reading, never used
  const std::vector<double> v = zero_phase_velocity_by_stretch(x, t, rate, 3.0, unmeasured);
  double worst = 0.0;
  for (int i = 3900; i < 4670; ++i)
    if (!unmeasured[i]) worst = std::max(worst, std::fabs(v[i] - whole[i]));
  EXPECT_LT(worst, 5e-3 * amplitude);  // 0.23 %; split into two padded stretches, 2 %
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

// The InputError's text when make_fit_series refuses `runs`, or "" when it takes them.
std::string refusal(const std::vector<mrd::record::RecordedRun>& runs, const FitSeriesOptions& options = {}) {
  try {
    (void)make_fit_series(runs, options);
    return "";
  } catch (const mrd::record::InputError& e) {
    return e.what();
  }
}

TEST(FitSeries, ARateNoRigLogsAtIsTheTimeColumnsUnitNotARun) {
  mrd::record::RecordedRun seconds_as_ms = sine_run(1000, 1, true);
  for (double& t : seconds_as_ms.time) t *= 1e3;
  seconds_as_ms.sample_rate = 1.0;  // at the bound: taken
  EXPECT_EQ(refusal({seconds_as_ms}), "");
  seconds_as_ms.sample_rate = 0.999;
  EXPECT_NE(refusal({seconds_as_ms}).find("sample rate 0.999 Hz is outside 1 Hz to 1e+06 Hz"), std::string::npos);
  mrd::record::RecordedRun fast = sine_run(1000, 1, true);
  fast.sample_rate = 1.001e6;
  EXPECT_NE(refusal({fast}).find("sample rate 1.001e+06 Hz"), std::string::npos);
}

// A load cell's noise on a still rod would be "explained" by any effect: no claim can come of it.
TEST(FitSeries, ARunWithoutMotionIsRefusedAndOneThatMovesIsTaken) {
  const auto with_motion = [](double amplitude) {
    mrd::record::RecordedRun run = sine_run(1000, 2, false);
    std::uint32_t state = 12345u;
    for (std::size_t i = 0; i < run.size(); ++i) {
      state = state * 1664525u + 1013904223u;  // white, +-1 um uniform: sigma 0.577 um
      const double noise = (static_cast<double>(state >> 8) / 16777216.0 - 0.5) * 2e-6;
      run.displacement[i] = 0.003 + amplitude * std::sin(2.0 * std::numbers::pi * run.time[i]) + noise;
    }
    return run;
  };
  // Unscreened: the screening would set the swinging force aside as implausible first.
  FitSeriesOptions unscreened;
  unscreened.screen = false;
  const std::string still = refusal({with_motion(0.0)}, unscreened);
  EXPECT_NE(still.find("sine.csv: the displacement spans"), std::string::npos) << still;
  EXPECT_NE(still.find("no damper motion to analyse"), std::string::npos) << still;
  EXPECT_NE(refusal({with_motion(0.0)}).find("(set aside: implausible 2000)"), std::string::npos);
  // 20 noise sigmas (11.5 um) is the bound: a 4 um sine is still, a 20 um one moves.
  EXPECT_NE(refusal({with_motion(4e-6)}, unscreened), "");
  EXPECT_EQ(refusal({with_motion(20e-6)}, unscreened), "");
  mrd::record::RecordedRun parked = sine_run(1000, 2, true);
  parked.displacement.assign(parked.size(), 0.003);
  parked.displacement.back() = 0.0030001;  // one sample off, the smallest step: no noise below it
  EXPECT_NE(refusal({parked}, unscreened).find("no damper motion"), std::string::npos);
}

TEST(FitSeries, TooFewSamplesLeftToFitSaysHowManyItNeedsAndWhy) {
  mrd::record::RecordedRun run = sine_run(1000, 1, true);
  // A rod stuck for all but 150 samples while the load cell swings (at the run's extreme: clipped).
  for (std::size_t i = 150; i < run.size(); ++i) run.displacement[i] = run.displacement[149];
  const std::string why = refusal({run});
  EXPECT_NE(why.find("sine.csv: the screening left "), std::string::npos) << why;
  EXPECT_NE(why.find("a fit needs at least 200 (set aside: clipped 8"), std::string::npos) << why;
  mrd::record::RecordedRun enough = sine_run(1000, 1, true);
  for (std::size_t i = 400; i < enough.size(); ++i) enough.displacement[i] = enough.displacement[399];
  EXPECT_EQ(refusal({enough}), "");
}

}  // namespace
