#pragma once

#include <string>

#include "record/recorded_run.hpp"
#include "tools/report/html_report.hpp"
#include "tools/replay/replay.hpp"

namespace mrd::tools {

// How the replay was asked for and how long it took, for the reports.
struct ReplayContext {
  const record::RecordedRun& run;
  const ReplayOptions& options;
  const ReplayResult& result;
  // Time spent in replay() (not reading or writing files): on the clock, and on the CPU, which
  // does not count the time the thread waited for a core on a loaded machine.
  double wall_seconds = 0.0;
  double cpu_seconds = 0.0;
};

// The human summary: the run, the force error (RMS, max, NRMSE), the commanded current, the
// reader's notes, and "replayed N s of data in M s (X x real time; CPU ...)".
[[nodiscard]] std::string replay_summary(const ReplayContext& c);

// The same figures as JSON (forces in N, currents in A; NRMSE dimensionless, null when the
// run has no force). Keys: docs/CLOSING-THE-LOOP.md.
[[nodiscard]] std::string replay_json(const ReplayContext& c);

// Per-sample CSV: time_s, displacement_mm, velocity_mm_s, coil_current_A, [measured_force_N,]
// predicted_force_N, [residual_N,] B_T, scheduled_current_A, command_current_A.
// Returns "" or why it could not be written.
[[nodiscard]] std::string write_replay_csv(const ReplayContext& c, const std::string& path);

// replay_force_displacement.png (measured and predicted against displacement, as the paper's
// Figures 12 and 14), replay_residual.png (measured - predicted against time) and
// replay_current.png (the run's current and the command) in `directory`. Returns "" or why
// not (gnuplot missing: the caller reports it and carries on).
[[nodiscard]] std::string plot_replay(const ReplayContext& c, const std::string& directory);

// --report DIR: report.html with the force fit (measured and predicted against time,
// displacement and velocity, the fit percentage), the residual's structure, the current, the
// damper's parameters (the config's: a replay fits nothing) and the provenance; the plots' .dat
// and .gp beside it. A run without force gets the prediction and the current only.
// Returns "" or why not.
[[nodiscard]] std::string write_replay_report(const ReplayContext& c, const Provenance& provenance,
                                              const std::string& directory);

}  // namespace mrd::tools
