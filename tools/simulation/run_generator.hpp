#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "model/effects/effect_set.hpp"
#include "tools/simulation/damper_class.hpp"

namespace mrd::tools {

// What the rig does in a simulated run.
enum class RunProfile {
  kTable4,      // sine at `frequency`, +-amplitude, Table 4 currents from the LVDT (the paper)
  kPaperSines,  // `cycles` whole cycles at 0.05, 0.1, 0.2, 0.5 and 1 Hz in turn, Table 4 currents
  kSine,        // sine at `frequency`, constant `current`
  kRandom,      // band-limited random displacement, constant `current`
  kTelegraph,   // band-limited random displacement, random telegraph current 0 / `current` (Dyke's)
};

std::optional<RunProfile> parse_run_profile(std::string_view name);
std::string_view to_string(RunProfile profile);

// A negative or zero value (where marked) takes the profile's or the damper class's default.
struct RunOptions {
  RunProfile profile = RunProfile::kTable4;
  DamperClass damper = damper_class_50kN();
  double rate = 1000.0;         // [Hz]
  double duration = 0.0;        // [s]; <= 0: 5 cycles (sines), 30 s (random), the whole sequence
  double frequency = 0.5;       // [Hz], table4 and sine
  double amplitude = 0.0;       // [m], sine amplitude or random peak; <= 0: the class's
  double current = -1.0;        // [A], sine/random level, telegraph high level; < 0: class default
  int cycles = 2;               // paper-sines: cycles per frequency
  double dwell = 0.02;          // [s], telegraph mean dwell (Dyke: about 20 ms)
  double lvdt_noise = -1.0;     // [m RMS]; < 0: the class's
  double force_noise = -1.0;    // [N RMS]; < 0: the class's
  std::uint64_t seed = 1;
  std::vector<EffectRequest> effects;  // carried by the plant, never written to the run
};

// Problems with the options, one per line; empty when they are fine.
std::string check(const RunOptions& options);
// The options with every default filled in from the profile and the damper class.
RunOptions resolve(const RunOptions& options);

struct RunSample {
  double time = 0.0;               // [s]
  double displacement = 0.0;       // LVDT: late with sensor_delay, with noise [m]
  double velocity = 0.0;           // the true velocity through the LVDT's delay [m/s]
  double current = 0.0;            // commanded, held over this period [A]
  double force = 0.0;              // load cell: true force plus noise [N]
  double B = 0.0;                  // [T]
  double temperature = 0.0;        // [degC]
  double true_displacement = 0.0;  // [m]
  double true_force = 0.0;         // [N]
};

struct SimulatedRun {
  RunOptions options;         // resolved
  model::EffectSet effects;   // what the plant carried, sized
  std::vector<RunSample> samples;
};

// Deterministic for the options (seed included): same options, same samples, bit for bit.
// The plant is sim::DamperPlant with the class's model and the requested effects; the rig
// commands the current of the profile, held over each period. For the Table 4 profiles the
// current follows the schedule on the LVDT reading, one period late, as a controller would.
SimulatedRun simulate_run(const RunOptions& options);

// RMS [N] of the damper class's model with `effects` (default: none, the base model) replayed on
// the run's own columns (LVDT displacement, velocity, current) against its force column. With
// no effects it is where a residual analysis starts; on a clean run it is the load cell's noise.
double model_residual(const SimulatedRun& run, const model::EffectSet& effects = {});

}  // namespace mrd::tools
