// mrd-bench: cost of one control-period step of the model parts. The current changes every
// step (a 0.5 Hz sine of 0..1.2 A sampled at 1 kHz), so every step integrates Eq. 10.
#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <numbers>

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

}  // namespace

