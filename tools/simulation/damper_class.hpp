#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "model/current_schedule.hpp"
#include "model/damper_model.hpp"
#include "model/effects/effect_set.hpp"

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
  // Each effect's parameters at size 1 (all off: --effect switches one on, each descriptor's
  // resize() says what a size does to it).
  model::EffectSet nominal_effects;
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

// Switches the effect on in `effects`, the class's nominal instance scaled by the request's
// size (model/effects/: each descriptor's resize()). `dissipated_energy` [J] is the clean run's,
// for effects sized by how much the run heats them.
void apply_effect(const DamperClass& damper, const EffectRequest& request, double dissipated_energy,
                  model::EffectSet& effects);

}  // namespace mrd::tools
