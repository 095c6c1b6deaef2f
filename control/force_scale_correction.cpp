#include "control/force_scale_correction.hpp"

#include <algorithm>
#include <cmath>

namespace mrd::control {

ValidationReport validate(const ForceScaleSettings& s) {
  ValidationReport r;
  r.require_positive("time_constant", s.time_constant);
  r.check(s.max_correction > 0.0 && s.max_correction <= 0.9, "max_correction",
          "must be in (0, 0.9]: 0 would hold the scale at 1 (leave the load cell out instead)");
  r.require_in_range("min_force_fraction", s.min_force_fraction, 0.0, 1.0, true);
  r.require_in_range("min_speed", s.min_speed, 0.0, 10.0, true);
  r.check(s.max_age_periods >= 1, "max_age_periods", "must be >= 1");
  return r;
}

ForceScaleCorrection::ForceScaleCorrection(const ForceScaleSettings& settings, double force_range,
                                           double sample_period)
    : sample_period_(sample_period),
      time_constant_(settings.time_constant),
      lower_(1.0 - settings.max_correction),
      upper_(1.0 + settings.max_correction),
      min_force_(settings.min_force_fraction * force_range),
      min_speed_(settings.min_speed),
      rearm_margin_(0.1 * settings.max_correction),
      max_age_periods_(settings.max_age_periods) {}

ScaleUpdate ForceScaleCorrection::update(const LoadCellObservation& in) {
  reached_bound_ = false;
  const bool finite = std::isfinite(in.measured) && std::isfinite(in.predicted) && std::isfinite(in.viscous) &&
                      std::isfinite(in.velocity);
  if (in.status == LoadCellStatus::kBad || (in.status == LoadCellStatus::kFresh && !finite)) {
    ++bad_samples_;
    if (periods_since_fresh_ < max_age_periods_ + 1) ++periods_since_fresh_;  // saturates: no overflow
    return ScaleUpdate::kBad;
  }
  if (in.status == LoadCellStatus::kNone) {
    if (periods_since_fresh_ < max_age_periods_ + 1) ++periods_since_fresh_;  // saturates: no overflow
    if (periods_since_fresh_ <= max_age_periods_) return ScaleUpdate::kWaiting;
    ++stale_periods_;
    return ScaleUpdate::kStale;
  }
  // The time this sample stands for: the periods since the previous fresh one, so that tau is
  // in seconds whatever the load cell's rate (one sample every 10 periods moves 10 periods' worth).
  const double dt = (periods_since_fresh_ + 1) * sample_period_;
  periods_since_fresh_ = 0;
  const double measured_yield = in.measured - in.viscous;
  const double model_yield = in.predicted - in.viscous;
  // On the yield parts, not the whole forces: at speed the viscous part alone can pass a force
  // gate while the yield part (the ratio's denominator) is the zero-field stress's few hundred N.
  const bool yielding = std::fabs(measured_yield) > min_force_ && std::fabs(model_yield) > min_force_ &&
                        std::fabs(in.velocity) > min_speed_ && measured_yield * model_yield > 0.0;
  if (!yielding) return ScaleUpdate::kGatedOut;
  // The target may lie past a bound (the scale then reaches it in finite time and stops there),
  // but not by more than the band's width, so one wild ratio cannot throw the scale.
  const double band = upper_ - lower_;
  const double target = std::clamp(scale_ * measured_yield / model_yield, lower_ - band, upper_ + band);
  const double gain = -std::expm1(-dt / time_constant_);  // 1 - exp(-dt / tau)
  scale_ = std::clamp(scale_ + gain * (target - scale_), lower_, upper_);
  at_bound_ = scale_ == lower_ || scale_ == upper_;
  // Said once per arrival: noise that lifts the scale off the bound and back says nothing new
  // until the scale has come a tenth of the band's half-width back inside.
  reached_bound_ = at_bound_ && armed_;
  if (at_bound_) armed_ = false;
  if (scale_ > lower_ + rearm_margin_ && scale_ < upper_ - rearm_margin_) armed_ = true;
  ++moves_;
  return ScaleUpdate::kMoved;
}

}  // namespace mrd::control
