#include "model/hysteresis_compensator.hpp"

#include <cmath>

namespace mrd::model {

HysteresisCompensator::HysteresisCompensator(const JilesAtherton& prototype,
                                             const TargetCurve& target,
                                             const CompensatorLimits& limits, double sample_period)
    : scratch_(prototype),
      target_(target),
      limits_(limits),
      limiter_(limits.min_current, limits.max_current, limits.slew_rate, sample_period) {}

double HysteresisCompensator::B_after(double current, const JilesAtherton& core) {
  scratch_.restore(core.state());
  return scratch_.apply_current(current);
}

double HysteresisCompensator::command(double scheduled_current, const JilesAtherton& core) {
  target_B_ = target_.B(scheduled_current);
  iterations_ = 0;
  double lo = limiter_.lowest_next();
  double hi = limiter_.highest_next();
  double f_lo = B_after(lo, core) - target_B_;
  if (f_lo >= 0.0) return limiter_.update(lo);
  double f_hi = B_after(hi, core) - target_B_;
  if (f_hi <= 0.0) return limiter_.update(hi);

  // Illinois: regula falsi that halves the stale end's residual, so it never stalls.
  double current = lo;
  int stale_side = 0;
  for (iterations_ = 1; iterations_ <= limits_.max_iterations; ++iterations_) {
    current = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
    const double f = B_after(current, core) - target_B_;
    if (std::fabs(f) <= limits_.tolerance) break;
    if (f < 0.0) {
      lo = current;
      f_lo = f;
      if (stale_side == -1) f_hi *= 0.5;
      stale_side = -1;
    } else {
      hi = current;
      f_hi = f;
      if (stale_side == 1) f_lo *= 0.5;
      stale_side = 1;
    }
  }
  return limiter_.update(current);
}

}  // namespace mrd::model
