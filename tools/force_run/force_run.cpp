#include "tools/force_run/force_run.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numbers>
#include <optional>
#include <random>

#include "model/bingham_damper.hpp"
#include "model/effects/coil_lag.hpp"
#include "model/effects/thermal_drift.hpp"
#include "model/observer.hpp"
#include "model/target_curve.hpp"
#include "sim/damper_plant.hpp"
#include "sim/displacement_profile.hpp"

namespace mrd::tools {

std::string_view profile_name(ProfileKind kind) {
  return kind == ProfileKind::kRandom ? "random" : "structure";
}

namespace {

// The yield stresses a damper can have with currents up to `max_current`: zero field and the
// anhysteretic B at the maximum (Eq. 13).
std::pair<double, double> yield_stress_range(const model::DamperModel& damper, double max_current) {
  const model::Observer observer(damper);
  const model::TargetCurve curve(observer.magnetics(), max_current);
  return {observer.yield_stress().zero_field_stress(), observer.yield_stress()(curve.B(max_current))};
}

// The drift: thermal_drift's linear yield law on a temperature the run scripts, rising from the
// reference by kDriftSpan over the run; the viscosity is left alone (the correction is about the
// yield force).
constexpr double kDriftSpan = 50.0;  // [K]
model::DamperModel with_yield_drift(model::DamperModel m, double fraction) {
  if (fraction <= 0.0) return m;
  auto& drift = m.effects.get<model::ThermalDriftEffect>();
  drift.enabled = true;
  drift.yield_law = model::TemperatureLaw::kLinear;
  drift.yield_coefficient = fraction / kDriftSpan;
  drift.viscosity_coefficient = 0.0;
  drift.min_factor = 0.0;
  return m;
}

}  // namespace

ReachableForce reachable_force(const model::DamperModel& damper, double min_yield_stress, double max_yield_stress,
                               double desired, double velocity) {
  const model::BinghamDamper bingham(damper.geometry, damper.fluid.viscosity, damper.fluid.flow_index);
  const double needed = bingham.yield_stress_for({.force = desired, .velocity = velocity});
  const double tau = std::clamp(needed, min_yield_stress, max_yield_stress);
  // At v = 0 the fluid holds any force up to its yield force (BinghamDamper::yield_stress_for).
  const double force = velocity == 0.0 ? std::copysign(bingham.sliding_force(tau), desired) : bingham.force({.velocity = velocity, .yield_stress = tau});
  return {force, needed >= min_yield_stress && needed <= max_yield_stress};
}

DemandProfile random_demand(double duration, double dt, std::uint64_t seed, double peak_displacement) {
  const auto n = static_cast<std::size_t>(std::llround(duration / dt));
  const sim::RandomProfile motion(peak_displacement, 0.2, 2.0, duration, dt, seed);
  // The force's size: eight sines at 0.1-1 Hz, random phases, scaled to [-1, 1] on the grid.
  std::mt19937_64 rng(seed ^ 0x5bd1e995ULL);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<std::pair<double, double>> sines;  // (omega, phase)
  for (int i = 0; i < 8; ++i) sines.emplace_back(2.0 * std::numbers::pi * (0.1 + 0.9 * unit(rng)), 2.0 * std::numbers::pi * unit(rng));
  std::vector<double> wander(n);
  double peak = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) * dt;
    for (const auto& [w, phase] : sines) wander[i] += std::sin(w * t + phase);
    peak = std::fmax(peak, std::fabs(wander[i]));
  }
  constexpr double kMid = 22.5e3, kHalfSpan = 17.5e3;  // 5..40 kN [N]
  constexpr double kSignVelocity = 0.02;               // [m/s]
  DemandProfile p;
  p.description = "band-limited random: motion 0.2-2 Hz to +-" + std::to_string(peak_displacement * 1e3).substr(0, 4) +
                  " mm, force 5-40 kN (0.1-1 Hz) x tanh(v / 20 mm/s)";
  p.sample_period = dt;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) * dt;
    const double v = motion.velocity(t);
    p.displacement.push_back(motion.displacement(t));
    p.velocity.push_back(v);
    p.force.push_back((kMid + kHalfSpan * wander[i] / peak) * std::tanh(v / kSignVelocity));
  }
  return p;
}

