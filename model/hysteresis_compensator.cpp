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
  const double lo = limiter_.lowest_next();
  const double hi = limiter_.highest_next();
  const double f_lo = B_after(lo, core) - target_B_;
  if (f_lo >= 0.0) return limiter_.update(lo);
  const double f_hi = B_after(hi, core) - target_B_;
  if (f_hi <= 0.0) return limiter_.update(hi);
  return limiter_.update(bracketed(target_B_, core, {lo, f_lo, hi, f_hi}, 2).current);
}

InductionSearch HysteresisCompensator::current_for(double target_B, const JilesAtherton& core,
                                                   const CurrentRange& interval) {
  iterations_ = 0;
  // The present current is where B(I) has its kink (the branch reverses there), and its B
  // costs no integration: inside the interval it bounds the side the target is on.
  const double now = core.circuit().current_from_field(core.H());
  const bool inside = now > interval.lowest && now < interval.highest;
  const double f_now = core.B() - target_B;
  if (inside && std::fabs(f_now) <= limits_.tolerance) return {.current = now, .B = core.B(), .reached = true};
  Bracket b{.lo = interval.lowest, .f_lo = f_now, .hi = interval.highest, .f_hi = f_now};
  int evaluations = 0;
  if (!inside || f_now >= 0.0) {
    b.f_lo = B_after(b.lo, core) - target_B;
    ++evaluations;
    if (b.f_lo >= 0.0) {
      return {.current = b.lo,
              .B = b.f_lo + target_B,
              .reached = b.f_lo <= limits_.tolerance,
              .evaluations = evaluations};
    }
  } else {
    b.lo = now;
  }
  if (!inside || f_now < 0.0) {
    b.f_hi = B_after(b.hi, core) - target_B;
    ++evaluations;
    if (b.f_hi <= 0.0) {
      return {.current = b.hi,
              .B = b.f_hi + target_B,
              .reached = -b.f_hi <= limits_.tolerance,
              .evaluations = evaluations};
    }
  } else {
    b.hi = now;
  }
  return bracketed(target_B, core, b, evaluations);
}

InductionSearch HysteresisCompensator::bracketed(double target_B, const JilesAtherton& core, Bracket b,
                                                 int evaluations) {
  // Illinois: regula falsi that halves the stale end's residual, so it never stalls. Both
  // ends' residuals get scaled, so the best trial is kept apart from them.
  // Here `B` holds the best trial's residual, B - target, until the end.
  InductionSearch best{.current = b.lo, .B = b.f_lo, .evaluations = evaluations};
  if (-b.f_lo > b.f_hi) best = {.current = b.hi, .B = b.f_hi, .evaluations = evaluations};
  int stale_side = 0;
  for (iterations_ = 1; iterations_ <= limits_.max_iterations; ++iterations_) {
    const double current = (b.lo * b.f_hi - b.hi * b.f_lo) / (b.f_hi - b.f_lo);
    const double f = B_after(current, core) - target_B;
    ++best.evaluations;
    if (std::fabs(f) <= std::fabs(best.B)) {
      best.current = current;
      best.B = f;
    }
    if (std::fabs(f) <= limits_.tolerance) break;
    if (f < 0.0) {
      b.lo = current;
      b.f_lo = f;
      if (stale_side == -1) b.f_hi *= 0.5;
      stale_side = -1;
    } else {
      b.hi = current;
      b.f_hi = f;
      if (stale_side == 1) b.f_lo *= 0.5;
      stale_side = 1;
    }
  }
  best.reached = std::fabs(best.B) <= limits_.tolerance;
  best.B += target_B;  // the residual back to a field
  return best;
}

}  // namespace mrd::model
