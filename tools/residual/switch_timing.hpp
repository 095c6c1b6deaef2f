#pragma once

#include <cstddef>
#include <vector>

#include "model/damper_model.hpp"
#include "tools/residual/fit_series.hpp"

namespace mrd::tools {

// A logger samples the coil current; a command that switched between two rows shows at the
// later row as if it had been held since the row before. Where the model carries a lag (the
// coil's, a field's), that period's uncertainty shows in the force for several time constants
// after each switch: up to a period's share of the step, decaying with the lag.
//
// A step's phase theta in [0, 1] is where in the period before its row it happened (0: at the
// previous row, as the observer takes a logged step; 1: at its own row). It is estimated per
// step from the force that follows it, and written into the series as the current the period
// held on average, theta u_{k-1} + (1 - theta) u_k: for a first-order lag of time constant tau,
// that reproduces the sub-row switch to O((T / tau)^2). On a run kept at the times its samples
// were taken unevenly, the period before a row is that row's own interval.
struct SwitchTiming {
  std::size_t steps = 0;      // rows where the current stepped by more than the threshold
  std::size_t estimated = 0;  // those with kept samples after them (others take the median)
  double median_phase = 0.0;  // of the estimated steps
  double rms_before = 0.0;    // [N] RMS of the fitting samples with every step at its previous row
  double rms_after = 0.0;     // [N] with the estimated phases
  bool applied = false;       // whether the phases were written (they lowered that RMS enough)
};

struct SwitchTimingOptions {
  double step_share = 0.1;  // a step of more than this share of the run's current range
  double window = 0.1;      // [s] of force after a step that can inform its phase
  int iterations = 3;       // Gauss-Newton passes over all steps (each two observer passes)
  // The phases are written only when they lower the fitting mean square by this many times what
  // fitting one phase per step to white noise would (steps / kept samples of it; 0: whenever
  // they lower it at all).
  double chance_multiple = 4.0;
};

// The rows of `series` where the current steps (a run's first row counts as a step from 0 A:
// the observer starts with no current flowing).
[[nodiscard]] std::vector<std::size_t> current_steps(const FitSeries& series, double step_share);

// Estimates every step's phase for `model` from the kept samples after it (validation samples
// too: a phase is a fact of the log, like a gap's place) and writes the blended current into
// `series` when that lowers the RMS of its fitting samples enough (else `series` is left as it was).
SwitchTiming time_current_steps(const model::DamperModel& model, FitSeries& series,
                                const SwitchTimingOptions& options = {});

}  // namespace mrd::tools