DemandProfile structure_demand(double duration, double dt, std::uint64_t seed, const model::DamperModel& damper,
                               double max_current, const StructureDemandOptions& options) {
  const auto [tau_min, tau_max] = yield_stress_range(damper, max_current);
  const Eigen::RowVector4d gain = clipped_optimal_gain(options.building, options.weights);
  const std::vector<double> ground = kanai_tajimi_ground_motion(options.ground, duration, dt, seed);
  const StructureResponse r = simulate_structure(options.building, gain, ground, dt, [&](double desired, double v) {
    return reachable_force(damper, tau_min, tau_max, desired, v).force;
  });
  DemandProfile p;
  p.description = "clipped-optimal LQR demand, two-storey shear building, Kanai-Tajimi ground motion";
  p.sample_period = dt;
  p.displacement = r.drift;
  p.velocity = r.velocity;
  p.force = r.desired;
  return p;
}

namespace {

// Which scored demands (from sample `first` on) the plant can deliver at all, and how many.
struct ScoredDemands {
  std::vector<bool> reachable;
  std::size_t scored = 0;
  std::size_t reachable_scored = 0;
};
ScoredDemands score_demands(const DemandProfile& profile, const ForceRunOptions& options, std::size_t first,
                            ForceRunResult& result) {
  const auto [tau_min, tau_max] = yield_stress_range(options.plant, options.limits.max_current);
  ScoredDemands d{std::vector<bool>(profile.size()), 0, 0};
  double sum_demand = 0.0;
  for (std::size_t i = first; i < profile.size(); ++i) {
    d.reachable[i] = reachable_force(options.plant, tau_min, tau_max, profile.force[i], profile.velocity[i]).reachable;
    sum_demand += profile.force[i] * profile.force[i];
    ++d.scored;
    d.reachable_scored += d.reachable[i];
  }
  const auto n = static_cast<double>(d.scored);
  result.desired_rms = d.scored ? std::sqrt(sum_demand / n) : 0.0;
  result.reachable_fraction = d.scored ? static_cast<double>(d.reachable_scored) / n : 0.0;
  return d;
}

}  // namespace

