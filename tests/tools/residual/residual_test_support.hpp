#pragma once

#include <sstream>
#include <string>
#include <vector>

#include "record/run_reader.hpp"
#include "tools/residual/fit_series.hpp"
#include "tools/residual/residual_search.hpp"
#include "tools/simulation/run_csv.hpp"
#include "tools/simulation/run_generator.hpp"

namespace mrd::tools::residual_testing {

// A simulated run carrying `effects`, written in the run format and read back, so the
// analysis sees exactly what the CLI would.
inline record::RecordedRun simulated_recorded_run(RunProfile profile, const char* damper_class,
                                          std::vector<EffectRequest> effects, double duration = 0.0,
                                          std::uint64_t seed = 3) {
  RunOptions o;
  o.profile = profile;
  o.damper = *find_damper_class(damper_class);
  o.duration = duration;
  o.seed = seed;
  o.effects = std::move(effects);
  std::ostringstream csv;
  write_run_csv(csv, simulate_run(o), RunColumns{});
  return record::parse_recorded_run(csv.str(), std::string(damper_class) + ".csv");
}

inline ResidualResult analyse(const record::RecordedRun& run) {
  ResidualOptions options;
  options.threads = 2;
  return find_missing_effects(make_fit_series({run}, {}), options);
}

}  // namespace mrd::tools::residual_testing
