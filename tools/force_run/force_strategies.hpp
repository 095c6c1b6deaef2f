#pragma once

#include <memory>
#include <string_view>

#include "model/force_inverse.hpp"
#include "model/observer.hpp"
#include "model/slew_limiter.hpp"
#include "model/target_curve.hpp"

// The force-control strategies mrd-force-run compares (docs/FORCE-CONTROL.md). Each turns the
// period's demand into a current command through the same driver (range and slew); each knows
// only the controller's model, never the plant's.
namespace mrd::tools {

// kInverseJaLoadCell (mrd-force-run --load-cell) is inverse_ja with control::ForceScaleCorrection
// on the load cell: the run loop moves its observer's yield scale (force_run.cpp).
enum class StrategyKind { kClippedOnOff, kInverseBingham, kInverseJa, kInverseJaLag, kInverseJaLoadCell };
inline constexpr StrategyKind kAllStrategies[] = {StrategyKind::kClippedOnOff, StrategyKind::kInverseBingham,
                                                  StrategyKind::kInverseJa, StrategyKind::kInverseJaLag};
std::string_view strategy_name(StrategyKind kind);

// What a strategy sees each period.
struct StrategyInput {
  model::ForceDemand demand;
  double measured_force = 0.0;  // the load cell at the end of the last period [N]
};

class ForceStrategy {
 public:
  virtual ~ForceStrategy() = default;
  // `observer` is the controller's, stepped to the end of the last period.
  virtual double command(const StrategyInput& in, const model::Observer& observer) = 0;
};

// Dyke et al. (1996)'s clipped-optimal law: the maximum current while the measured force is
// below the desired one in the dissipative sense, (f_c - f) f > 0, else none.
[[nodiscard]] bool clipped_on_off_wants_maximum(double desired, double measured);

class ClippedOnOff final : public ForceStrategy {
 public:
  explicit ClippedOnOff(const model::CompensatorLimits& limits, double sample_period);
  double command(const StrategyInput& in, const model::Observer& observer) override;

 private:
  model::SlewLimiter driver_;
  double max_current_;
};

// A static inverse on the anhysteretic curve: Eq. 11-12 and 13 inverted as the J-A inverse
// does, then the current whose anhysteretic B (TargetCurve) is that |B|. No hysteresis, no lag:
// what a force-mode law without the paper's model would do.
class InverseBingham final : public ForceStrategy {
 public:
  InverseBingham(const model::Observer& observer, const model::CompensatorLimits& limits);
  double command(const StrategyInput& in, const model::Observer& observer) override;
  // The current >= 0 whose anhysteretic B is |B| (bisection on the tabulated curve), clamped to
  // [0, max_current].
  [[nodiscard]] double current_for(double B) const;

 private:
  model::YieldStress yield_stress_;
  model::BinghamDamper damper_;
  model::TargetCurve curve_;
  model::SlewLimiter driver_;
  double min_yield_stress_;
  double max_yield_stress_;
};

// model::ForceInverse: the J-A compensated inverse, the coil lag inverted or not.
class InverseJa final : public ForceStrategy {
 public:
  InverseJa(const model::Observer& observer, const model::CompensatorLimits& limits, bool invert_coil_lag);
  double command(const StrategyInput& in, const model::Observer& observer) override;

 private:
  model::ForceInverse inverse_;
};

std::unique_ptr<ForceStrategy> make_strategy(StrategyKind kind, const model::Observer& observer,
                                             const model::CompensatorLimits& limits);

}  // namespace mrd::tools
