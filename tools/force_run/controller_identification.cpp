#include "tools/force_run/controller_identification.hpp"

#include <cmath>
#include <cstdio>
#include <random>

#include "tools/force_run/force_run.hpp"
#include "model/slew_limiter.hpp"
#include "sim/damper_plant.hpp"
#include "sim/displacement_profile.hpp"
#include "tools/identification/bh_objective.hpp"
#include "tools/identification/identification.hpp"
#include "tools/identification/synthetic_curve.hpp"
#include "tools/residual/candidate_effects.hpp"
#include "tools/residual/model_fit.hpp"

namespace mrd::tools {

namespace {

std::string formatted(const char* format, double a, double b = 0.0, double c = 0.0) {
  char text[200];
  std::snprintf(text, sizeof text, format, a, b, c);
  return text;
}

// The J-A parameters from a noisy major loop.
model::JilesAthertonParams identify_magnetics(const model::DamperModel& plant, const model::CompensatorLimits& limits,
                                              const ControllerIdentificationOptions& options,
                                              IdentifiedController& out) {
  const double H_max = plant.circuit.field_from_current(limits.max_current);
  BHCurve curve = synthetic_loop(plant.jiles_atherton, H_max, 400, plant.integration);
  std::mt19937_64 rng(options.seed);
  std::normal_distribution<double> noise(0.0, options.bh_noise_rms);
  for (auto& loop : curve.loops) {
    for (double& B : loop.B) B += noise(rng);
  }
  curve.source = "simulated B-H loop";
  const BHObjective objective(curve, plant.integration);
  IdentifyOptions identify_options;
  identify_options.seed = options.seed;
  identify_options.polish = true;
  identify_options.threads = 1;  // deterministic and light on a shared machine
  const IdentifyResult fit = identify(objective, curve, identify_options);
  const Point best = fit.polish ? fit.polish->best : fit.search.best;
  out.bh_rmse = fit.polish ? fit.polish->rmse : fit.fit.rmse;
  out.notes.push_back(formatted("J-A: improved PSO + polish on a major loop to %.0f A/m with %.3g T RMS noise on B: "
                                "RMSE %.4f T",
                                H_max, options.bh_noise_rms, out.bh_rmse));
  return to_params(best);
}

// A run of the plant the way a rig would record it: random motion, the driver stepping between
// random current levels every 0.25 s at its slew rate, a noisy load cell.
FitSeries simulated_force_run(const model::DamperModel& plant, const model::CompensatorLimits& limits,
                              const ControllerIdentificationOptions& options) {
  constexpr double dt = 1e-3;
  const auto n = static_cast<std::size_t>(std::llround(options.force_run_duration / dt));
  const sim::RandomProfile motion(0.03, 0.1, 2.0, options.force_run_duration, dt, options.seed + 17);
  sim::DamperPlant rig(plant, {.sample_period = dt, .force_noise_rms = options.force_noise_rms,
                               .seed = static_cast<unsigned>(options.seed + 29)});
  model::SlewLimiter driver(limits.min_current, limits.max_current, limits.slew_rate, dt);
  std::mt19937_64 rng(options.seed + 41);
  std::uniform_real_distribution<double> level(limits.min_current, limits.max_current);
  FitSeries s;
  s.sample_period = dt;
  s.run_periods = {dt};
  s.run_starts = {0};
  double wanted = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) * dt;
    if (i % 250 == 0) wanted = level(rng);
    const double current = driver.update(wanted);
    const double v = motion.velocity(t);
    const sim::PlantReading r = rig.step({.displacement = motion.displacement(t), .velocity = v, .coil_current = current});
    s.displacement.push_back(motion.displacement(t));
    s.velocity.push_back(v);
    s.current.push_back(current);
    s.force.push_back(r.measured_force);
    // Alternate 1 s blocks validate.
    s.role.push_back((i / 1000) % 2 ? SampleRole::kValidation : SampleRole::kFitting);
  }
  s.notes.push_back("simulated force run");
  return s;
}

}  // namespace

IdentifiedController identify_controller(const model::DamperModel& plant, const model::DamperModel& nominal,
                                         const model::CompensatorLimits& limits,
                                         const ControllerIdentificationOptions& options) {
  IdentifiedController out;
  model::DamperModel start = nominal;
  start.jiles_atherton = identify_magnetics(plant, limits, options, out);
  const model::EffectInfo& lag = coil_lag_effect();
  lag.disable(start.effects);

  const FitSeries series = simulated_force_run(plant, limits, options);
  const SeriesScales scales = series_scales(series);
  FittedModel fit = fit_space(base_space(start, start, scales, Magnetics::kKept), series, nullptr, options.seed);
  if (lag.enabled(plant.effects)) {
    // The lag on the first fit, then the base again with the lag in: the first fit's force
    // scale and viscous term leaned to make up for the lag it did not have.
    fit = fit_space(effect_space(lag, fit.model, scales), series, nullptr, options.seed + 1);
    const ParameterSpace joint = combine(base_space(fit.model, fit.model, scales, Magnetics::kKept),
                                         effect_space(lag, fit.model, scales));
    Point from(joint.bounds.lower.size());
    from << base_coordinates(fit.model, fit.model, scales, Magnetics::kKept), effect_coordinates(lag, fit.model, scales);
    fit = refine_space(joint, series, from, 200);
    out.notes.push_back(formatted("coil lag: tau %.2f ms", coil_lag_time_constant(fit.model) * 1e3));
  }
  const model::BinghamDamper fitted(fit.model.geometry, fit.model.fluid.viscosity, fit.model.fluid.flow_index);
  const model::BinghamDamper truth(plant.geometry, plant.fluid.viscosity);
  out.notes.push_back(formatted("Bingham: yield gain 3 Ap L / hd %.4f of the plant's, c0 %.4f of it, v_s %.3g mm/s",
                                fitted.yield_force(1.0) / truth.yield_force(1.0),
                                fitted.viscous_coefficient() / truth.viscous_coefficient(),
                                fit.model.geometry.sign_velocity_scale * 1e3));
  out.force_fit_rms = fit.fitting_rms;
  out.notes.push_back(formatted("force fit residual %.0f N RMS on %.0f s with %.0f N RMS load-cell noise", out.force_fit_rms,
                                options.force_run_duration, options.force_noise_rms));
  out.model = fit.model;
  return out;
}

}  // namespace mrd::tools
