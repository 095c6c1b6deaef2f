// mrd-bench: cost of one control-period step of the model parts. The current changes every
// step (a 0.5 Hz sine of 0..1.2 A sampled at 1 kHz), so every step integrates Eq. 10.
#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <numbers>

#include "model/force_inverse.hpp"
#include "model/hysteresis_compensator.hpp"
#include "model/observer.hpp"

namespace {

constexpr int kSamplesPerCycle = 2000;  // 0.5 Hz at 1 kHz

const std::array<double, kSamplesPerCycle>& sine_current() {
  static const auto table = [] {
    std::array<double, kSamplesPerCycle> t{};
    for (int i = 0; i < kSamplesPerCycle; ++i) {
      t[i] = 0.6 - 0.6 * std::cos(2.0 * std::numbers::pi * i / kSamplesPerCycle);
    }
    return t;
  }();
  return table;
}

const std::array<double, kSamplesPerCycle>& sine_displacement() {
  static const auto table = [] {
    std::array<double, kSamplesPerCycle> t{};
    for (int i = 0; i < kSamplesPerCycle; ++i) {
      t[i] = 0.04 * std::sin(2.0 * std::numbers::pi * i / kSamplesPerCycle);
    }
    return t;
  }();
  return table;
}

void run_jiles_atherton_steps(benchmark::State& state, mrd::model::Integrator integrator) {
  const mrd::model::DamperModel m;
  mrd::model::JilesAthertonSettings settings = m.integration;
  settings.integrator = integrator;
  mrd::model::JilesAtherton core(m.jiles_atherton, m.circuit, settings);
  const auto& current = sine_current();
  int i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(core.apply_current(current[i]));
    i = (i + 1) % kSamplesPerCycle;
  }
}

void BM_JilesAthertonStep(benchmark::State& state) {
  run_jiles_atherton_steps(state, mrd::model::Integrator::kRk4);
}
BENCHMARK(BM_JilesAthertonStep);

// The cheaper 2nd-order option, for the trade-off table in docs/PERFORMANCE.md.
void BM_JilesAthertonStepHeun(benchmark::State& state) {
  run_jiles_atherton_steps(state, mrd::model::Integrator::kHeun);
}
BENCHMARK(BM_JilesAthertonStepHeun);

void run_observer_steps(benchmark::State& state, const mrd::model::DamperModel& model) {
  mrd::model::Observer observer{model};
  const auto& current = sine_current();
  const auto& x = sine_displacement();
  int i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(observer.step({.displacement = x[i], .coil_current = current[i]}));
    i = (i + 1) % kSamplesPerCycle;
  }
}

void BM_ObserverStep(benchmark::State& state) { run_observer_steps(state, mrd::model::DamperModel{}); }
BENCHMARK(BM_ObserverStep);

// The same step with every optional effect on (docs/MODEL.md, "Optional effects"): what the
// improved model costs. BM_ObserverStep, with them all off, must not move.
void BM_ObserverStepAllEffects(benchmark::State& state) {
  mrd::model::DamperModel m;
  m.effects.get<mrd::model::CoilLagEffect>().enabled = true;
  m.effects.get<mrd::model::PreyieldHysteresisEffect>().enabled = true;
  m.effects.get<mrd::model::GasSpringEffect>() = {true, 1500.0, 3e4};
  m.effects.get<mrd::model::ThermalDriftEffect>().enabled = true;
  m.effects.get<mrd::model::SensorDelayEffect>() = {true, 2e-3};
  m.effects.get<mrd::model::StrokeEndAirEffect>().enabled = true;
  run_observer_steps(state, m);
}
BENCHMARK(BM_ObserverStepAllEffects);

// A damper whose every shape differs from the paper's (docs/MODEL.md, "Shapes of another
// damper"): a yield exponent and ceiling of knee `ceiling_shape`, a Herschel-Bulkley fluid, an
// atan-like sign and seal friction, what mrd-residual may write into a config.
mrd::model::DamperModel other_shapes(double ceiling_shape) {
  mrd::model::DamperModel m;
  m.fluid.field_exponent = 0.9;
  m.fluid.saturation_induction = 1.2;
  m.fluid.saturation_shape = ceiling_shape;
  m.fluid.flow_index = 0.7;
  m.geometry.sign_shape = -0.6;
  m.geometry.seal_friction = 300.0;
  return m;
}

void BM_ObserverStepOtherShapes(benchmark::State& state) { run_observer_steps(state, other_shapes(0.5)); }
BENCHMARK(BM_ObserverStepOtherShapes);

// The ceiling's knee past order 8 (a power law capped hard): the knee of order m costs an exp2
// and two std::pow where order 8 takes multiplications.
void BM_ObserverStepCappedYield(benchmark::State& state) { run_observer_steps(state, other_shapes(2.0)); }
BENCHMARK(BM_ObserverStepCappedYield);

