// The whole force-mode law of one control cycle (issue 18's goal: under 2 us): the demand's
// check, the observer (ControlLaw::observe, with the Table 4 schedule it runs in every mode) and
// ControlLaw::command, the inverse and the slew limit. The loop's I/O and supervisor are not in
// it. docs/PERFORMANCE.md has the figures.
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <numbers>

#include "control/control_law.hpp"
#include "control/demand_check.hpp"

namespace {

constexpr double kPeriod = 1e-3;
constexpr double kAmplitude = 0.040;                    // [m], Table 4's motion
constexpr double kOmega = 2.0 * std::numbers::pi * 0.5;  // [rad/s]

// `load_cell`: the load-cell correction runs too, on a load cell reading 0.9 of the demand
// (a fresh sample every period, so it moves the scale whenever the gate lets it).
void run_control_law(benchmark::State& state, mrd::control::ControlMode mode, bool load_cell = false) {
  mrd::control::ControlLawConfig config;
  config.mode = mode;
  config.has_load_cell = load_cell;
  config.limits.min_current = -config.limits.max_current;  // bipolar, as in docs/FORCE-CONTROL.md
  mrd::control::ControlLaw law(config);
  mrd::control::DemandChecker demands({.range = 60e3, .max_age = std::chrono::milliseconds{5}});
  double coil = 0.0;
  std::uint32_t i = 0;
  long evaluations = 0;
  for (auto _ : state) {
    const double t = i * kPeriod;
    const auto now = std::chrono::duration_cast<mrd::hal::Timestamp>(std::chrono::duration<double>(t));
    const mrd::hal::Sample demand{250e3 * kAmplitude * kOmega * std::cos(kOmega * t), now, ++i, mrd::hal::kSampleValid};
    benchmark::DoNotOptimize(demands.check(demand, now));
    law.observe({.displacement = kAmplitude * std::sin(kOmega * t),
                 .timing = mrd::model::SampleTiming{.fresh = true, .interval = kPeriod, .age = 0.0},
                 .coil_current = coil});
    if (load_cell) {
      benchmark::DoNotOptimize(law.correct_force_scale(mrd::control::LoadCellStatus::kFresh, 0.9 * demand.value));
    }
    // Kept from the optimiser as a const value: Google Benchmark's DoNotOptimize on a non-const
    // double that is read afterwards ("+m,r") is miscompiled by GCC 12 (GCC bug 92597); here it
    // fed sin(wt) back as the coil current, a 1 A swing that tripled the cycle's time.
    const auto command = law.command(demands.held_value());
    benchmark::DoNotOptimize(command);
    coil = command.current;
    if (const auto* inverse = law.force_inverse()) evaluations += inverse->last_evaluations();
  }
  state.counters["evaluations"] = benchmark::Counter(static_cast<double>(evaluations), benchmark::Counter::kAvgIterations);
}

void BM_ForceModeLawCycle(benchmark::State& state) { run_control_law(state, mrd::control::ControlMode::kForce); }
BENCHMARK(BM_ForceModeLawCycle);
void BM_ForceModeLawCycleLoadCell(benchmark::State& state) {
  run_control_law(state, mrd::control::ControlMode::kForce, true);
}
BENCHMARK(BM_ForceModeLawCycleLoadCell);

}  // namespace
