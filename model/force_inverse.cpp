#include "model/force_inverse.hpp"

#include <cmath>

#include "model/target_curve.hpp"

namespace mrd::model {

ForceInverse::ForceInverse(const Observer& observer, const CompensatorLimits& limits,
                           const ForceInverseOptions& options)
    : yield_stress_(observer.yield_stress()),
      damper_(observer.damper()),
      compensator_(observer.magnetics(), TargetCurve(observer.magnetics(), limits.max_current), limits,
                   observer.sample_period()),
      driver_(limits.min_current, limits.max_current, limits.slew_rate, observer.sample_period()),
      sample_period_(observer.sample_period()),
      min_yield_stress_(yield_stress_.zero_field_stress()),
      max_yield_stress_(yield_stress_(compensator_.target().B(limits.max_current))),
      invert_coil_lag_(options.invert_coil_lag) {}

double ForceInverse::aimed_yield_stress(const ForceDemand& demand, double scale, bool& clipped) const {
  if (!std::isfinite(demand.force) || !std::isfinite(demand.velocity)) {
    clipped = true;  // the safe answer to a bad demand: the least force
    return min_yield_stress_;
  }
  // Negative where the demand pushes with the motion or asks less than c0 v (Eq. 11-12). The
  // observer's yield scale multiplies Eq. 13's stress, so the model's stress is the needed one
  // divided by it.
  const double needed = damper_.yield_stress_for({.force = demand.force, .velocity = demand.velocity}) / scale;
  clipped = !(needed >= min_yield_stress_ && needed <= max_yield_stress_);
  return std::fmin(std::fmax(needed, min_yield_stress_), max_yield_stress_);
}

ForceCommand ForceInverse::step(const ForceDemand& demand, const Observer& observer) {
  ForceCommand out;
  const double scale = observer.yield_scale();
  const double tau = aimed_yield_stress(demand, scale, out.clipped);
  out.yield_force = damper_.yield_force(tau * scale);
  // Eq. 13 gives |B|; the polarity the core already has is the one nearer.
  const JilesAtherton& core = observer.magnetics();
  out.target_B = std::copysign(yield_stress_.induction(tau), core.B());

  // The currents that can flow by the end of the period, from the commands the driver allows
  // now; the J-A search picks one, and the command is what makes it flow.
  const CurrentRange commands{.lowest = driver_.lowest_next(), .highest = driver_.highest_next()};
  const EffectChain& chain = observer.effects();
  const CurrentRange flowing = invert_coil_lag_ ? chain.reachable_current(commands, sample_period_) : commands;
  const InductionSearch found = compensator_.current_for(out.target_B, core, flowing);
  const double command =
      invert_coil_lag_ ? chain.command_for(found.current, sample_period_, commands) : found.current;
  out.current = driver_.update(command);
  out.reached = found.reached;
  evaluations_ = found.evaluations;
  return out;
}

}  // namespace mrd::model