void BM_CompensatorStep(benchmark::State& state) {
  const mrd::model::DamperModel m;
  mrd::model::JilesAtherton core(m.jiles_atherton, m.circuit, m.integration);
  const mrd::model::TargetCurve target(core, 1.5);
  mrd::model::HysteresisCompensator compensator(core, target, {}, 1e-3);
  const auto& current = sine_current();
  int i = 0;
  for (auto _ : state) {
    const double command = compensator.command(current[i], core);
    benchmark::DoNotOptimize(core.apply_current(command));
    i = (i + 1) % kSamplesPerCycle;
  }
}
BENCHMARK(BM_CompensatorStep);

// The force-mode law, one period: the inverse (Eq. 11-12, 13 inverted, the J-A search, the coil
// lag inverted when declared) and the observer step it reads. Table 4's motion with a viscous
// demand of 250 kN s/m on a bipolar driver (docs/FORCE-CONTROL.md).
void run_force_law(benchmark::State& state, const mrd::model::DamperModel& model,
                   const mrd::model::CompensatorLimits& limits, double (*demand)(int i, double v)) {
  mrd::model::Observer observer{model};
  mrd::model::ForceInverse inverse(observer, limits);
  const auto& x = sine_displacement();
  constexpr double kPeakVelocity = 0.04 * 2.0 * std::numbers::pi * 0.5;  // of sine_displacement
  int i = 0;
  long evaluations = 0;
  for (auto _ : state) {
    const double v = kPeakVelocity * std::cos(2.0 * std::numbers::pi * i / kSamplesPerCycle);
    const auto command = inverse.step({.force = demand(i, v), .velocity = v}, observer);
    benchmark::DoNotOptimize(observer.step({.displacement = x[i], .velocity = v, .coil_current = command.current}));
    evaluations += inverse.last_evaluations();
    i = (i + 1) % kSamplesPerCycle;
  }
  state.counters["evaluations"] = benchmark::Counter(static_cast<double>(evaluations), benchmark::Counter::kAvgIterations);
}

mrd::model::CompensatorLimits bipolar_limits() {
  mrd::model::CompensatorLimits limits;
  limits.min_current = -limits.max_current;
  return limits;
}

double viscous_demand(int, double v) { return 250e3 * v; }

void BM_ForceInverseStep(benchmark::State& state) {
  run_force_law(state, mrd::model::DamperModel{}, bipolar_limits(), viscous_demand);
}
BENCHMARK(BM_ForceInverseStep);

void BM_ForceInverseStepCoilLag(benchmark::State& state) {
  mrd::model::DamperModel m;
  m.effects.get<mrd::model::CoilLagEffect>() = {true, 20e-3};
  run_force_law(state, m, bipolar_limits(), viscous_demand);
}
BENCHMARK(BM_ForceInverseStepCoilLag);

// A full swing every period: the demand jumps between far above the maximum force and none.
// At the default 100 A/s the slew window holds the target outside it, so the search stops at an
// end after one or two integrations.
double full_swing_demand(int i, double v) { return i % 2 ? 1e6 * v : 0.0; }
// A swing inside the range: 40 kN of the 45 kN yield force at 1.5 A, and none.
double inner_swing_demand(int i, double v) { return i % 2 ? 40e3 * std::tanh(v / 1e-3) + 53e3 * v : 0.0; }

void BM_ForceInverseFullSwing(benchmark::State& state) {
  run_force_law(state, mrd::model::DamperModel{}, bipolar_limits(), full_swing_demand);
}
BENCHMARK(BM_ForceInverseFullSwing);

// The bound at the default limits: a tolerance no trial meets, so every period runs the whole
// cap (2 + 24 integrations over the 0.1 A slew window).
void BM_ForceInverseSearchCap(benchmark::State& state) {
  auto limits = bipolar_limits();
  limits.tolerance = -1.0;  // no trial meets it, not even an exact one
  run_force_law(state, mrd::model::DamperModel{}, limits, viscous_demand);
}
BENCHMARK(BM_ForceInverseSearchCap);

// The worst case: a driver that slews its whole range in one period (1e4 A/s at 1 kHz), a swing
// between no force and nearly the most every period, and the whole cap each time: 25
// integrations over up to 1.5 A.
void BM_ForceInverseWorstCase(benchmark::State& state) {
  auto limits = bipolar_limits();
  limits.slew_rate = 1e4;
  limits.tolerance = -1.0;  // no trial meets it, not even an exact one
  run_force_law(state, mrd::model::DamperModel{}, limits, inner_swing_demand);
}
BENCHMARK(BM_ForceInverseWorstCase);

}  // namespace