ForceRunResult run_force_tracking(const DemandProfile& profile, const ForceRunOptions& options) {
  const double dt = profile.sample_period;
  const auto first = static_cast<std::size_t>(std::llround(options.settle / dt));
  ForceRunResult result;
  const auto [reachable, scored, reachable_scored] = score_demands(profile, options, first, result);

  const model::DamperModel truth = with_yield_drift(options.plant, options.yield_drift);
  const double reference = truth.effects.get<model::ThermalDriftEffect>().reference_temperature;
  const double run_time = static_cast<double>(profile.size()) * dt;
  const auto fluid_temperature = [&](std::size_t i) {
    return reference + kDriftSpan * static_cast<double>(i) * dt / run_time;
  };
  if (options.yield_drift > 0.0) {
    result.plant_yield_factor.reserve(profile.size());
    for (std::size_t i = 0; i < profile.size(); ++i) {
      result.plant_yield_factor.push_back(1.0 - options.yield_drift * static_cast<double>(i) * dt / run_time);
    }
  }
  std::vector<StrategyKind> kinds(std::begin(kAllStrategies), std::end(kAllStrategies));
  if (options.load_cell) kinds.push_back(StrategyKind::kInverseJaLoadCell);
  const double force_range =
      model::BinghamDamper(options.controller.geometry, options.controller.fluid.viscosity)
          .yield_force(yield_stress_range(options.controller, options.limits.max_current).second);

  for (const StrategyKind kind : kinds) {
    sim::DamperPlant plant(truth, {.sample_period = dt, .force_noise_rms = options.force_noise_rms,
                                   .seed = options.seed});
    model::Observer observer(options.controller, model::ObserverSettings{dt});
    const auto strategy = make_strategy(kind, observer, options.limits);
    std::optional<control::ForceScaleCorrection> correction;
    if (kind == StrategyKind::kInverseJaLoadCell) correction.emplace(options.load_cell_settings, force_range, dt);
    StrategyFigures f;
    f.kind = kind;
    f.delivered.reserve(profile.size());
    f.current.reserve(profile.size());
    double measured = 0.0, sum_sq = 0.0, sum_sq_reachable = 0.0;
    for (std::size_t i = 0; i < profile.size(); ++i) {
      const double x = profile.displacement[i], v = profile.velocity[i];
      if (options.yield_drift > 0.0) plant.set_fluid_temperature(fluid_temperature(i));
      // The command of this period, from its demand; the plant holds it over the period and
      // its force at the end is what the demand is compared with (model::ForceInverse).
      const double command =
          strategy->command({.demand = {.force = profile.force[i], .velocity = v}, .measured_force = measured}, observer);
      const sim::PlantReading reading = plant.step({.displacement = x, .velocity = v, .coil_current = command});
      const model::ObserverEstimate predicted = observer.step({.displacement = x, .velocity = v, .coil_current = command});
      measured = reading.measured_force;
      if (correction) {
        // The load cell's force at the end of the period against the observer's for the same
        // instant; the next period's inverse and estimate use the moved scale.
        correction->update({.status = control::LoadCellStatus::kFresh,
                            .measured = measured,
                            .predicted = predicted.force,
                            .viscous = observer.damper().force({.velocity = v, .yield_stress = 0.0}),
                            .velocity = v});
        observer.set_yield_scale(correction->scale());
        f.yield_scale.push_back(correction->scale());
      }
      f.delivered.push_back(reading.force);
      f.current.push_back(command);
      if (i < first) continue;
      const double error = reading.force - profile.force[i];
      sum_sq += error * error;
      if (reachable[i]) sum_sq_reachable += error * error;
      f.max_error = std::fmax(f.max_error, std::fabs(error));
    }
    f.rms_error = scored ? std::sqrt(sum_sq / static_cast<double>(scored)) : 0.0;
    f.rms_error_reachable = reachable_scored ? std::sqrt(sum_sq_reachable / static_cast<double>(reachable_scored)) : 0.0;
    result.strategies.push_back(std::move(f));
  }
  return result;
}

const model::EffectInfo& coil_lag_effect() {
  static const model::EffectInfo* const info = model::find_effect(model::CoilLagEffect::kName);
  return *info;
}

model::DamperModel with_coil_lag(model::DamperModel m, double time_constant) {
  m.effects.get<model::CoilLagEffect>() = {time_constant > 0.0, time_constant > 0.0 ? time_constant : 5e-3};
  return m;
}

double coil_lag_time_constant(const model::DamperModel& m) {
  const auto& lag = m.effects.get<model::CoilLagEffect>();
  return lag.enabled ? lag.time_constant : 0.0;
}

model::DamperModel perturbed_model(const model::DamperModel& truth) {
  model::DamperModel m = truth;
  m.jiles_atherton.Ms *= 1.10;
  m.jiles_atherton.a *= 0.85;
  m.jiles_atherton.alpha *= 1.20;
  m.jiles_atherton.k *= 0.85;
  m.jiles_atherton.c *= 1.20;
  m.fluid.viscosity *= 1.15;
  m.fluid.volume_fraction *= 1.10;
  m.geometry.pole_length *= 0.90;
  m.geometry.sign_velocity_scale *= 1.20;
  m.effects.get<model::CoilLagEffect>().time_constant *= 1.20;
  return m;
}

}  // namespace mrd::tools
