#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "model/current_schedule.hpp"
#include "model/damper_model.hpp"

namespace mrd::tools {

// A damper size the run generator simulates: its base model (effects off), its Table 4 schedule
// and stroke, its sensors' noise, and the nominal size (size 1) of each optional effect on it.
// docs/CLOSING-THE-LOOP.md lists both classes.
struct DamperClass {
  std::string name;                      // "50kN" or "1kN"
  model::DamperModel model;              // J-A + Bingham, every effect off
  model::CurrentScheduleTable schedule;  // Table 4, scaled to the stroke
  double amplitude = 0.0;                // sine amplitude and random-motion peak [m]
  double max_current = 0.0;              // [A]
  double lvdt_noise = 0.0;               // [m RMS]
  double force_noise = 0.0;              // load cell [N RMS]
  double random_low = 0.0;               // band of random motion [Hz]
  double random_high = 0.0;
  // The effects at size 1:
  double coil_time_constant = 0.0;       // [s]
  double preyield_travel = 0.0;          // z_max of the Bouc-Wen element [m]
  double preyield_fraction = 0.0;        // share w of the yield force it carries [-]
  double gas_preload = 0.0;              // [N]
  double gas_stiffness = 0.0;            // [N/m]
  double thermal_rise = 0.0;             // fluid temperature rise over the run [K]
  double sensor_delay = 0.0;             // [s]
  double stroke_end_threshold = 0.0;     // [m]
  double stroke_end_length = 0.0;        // [m]
  double stroke_end_depth = 0.0;         // [-], capped at 0.95 when sized up
};

// The project's default damper (docs/MODEL.md): 100 mm piston, 0..1.2 A, +-40 mm.
DamperClass damper_class_50kN();
// A small damper like Quiroz's (about 1.5 kN at 1 A) or Dyke's: 40 mm piston, 0..1 A, +-20 mm.
DamperClass damper_class_1kN();
std::optional<DamperClass> find_damper_class(std::string_view name);  // "50kN", "1kN"

// One --effect NAME[:SIZE]: SIZE is small (0.5), medium (1, the default), large (2) or a number
// > 0 that scales the effect's nominal size.
struct EffectRequest {
  std::string name;
  double size = 1.0;
};

// nullopt with `error` set for an unknown name or a bad size.
std::optional<EffectRequest> parse_effect_request(std::string_view text, std::string& error);

// Switches the effect on in `effects`, sized for the damper class:
//   coil_lag             tau = size x coil_time_constant
//   preyield_hysteresis  w = min(size x preyield_fraction, 1), z_max = preyield_travel
//                        (A = 1, n = 2, beta = gamma)
//   gas_spring           F0 = size x gas_preload, k = size x gas_stiffness
//   thermal_drift        C such that the run's dissipated energy heats the fluid by
//                        size x thermal_rise (cooling aside): C = E / (size x rise)
//   sensor_delay         d = size x sensor_delay (at most model::kMaxSensorDelay)
//   stroke_end_air       depth = min(size x stroke_end_depth, 0.95), the class's threshold and length
// `dissipated_energy` [J] is the clean run's, used by thermal_drift only.
void apply_effect(const DamperClass& damper, const EffectRequest& request, double dissipated_energy,
                  model::EffectSet& effects);

}  // namespace mrd::tools
