#include "tools/replay/replay.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "config/config_loader.hpp"
#include "tests/record/input_error_of.hpp"
#include "record/run_csv.hpp"
#include "record/run_csv_writer.hpp"
#include "tests/support/simulated_rig_run.hpp"

namespace {

using mrd::tools::force_error;
using mrd::record::RecordedRun;
using mrd::tools::replay;
using mrd::tools::ReplayOptions;
using mrd::tools::simulate_run;

ReplayOptions default_options() {
  ReplayOptions o;
  o.law = mrd::config::load_default_config().config.law;
  return o;
}

std::string error_of(const RecordedRun& run, const ReplayOptions& options) {
  return mrd::record::testing::input_error_of([&] { (void)replay(run, options); });
}

TEST(ForceError, DefinitionsOnAHandExample) {
  const std::vector<double> measured{0.0, 10.0, 20.0};
  const std::vector<double> predicted{1.0, 10.0, 17.0};  // residuals -1, 0, 3
  const auto e = force_error(measured, predicted);
  EXPECT_EQ(e.samples, 3u);
  EXPECT_DOUBLE_EQ(e.rms, std::sqrt(10.0 / 3.0));
  EXPECT_DOUBLE_EQ(e.max, 3.0);
  EXPECT_DOUBLE_EQ(e.mean, 2.0 / 3.0);
  EXPECT_DOUBLE_EQ(e.measured_range, 20.0);
  EXPECT_DOUBLE_EQ(e.nrmse, std::sqrt(10.0 / 3.0) / 20.0);
  EXPECT_TRUE(std::isnan(force_error(std::vector{5.0, 5.0}, std::vector{4.0, 6.0}).nrmse));
}

// The rig's plant runs the same physics as the observer, so a replay with the same model and
// the plant's velocity must reproduce its force: whatever error the replay itself adds shows.
TEST(Replay, SimulatedRunFromTheSameModelGivesZeroForceError) {
  auto options = default_options();
  const RecordedRun run = simulate_run(options.law.damper);
  options.use_recorded_velocity = true;
  const auto result = replay(run, options);
  ASSERT_TRUE(result.force);
  EXPECT_GT(result.force->measured_range, 1e4);  // a 50 kN class damper through minor loops
  EXPECT_LT(result.force->rms, 1e-9 * result.force->measured_range);
  EXPECT_LT(result.force->max, 1e-9 * result.force->measured_range);
  for (std::size_t i = 0; i < run.size(); ++i) ASSERT_NEAR(result.trace.B[i], run.B[i], 1e-12);
}

// A logging gap costs only the gap: the rate is the logger's, the loop steps through the gap on
// its bridge, and the samples after it are replayed as in the unbroken run (the zero-phase
// velocity never runs across its straight bridge).
TEST(Replay, ALoggingGapCostsOnlyTheGap) {
  auto options = default_options();
  const RecordedRun whole = simulate_run(options.law.damper);
  options.zero_phase_cutoff = 0.0;
  const auto unbroken = replay(whole, options);
  RecordedRun broken = whole;
  const std::size_t from = whole.size() / 2, to = from + whole.size() / 20;
  for (std::vector<double>* c : {&broken.time, &broken.displacement, &broken.coil, &broken.force, &broken.velocity, &broken.B})
    if (!c->empty()) c->erase(c->begin() + static_cast<std::ptrdiff_t>(from), c->begin() + static_cast<std::ptrdiff_t>(to));
  broken.sample_rate = mrd::record::nominal_sample_rate(broken.time);
  EXPECT_NEAR(broken.sample_rate, whole.sample_rate, 1e-6 * whole.sample_rate);
  const auto gapped = replay(broken, options);
  ASSERT_EQ(gapped.trace.predicted_force.size(), broken.size());
  // From 50 ms beside the gap on, the force is the unbroken run's to 0.1 % of its range.
  const auto margin = static_cast<std::size_t>(0.05 * whole.sample_rate);
  double worst = 0.0;
  for (std::size_t i = margin; i + margin < from; ++i)
    worst = std::max(worst, std::fabs(gapped.trace.predicted_force[i] - unbroken.trace.predicted_force[i]));
  for (std::size_t i = from + margin; i + margin < broken.size(); ++i) {
    const std::size_t j = i + (to - from);
    worst = std::max(worst, std::fabs(gapped.trace.predicted_force[i] - unbroken.trace.predicted_force[j]));
  }
  ASSERT_TRUE(unbroken.force);
  // Measured: 0.01 % of the force's range with the velocity's quintic bridge; 0.6 % with the
  // velocity split at the gap; without the filling, 43 %.
  EXPECT_LT(worst, 1e-3 * unbroken.force->measured_range);
}

TEST(Replay, AnotherModelGivesAnErrorTheTestWouldSee) {
  auto options = default_options();
  const RecordedRun run = simulate_run(options.law.damper);
  options.use_recorded_velocity = true;
  options.law.damper.fluid.viscosity *= 1.1;
  const auto result = replay(run, options);
  EXPECT_GT(result.force->nrmse, 1e-3);
}

TEST(Replay, SimulatedRunThroughTheOwnCsvFormatStillMatches) {
  auto options = default_options();
  const RecordedRun simulated = simulate_run(options.law.damper);
  const RecordedRun run =
      mrd::record::parse_run_csv(mrd::record::format_run_csv(simulated), "sim.csv");
  options.use_recorded_velocity = true;
  const auto result = replay(run, options);
  EXPECT_LT(result.force->nrmse, 1e-8);
}

// Without the velocity the observer filters the LVDT as the controller does; the filter's
// error at reversals (docs/MODEL.md) is what remains.
TEST(Replay, ControllersVelocityFilterAddsOnlyItsOwnError) {
  const auto options = default_options();
  const auto result = replay(simulate_run(options.law.damper), options);
  EXPECT_LT(result.force->nrmse, 0.02);
  EXPECT_GT(result.force->nrmse, 1e-6);  // it is a filter, not the truth
}

TEST(Replay, IsDeterministic) {
  const auto options = default_options();
  mrd::tools::SimulatedRunOptions noisy;
  noisy.lvdt_noise = 20e-6;
  const RecordedRun run = simulate_run(options.law.damper, noisy);
  const auto a = replay(run, options);
  const auto b = replay(run, options);
  EXPECT_EQ(a.trace.predicted_force, b.trace.predicted_force);
  EXPECT_EQ(a.trace.command_current, b.trace.command_current);
  EXPECT_EQ(a.trace.velocity, b.trace.velocity);
  EXPECT_EQ(a.force->rms, b.force->rms);
}

TEST(Replay, CommandIsTheControllersOwnClosedLoopWithinItsLimits) {
  const auto options = default_options();
  const RecordedRun run = simulate_run(options.law.damper);
  const auto result = replay(run, options);
  const auto& limits = options.law.limits;
  double highest = 0.0;
  for (std::size_t i = 0; i < run.size(); ++i) {
    const double c = result.trace.command_current[i];
    ASSERT_GE(c, limits.min_current);
    ASSERT_LE(c, limits.max_current);
    if (i > 0) {
      ASSERT_LE(std::fabs(c - result.trace.command_current[i - 1]),
                limits.slew_rate / run.sample_rate + 1e-12);
    }
    highest = std::max(highest, c);
  }
  // +-20 mm reaches Table 4's 0.4 A level (10..20 mm); the compensator asks for more than that.
  EXPECT_GE(highest, 0.4);
  EXPECT_DOUBLE_EQ(result.sample_period, 1e-3);
}

TEST(Replay, CommandVoltageTimesTheDriverGainIsTheCurrent) {
  auto options = default_options();
  const RecordedRun run = simulate_run(options.law.damper);
  RecordedRun voltage = run;
  voltage.coil_signal = mrd::record::CoilSignal::kCommandVoltage;
  for (double& v : voltage.coil) v /= 0.5;
  EXPECT_EQ(error_of(voltage, options),
            "simulated: the run logged the driver's command voltage, not the coil current: give "
            "the driver gain (--amps-per-volt)");
  options.amps_per_volt = 0.5;
  EXPECT_EQ(replay(voltage, options).trace.predicted_force,
            replay(run, options).trace.predicted_force);
}

TEST(Replay, RunsItCannotReplay) {
  auto options = default_options();
  RecordedRun run = simulate_run(options.law.damper);
  run.velocity.clear();
  options.use_recorded_velocity = true;
  EXPECT_EQ(error_of(run, options),
            "simulated: --recorded-velocity, but the run has no velocity column");
  run.force.clear();
  options.use_recorded_velocity = false;
  EXPECT_FALSE(replay(run, options).force);  // a candump run: prediction and command only
  RecordedRun in_ms = run;
  in_ms.sample_rate = 0.5;  // a 500 Hz run whose time column was read as seconds though in ms
  EXPECT_EQ(error_of(in_ms, options),
            "simulated: sample rate 0.5 Hz is outside 1 Hz to 1e+06 Hz: is the time column in seconds "
            "(--columns names its unit, e.g. t=time_ms), or the rate (--sample-rate) right?");
  run.time.resize(1);
  EXPECT_EQ(error_of(run, options),
            "simulated: cannot replay: the run needs at least 2 samples at a known rate");
}

}  // namespace
