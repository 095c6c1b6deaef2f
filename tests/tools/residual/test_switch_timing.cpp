#include "tools/residual/switch_timing.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "model/effects/coil_lag.hpp"
#include "model/observer.hpp"

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

// A run of the damper stepped ten times per row, with the load cell's noise, its current switching between 0 and 1 A every
// 30-70 ms (from 0 A) at a step of the rig's own (or on a row, `on_rows`), written at every tenth step as a
// logger writes it: the current it held at the row. `phases` gets each switch's true phase: the
// share of the row's period before the switch took effect (the rig's step holds its command over
// the period that ends at it).
FitSeries logged_run(bool on_rows, std::vector<double>& phases) {
  const mrd::model::DamperModel damper = lagged_damper();
  mrd::model::ObserverSettings settings;
  settings.sample_period = kPeriod / kFine;
  mrd::model::Observer rig(damper, settings);
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> dwell(30 * kFine, 70 * kFine);
  std::normal_distribution<double> load_cell(0.0, kNoise);
  FitSeries s;
  s.sample_period = kPeriod;
  s.run_periods = {kPeriod};
  s.run_starts = {0};
  s.run_names = {"logged"};
  double command = 0.0;
  int next_switch = dwell(rng);
  const int rows = 2000;
  for (int j = 0; j < rows * kFine; ++j) {
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
    if (j % kFine != 0) continue;
    s.time.push_back(t);
    s.displacement.push_back(x);
    s.velocity.push_back(v);
    s.current.push_back(command);
    s.force.push_back(force + load_cell(rng));
    s.role.push_back(SampleRole::kFitting);
  }
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

}  // namespace
