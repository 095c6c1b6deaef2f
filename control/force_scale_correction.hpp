#pragma once

#include <cstdint>

#include "common/validation_report.hpp"

namespace mrd::control {

// force.load_cell.* (docs/FORCE-CONTROL.md, "Load-cell feedback").
struct ForceScaleSettings {
  double time_constant = 5.0;        // [s] of the first-order move toward measured / predicted
  double max_correction = 0.3;       // the scale stays in [1 - max, 1 + max]
  double min_force_fraction = 0.1;   // gate: both yield parts, |F - c0 v|, above this share of the range
  double min_speed = 0.01;           // gate: |v| above it [m/s] (10 v_s: the sign term is saturated)
  int max_age_periods = 5;           // more periods than this without a fresh sample: stale
};

ValidationReport validate(const ForceScaleSettings& settings);

// What the loop knows of the load cell in one period.
enum class LoadCellStatus : std::uint8_t {
  kNone,   // nothing new arrived
  kFresh,  // a new, usable measurement
  kBad,    // a new one the back end marked unusable (corrupted, sensor fault, not finite)
};

struct LoadCellObservation {
  LoadCellStatus status = LoadCellStatus::kNone;
  double measured = 0.0;   // the load cell's force [N]
  double predicted = 0.0;  // the observer's force this period, with the present scale [N]
  double viscous = 0.0;    // its part without yield stress, c0 v (Eq. 11-12) [N]
  double velocity = 0.0;   // [m/s]
};

// What one update did.
enum class ScaleUpdate : std::uint8_t {
  kMoved,     // the scale moved toward the measured ratio
  kGatedOut,  // a fresh sample, but the damper was not yielding with enough force
  kWaiting,   // no sample this period, not yet stale
  kStale,     // no fresh sample for more than max_age_periods: frozen
  kBad,       // an unusable sample: frozen
};

// Load-cell feedback on the model's yield force (issue 18): a multiplicative scale s on Eq. 13's
// yield stress (Observer::set_yield_scale) so that a slow drift of the fluid (heating lowers
// its yield stress) does not build up as force error. Each period with a fresh sample that
// passes the gate, s moves toward the scale that would have made the prediction match,
//
//   s* = s (F_measured - c0 v) / (F_model - c0 v),
//
// by 1 - exp(-dt / time_constant) of the way, dt the time since the previous fresh sample (a
// first-order filter in seconds gated in, whatever the load cell's rate),
// and stays in [1 - max_correction, 1 + max_correction]. The gate: both yield parts,
// |F_measured - c0 v| and |F_model - c0 v|, above min_force_fraction of the force range, of the
// same sign, and |v| above min_speed; elsewhere the ratio is noise over a small number. A stale or bad load cell freezes
// s (not a fault: the law keeps the last scale) and is counted. Pure, no heap.
class ForceScaleCorrection {
 public:
  // `force_range` [N]: what the gate's fraction is of (the model's maximum yield force).
  ForceScaleCorrection(const ForceScaleSettings& settings, double force_range, double sample_period);

  ScaleUpdate update(const LoadCellObservation& in);

  [[nodiscard]] double scale() const { return scale_; }
  // At 1 - max or 1 + max now.
  [[nodiscard]] bool at_bound() const { return at_bound_; }
  // The last update took the scale onto a bound (the loop journals it once per arrival; the
  // next arrival counts after the scale came back inside by a tenth of max_correction).
  [[nodiscard]] bool reached_bound() const { return reached_bound_; }
  [[nodiscard]] std::uint64_t stale_periods() const { return stale_periods_; }
  [[nodiscard]] std::uint64_t bad_samples() const { return bad_samples_; }
  [[nodiscard]] std::uint64_t moves() const { return moves_; }

 private:
  double sample_period_;  // T [s]
  double time_constant_;  // tau [s]
  double lower_;      // 1 - max_correction
  double upper_;      // 1 + max_correction
  double min_force_;  // [N]
  double min_speed_;  // [m/s]
  double rearm_margin_;  // how far inside the bounds the scale must come before a new arrival is said
  int max_age_periods_;
  double scale_ = 1.0;
  int periods_since_fresh_ = 0;
  bool at_bound_ = false;
  bool reached_bound_ = false;
  bool armed_ = true;  // the next arrival at a bound is said
  std::uint64_t stale_periods_ = 0;
  std::uint64_t bad_samples_ = 0;
  std::uint64_t moves_ = 0;
};

}  // namespace mrd::control
