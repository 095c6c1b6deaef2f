#pragma once

#include <cstdint>

namespace mrd::test {

// What a soak run measured (docs/RELIABILITY.md prints these).
struct SoakFigures {
  std::uint64_t cycles = 0;
  double seconds = 0.0;              // wall time of the run
  std::uint64_t faults = 0;          // scripted faults injected
  std::uint64_t safe_entries = 0;    // transitions into SAFE
  std::uint64_t recoveries = 0;      // SAFE -> RUN
  // Longest time in SAFE (or INIT) after the last fault ended, in cycles: the recovery time.
  std::uint64_t longest_recovery = 0;
  std::uint64_t stuck_in_safe = 0;   // cycles in SAFE/INIT past the recovery condition (must be 0)
  std::uint64_t latches = 0;         // SAFE latched by repeated driver faults, cleared by the soak's operator
  std::uint64_t non_finite = 0;      // cycles with a non-finite J-A state or force (must be 0)
  double Ms = 0.0;                   // the config's saturation magnetisation [A/m]
  double max_abs_M_observer = 0.0;   // [A/m]
  double max_abs_B_plant = 0.0;      // [T]
  double max_abs_B_observer = 0.0;   // [T]
  long rss_after_warmup_kib = 0;     // resident size after the first 5 % of the cycles
  long rss_max_kib = 0;              // largest resident size sampled after that
  std::uint64_t telemetry_offered = 0;
  std::uint64_t telemetry_written = 0;
  std::uint64_t telemetry_dropped = 0;
};

// The controller's loop on the mock HAL with the simulated plant (the default config's
// simulated rig), run as fast as the machine goes for `cycles` periods, under a random fault
// script from `seed`: one fault at a time, random kind, length and gap. Telemetry goes through
// the real ring and CSV writer into /dev/null.
SoakFigures run_soak(std::uint64_t cycles, std::uint32_t seed);

}  // namespace mrd::test
