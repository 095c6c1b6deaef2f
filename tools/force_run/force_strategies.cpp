#include "tools/force_run/force_strategies.hpp"

#include <cmath>

namespace mrd::tools {

std::string_view strategy_name(StrategyKind kind) {
  switch (kind) {
    case StrategyKind::kClippedOnOff: return "clipped_on_off";
    case StrategyKind::kInverseBingham: return "inverse_bingham";
    case StrategyKind::kInverseJa: return "inverse_ja";
    case StrategyKind::kInverseJaLag: return "inverse_ja_lag";
    case StrategyKind::kInverseJaLoadCell: return "inverse_ja_load_cell";
  }
  return "?";
}

bool clipped_on_off_wants_maximum(double desired, double measured) { return (desired - measured) * measured > 0.0; }

ClippedOnOff::ClippedOnOff(const model::CompensatorLimits& limits, double sample_period)
    : driver_(limits.min_current, limits.max_current, limits.slew_rate, sample_period),
      max_current_(limits.max_current) {}

double ClippedOnOff::command(const StrategyInput& in, const model::Observer&) {
  return driver_.update(clipped_on_off_wants_maximum(in.demand.force, in.measured_force) ? max_current_ : 0.0);
}

InverseBingham::InverseBingham(const model::Observer& observer, const model::CompensatorLimits& limits)
    : yield_stress_(observer.yield_stress()),
      damper_(observer.damper()),
      curve_(observer.magnetics(), limits.max_current),
      driver_(limits.min_current, limits.max_current, limits.slew_rate, observer.sample_period()),
      min_yield_stress_(yield_stress_.zero_field_stress()),
      max_yield_stress_(yield_stress_(curve_.B(limits.max_current))) {}

double InverseBingham::current_for(double B) const {
  const double target = std::fabs(B);
  double lo = 0.0, hi = curve_.max_current();
  if (!(target > 0.0)) return 0.0;  // no field wanted (or NaN): no current
  if (target >= curve_.B(hi)) return hi;
  for (int i = 0; i < 60 && hi - lo > 1e-9; ++i) {  // the curve rises with the current
    const double mid = 0.5 * (lo + hi);
    (curve_.B(mid) < target ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

double InverseBingham::command(const StrategyInput& in, const model::Observer&) {
  double tau = min_yield_stress_;
  if (std::isfinite(in.demand.force) && std::isfinite(in.demand.velocity)) {
    tau = std::fmin(std::fmax(damper_.yield_stress_for({.force = in.demand.force, .velocity = in.demand.velocity}), min_yield_stress_),
                    max_yield_stress_);
  }
  return driver_.update(current_for(yield_stress_.induction(tau)));
}

InverseJa::InverseJa(const model::Observer& observer, const model::CompensatorLimits& limits, bool invert_coil_lag)
    : inverse_(observer, limits, {.invert_coil_lag = invert_coil_lag}) {}

double InverseJa::command(const StrategyInput& in, const model::Observer& observer) {
  return inverse_.step(in.demand, observer).current;
}

std::unique_ptr<ForceStrategy> make_strategy(StrategyKind kind, const model::Observer& observer,
                                             const model::CompensatorLimits& limits) {
  switch (kind) {
    case StrategyKind::kClippedOnOff: return std::make_unique<ClippedOnOff>(limits, observer.sample_period());
    case StrategyKind::kInverseBingham: return std::make_unique<InverseBingham>(observer, limits);
    case StrategyKind::kInverseJa: return std::make_unique<InverseJa>(observer, limits, false);
    case StrategyKind::kInverseJaLag: return std::make_unique<InverseJa>(observer, limits, true);
    case StrategyKind::kInverseJaLoadCell: return std::make_unique<InverseJa>(observer, limits, false);
  }
  return nullptr;
}

}  // namespace mrd::tools
