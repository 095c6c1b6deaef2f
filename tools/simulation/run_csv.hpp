#pragma once

#include <ostream>
#include <string>

#include "tools/simulation/run_generator.hpp"

namespace mrd::tools {

// Optional columns of the recorded-run CSV; the four required ones are always written.
struct RunColumns {
  bool velocity = true;      // velocity_mm_s
  bool B = false;            // B_T (a rig rarely measures the gap induction)
  bool temperature = false;  // temperature_C (a thermocouple on the body)
};

// The project's recorded-run format (record::RunCsvWriter): a header naming each column with its
// unit, then one row per sample: time_s,displacement_mm,current_A,force_N[,velocity_mm_s][,B_T]
// [,temperature_C].
// Only what a rig measures: the LVDT, the commanded current and the load cell. The effects the
// plant carried are not declared in it.
void write_run_csv(std::ostream& out, const SimulatedRun& run, const RunColumns& columns);

// What the run is, for the tests and tables that check a residual analysis against the truth:
// a JSON object with the class, profile, rate, duration, seed, noise, the effects with their
// sizes, and the effects' [damper.effects.*] tables as the config would state them.
std::string run_manifest_json(const SimulatedRun& run);

}  // namespace mrd::tools
