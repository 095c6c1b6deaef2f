#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "control/force_scale_correction.hpp"
#include "model/damper_model.hpp"
#include "model/effects/effect_set.hpp"
#include "model/hysteresis_compensator.hpp"
#include "tools/force_run/force_strategies.hpp"
#include "tools/force_run/shear_building.hpp"

// mrd-force-run's run: a desired-force profile played through each strategy on the simulated
// plant (docs/FORCE-CONTROL.md, "Force tracking on the simulated plant").
namespace mrd::tools {

// The motion the damper sees and the force wanted of it, one sample a period.
struct DemandProfile {
  std::string description;
  double sample_period = 1e-3;     // [s]
  std::vector<double> displacement;  // [m]
  std::vector<double> velocity;      // [m/s]
  std::vector<double> force;         // desired [N]
  [[nodiscard]] std::size_t size() const { return force.size(); }
};

enum class ProfileKind { kRandom, kStructure };
std::string_view profile_name(ProfileKind kind);

// Band-limited random: motion 0.2-2 Hz (sim::RandomProfile) to +-`peak_displacement`, and a
// force F_r(t) tanh(v / 20 mm/s) with F_r wandering (0.1-1 Hz, a sum of sines) over
// 5..40 kN: always dissipative, its size random and its sign the motion's.
DemandProfile random_demand(double duration, double sample_period, std::uint64_t seed,
                            double peak_displacement = 0.025);

// The clipped-optimal demand f_c = -G z of the two-storey building (shear_building.hpp) under a
// Kanai-Tajimi ground motion; the motion is the first storey's drift with a hysteresis-free
// semi-active damper in it: f_c projected on what `damper`'s Bingham model can give at the
// storey's velocity with its yield stress between zero field and the anhysteretic B at
// `max_current` (each strategy then replays that motion, so all see the same run).
struct StructureDemandOptions {
  ShearBuilding building;
  LqrWeights weights;
  KanaiTajimi ground;
};
DemandProfile structure_demand(double duration, double sample_period, std::uint64_t seed,
                               const model::DamperModel& damper, double max_current,
                               const StructureDemandOptions& options = {});

// The nearest force to `desired` the damper's Bingham model can give at `velocity` with a yield
// stress in [min, max] [Pa] (Eq. 11-12), and whether `desired` lies in that range.
struct ReachableForce {
  double force;
  bool reachable;
};
ReachableForce reachable_force(const model::DamperModel& damper, double min_yield_stress, double max_yield_stress,
                               double desired, double velocity);

struct StrategyFigures {
  StrategyKind kind{};
  double rms_error = 0.0;            // delivered - desired over the scored samples [N]
  double max_error = 0.0;            // [N]
  double rms_error_reachable = 0.0;  // the same over the samples the plant could deliver exactly [N]
  std::vector<double> delivered;     // the plant's force, every sample [N]
  std::vector<double> current;       // the command [A]
  std::vector<double> yield_scale;   // inverse_ja_load_cell: the correction's scale, every sample
};

struct ForceRunOptions {
  model::DamperModel plant;       // the truth
  model::DamperModel controller;  // what the strategies know
  model::CompensatorLimits limits;
  double force_noise_rms = 50.0;  // the load cell [N] (the clipped law reads it)
  double settle = 1.0;            // [s] left out of the figures
  unsigned seed = 1;
  // The plant's yield stress falls linearly by this fraction over the run, as the fluid heats
  // (thermal_drift on a scripted temperature ramp; its viscosity kept): 0 for none.
  double yield_drift = 0.0;
  // Adds inverse_ja_load_cell: inverse_ja with the load-cell correction of its yield scale.
  bool load_cell = false;
  control::ForceScaleSettings load_cell_settings;
};

struct ForceRunResult {
  double desired_rms = 0.0;         // [N], scored samples
  double reachable_fraction = 0.0;  // of the scored samples, for the plant's anhysteretic range
  std::vector<StrategyFigures> strategies;
  std::vector<double> plant_yield_factor;  // the drift: the plant's yield stress over the model's, every sample
};

ForceRunResult run_force_tracking(const DemandProfile& profile, const ForceRunOptions& options);

// The coil lag is the one effect the strategies treat apart (inverse_ja_lag inverts it); these
// are the only places mrd-force-run names it (cmake/check_effect_names.cmake).
const model::EffectInfo& coil_lag_effect();
// `m` with a coil lag of `time_constant` [s], or none for 0.
model::DamperModel with_coil_lag(model::DamperModel m, double time_constant);
// [s], 0 when the model has none.
double coil_lag_time_constant(const model::DamperModel& m);

// The documented perturbation of the controller's model (docs/FORCE-CONTROL.md): every J-A
// and Bingham parameter off by 10-20 % with fixed signs, the coil lag's tau +20 %.
model::DamperModel perturbed_model(const model::DamperModel& truth);

}  // namespace mrd::tools
