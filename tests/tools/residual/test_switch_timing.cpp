#include "tools/residual/switch_timing.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "model/effects/coil_lag.hpp"
#include "model/observer.hpp"
#include "record/run_gaps.hpp"

namespace {

using namespace mrd::tools;

constexpr double kPeriod = 1e-3;  // [s], the logger's
constexpr int kFine = 10;         // the rig's steps per logged row
constexpr double kNoise = 2.0;    // [N] RMS, the load cell's

mrd::model::DamperModel lagged_damper() {
  mrd::model::DamperModel m;
  m.effects.get<mrd::model::CoilLagEffect>() = {.enabled = true, .time_constant = 10e-3};
  return m;
}

constexpr int kRows = 2000;

// What the load cell and the LVDT saw at one of the rig's steps.
struct RigSample {
  double t, x, v, current, force;
};

// The damper stepped ten times per row, with the load cell's noise, its current switching between
// 0 and 1 A every 30-70 ms (from 0 A) at a step of the rig's own (or on a row, `on_rows`).
// `phases` gets each switch's true phase: the share of the row's period before the switch took
// effect (the rig's step holds its command over the period that ends at it).
std::vector<RigSample> rig_steps(bool on_rows, std::vector<double>& phases) {
  const mrd::model::DamperModel damper = lagged_damper();
  mrd::model::ObserverSettings settings;
  settings.sample_period = kPeriod / kFine;
  mrd::model::Observer rig(damper, settings);
  std::mt19937 rng(7);
  std::mt19937 noise_rng(11);
  std::uniform_int_distribution<int> dwell(30 * kFine, 70 * kFine);
  std::normal_distribution<double> load_cell(0.0, kNoise);
  std::vector<RigSample> steps;
  double command = 0.0;
  int next_switch = dwell(rng);
  for (int j = 0; j < kRows * kFine; ++j) {
    if (j == next_switch) {
      // On a row: the rig's step just after a row, whose command holds over the whole period
      // up to the next row (phase 0, as the observer takes a logged step).
      if (on_rows) next_switch += (kFine + 1 - next_switch % kFine) % kFine;
      if (j == next_switch) {
        command = 1.0 - command;
        const int row = (j + kFine - 1) / kFine;
        phases.push_back(static_cast<double>(j - 1 - kFine * (row - 1)) / kFine);
        next_switch = j + dwell(rng);
      }
    }
    const double t = j * kPeriod / kFine;
    const double w = 2.0 * std::numbers::pi * 2.0;
    const double x = 0.02 * std::sin(w * t), v = 0.02 * w * std::cos(w * t);
    const double force = rig.step({.displacement = x, .velocity = v, .coil_current = command}).force;
    steps.push_back({t, x, v, command, force + load_cell(noise_rng)});
  }
  return steps;
}

FitSeries empty_series(const char* name) {
  FitSeries s;
  s.sample_period = kPeriod;
  s.run_periods = {kPeriod};
  s.run_starts = {0};
  s.run_names = {name};
  return s;
}

void append(FitSeries& s, const RigSample& sample) {
  s.time.push_back(sample.t);
  s.displacement.push_back(sample.x);
  s.velocity.push_back(sample.v);
  s.current.push_back(sample.current);
  s.force.push_back(sample.force);
  s.role.push_back(SampleRole::kFitting);
}

// The rig written at every tenth step as a logger writes it: the current it held at the row.
FitSeries logged_run(bool on_rows, std::vector<double>& phases) {
  FitSeries s = empty_series("logged");
  const std::vector<RigSample> steps = rig_steps(on_rows, phases);
  for (std::size_t j = 0; j < steps.size(); j += kFine) append(s, steps[j]);
  return s;
}

// The rig logged unevenly: row k sampled at the rig's step up to `jitter` of a period off its grid
// time, and read as mrd-residual reads it (record::fill_gaps keeps the recorded times). The
// default damper's sign knee is far shorter than a period, so a reversal's force is a step
// between two samples: the rows beside each reversal are set aside, as in the runs above.
FitSeries jittered_run(double jitter, std::vector<double>& phases) {
  const std::vector<RigSample> steps = rig_steps(false, phases);
  std::mt19937 rng(3);
  const int reach = static_cast<int>(std::lround(jitter * kFine));
  std::uniform_int_distribution<int> wander(-reach, reach);
  std::vector<RigSample> samples;
  int previous = -1;
  for (int k = 0; k < kRows; ++k) {
    previous = std::clamp(k * kFine + wander(rng), previous + 1, kRows * kFine - 1);
    samples.push_back(steps[static_cast<std::size_t>(previous)]);
  }
  mrd::record::RecordedRun logged;
  for (const RigSample& sample : samples) {
    logged.time.push_back(sample.t);
    logged.displacement.push_back(sample.x);
    logged.velocity.push_back(sample.v);
    logged.coil.push_back(sample.current);
    logged.force.push_back(sample.force);
  }
  logged.sample_rate = 1.0 / kPeriod;
  const mrd::record::GapFilledRun read = mrd::record::fill_gaps(logged, mrd::record::UnevenTimes::kKeep);
  FitSeries s = empty_series("jittered");
  s.run_timing = {read.timing};
  for (std::size_t k = 0; k < read.run.size(); ++k)
    append(s, {read.run.time[k], read.run.displacement[k], read.run.velocity[k], read.run.coil[k], read.run.force[k]});
  for (std::size_t k = 1; k < s.size(); ++k)
    if (s.velocity[k] * s.velocity[k - 1] <= 0.0)
      for (std::size_t r = k > 2 ? k - 2 : 0; r < std::min(s.size(), k + 2); ++r) s.role[r] = SampleRole::kExcluded;
  return s;
}

TEST(SwitchTiming, TheRowsWhereTheCurrentStepsAndARunsFirstRow) {
  FitSeries s;
  s.run_starts = {0, 6};
  s.run_periods = {kPeriod, kPeriod};
  s.current = {1.0, 1.0, 0.0, 0.0, 0.05, 1.0, /* second run: one current */ 0.5, 0.5, 0.5};
  s.role.assign(s.current.size(), SampleRole::kFitting);
  EXPECT_EQ(current_steps(s, 0.1), (std::vector<std::size_t>{0, 2, 5}));
}

// The switches fell between the rows: taken at their rows the model errs for a lag's time after
// each; timed from the force after them, the phases are the rig's to a few hundredths of a
// period, and the error falls to a few per cent of what it was.
TEST(SwitchTiming, StepsBetweenTheRowsAreTimedFromTheForceAfterThem) {
  std::vector<double> truth;
  FitSeries s = logged_run(false, truth);
  const std::vector<std::size_t> rows = current_steps(s, 0.1);
  ASSERT_EQ(rows.size(), truth.size());
  ASSERT_GT(truth.size(), 25u);
  const SwitchTiming t = time_current_steps(lagged_damper(), s);
  ASSERT_TRUE(t.applied);
  EXPECT_EQ(t.steps, rows.size());
  // What is left is the blend's own error, O((T / tau)^2) of each step's force.
  EXPECT_LT(t.rms_after, 0.03 * t.rms_before) << t.rms_before << " -> " << t.rms_after;
  double squares = 0.0;
  for (std::size_t j = 0; j < truth.size(); ++j) {
    const std::size_t k = rows[j];
    const double before = s.current[k - 1] < 0.5 ? 0.0 : 1.0;  // the row before is never a switch
    const double after = 1.0 - before;
    const double phase = (s.current[k] - after) / (before - after);
    squares += (phase - truth[j]) * (phase - truth[j]);
  }
  EXPECT_LT(std::sqrt(squares / static_cast<double>(truth.size())), 0.03);
}

// Switches on the rows: the logged current is what the rig held, and nothing is written (what
// timing would buy there is the rates' discretisation, far under the noise).
TEST(SwitchTiming, StepsOnTheRowsAreLeftAsLogged) {
  std::vector<double> truth;
  FitSeries s = logged_run(true, truth);
  const std::vector<double> logged = s.current;
  const SwitchTiming t = time_current_steps(lagged_damper(), s);
  EXPECT_GT(t.steps, 25u);
  EXPECT_FALSE(t.applied) << t.rms_before << " -> " << t.rms_after << ", median phase " << t.median_phase;
  EXPECT_EQ(s.current, logged);
}

// Logged with 30 % jitter and kept at the recorded times, each row stepped by its own interval:
// no force is interpolated, each switch falls within one row as on an even run, and timing takes
// the error down as far as there (1.5 % of before; on the even grid, where the interpolation
// made each switch a ramp over up to three rows, it stopped at 9.8 %). Stepped a period a row
// instead, the same rows leave 20 times as much (175 N against 8.8 N).
TEST(SwitchTiming, AJitteredRunAtItsRecordedTimesIsTimedLikeAnEvenOne) {
  std::vector<double> truth;
  FitSeries s = jittered_run(0.3, truth);
  ASSERT_EQ(s.run_timing, std::vector<mrd::record::RunTiming>{mrd::record::RunTiming::kRecorded});
  const SwitchTiming t = time_current_steps(lagged_damper(), s);
  ASSERT_TRUE(t.applied);
  EXPECT_EQ(t.steps, truth.size());
  EXPECT_LT(t.rms_after, 0.02 * t.rms_before) << t.rms_before << " -> " << t.rms_after;
  std::vector<double> unused;
  FitSeries counted = jittered_run(0.3, unused);
  counted.run_timing = {mrd::record::RunTiming::kEven};
  const SwitchTiming c = time_current_steps(lagged_damper(), counted);
  EXPECT_GT(c.rms_after, 10.0 * t.rms_after) << c.rms_before << " -> " << c.rms_after;
}

}  // namespace
