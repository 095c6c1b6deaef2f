#pragma once

// mrd-force-run's comparison as one library function: the plant, the desired-force profile, the
// cases (matched, identified, perturbed) with their strategies, the summary on stdout and the
// outputs (--json, --out). Its main (mrd_force_run.cpp) declares the options and calls it.
#include <cstdint>
#include <string>

#include "control/force_scale_correction.hpp"
#include "tools/force_run/force_run.hpp"

namespace mrd::tools {

// mrd-force-run's command line, as parsed.
struct ForceRunArguments {
  std::string profile_choice = "random";
  std::string case_choice = "identified";
  double coil_lag_ms = 0.0;
  std::uint64_t seed = 1;
  double duration = 20.0;
  double force_noise = 50.0;
  double lqr_force_weight = LqrWeights{}.force_weight;
  double pga_g = 0.3;
  double drift_pct = 0.0;
  bool load_cell = false;
  double load_cell_tau = mrd::control::ForceScaleSettings{}.time_constant;
  std::string json_path, out_dir;
  bool no_plot = false;

  ProfileKind profile_kind() const {
    return profile_choice == "random" ? ProfileKind::kRandom : ProfileKind::kStructure;
  }
};

// Runs the comparison and writes its outputs; the exit code (common/cli/exit_code.hpp).
int run_force_comparison(const ForceRunArguments& args);

}  // namespace mrd::tools
