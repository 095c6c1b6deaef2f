#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "control/control_law.hpp"
#include "record/recorded_run.hpp"

namespace mrd::tools {

struct ReplayOptions {
  // The controller's law (damper model, schedule, compensator, observer settings), usually
  // from the TOML config. Its observer.sample_period is replaced by the run's nominal period.
  control::ControlLawConfig law;
  // The current driver's gain [A/V], for runs that logged the command voltage: the coil
  // current is voltage x gain, with no lag (a lag is a model effect, not the replay's).
  std::optional<double> amps_per_volt;
  // Feed the run's recorded velocity to the observer (a velocity sensor) instead of the
  // controller's own velocity filter on the displacement.
  bool use_recorded_velocity = false;
  // Offline analysis: the velocity from zero_phase_velocity at this cutoff [Hz] (0: from the
  // motion's spectrum), fed to the observer and the law as a sensor's. Not what the controller
  // can do (it cannot look ahead); for comparing models without the causal filter's lag.
  std::optional<double> zero_phase_cutoff;
};

// What the controller's code computed at each sample of the run, index for index.
struct ReplayTrace {
  std::vector<double> coil_current;       // [A] that flowed: recorded, or voltage x gain
  std::vector<double> velocity;           // [m/s] the observer used
  std::vector<double> B;                  // [T] the observer's gap induction
  std::vector<double> predicted_force;    // [N] the observer's force
  std::vector<double> scheduled_current;  // [A] Table 4's choice for the displacement
  std::vector<double> command_current;    // [A] what the controller would have commanded
};

// Residual r = measured - predicted force over all samples.
struct ForceError {
  std::size_t samples = 0;
  double rms = 0.0;             // [N]
  double max = 0.0;             // max |r| [N]
  double mean = 0.0;            // bias [N]
  double measured_range = 0.0;  // max - min of the measured force [N]
  // rms / measured_range: dimensionless, comparable across damper sizes. NaN when the
  // measured force is constant.
  double nrmse = 0.0;
};
[[nodiscard]] ForceError force_error(std::span<const double> measured,
                                     std::span<const double> predicted);

struct ReplayResult {
  ReplayTrace trace;
  std::optional<ForceError> force;  // when the run measured the force
  double sample_period = 0.0;       // [s] the law ran with: the run's nominal period
  record::SamplingSummary sampling;
};

// Runs the firmware's ControlLaw (schedule, observer, compensator) over the run, one step
// per sample, in order, from a demagnetised core, as the controller would have run on these
// samples. Every sample counts as one nominal period: J-A is rate-independent, and only the
// velocity filter and the compensator's slew limit see the period, so jitter enters only
// there (docs/CLOSING-THE-LOOP.md). The coil current each step is the run's, not the law's
// command: the run is what happened, the command is what the controller would have done.
// Deterministic. Throws InputError when the run cannot be replayed as asked (a voltage run
// without a gain, recorded velocity asked for but not recorded, an invalid law).
[[nodiscard]] ReplayResult replay(const record::RecordedRun& run, const ReplayOptions& options);

}  // namespace mrd::tools
