#pragma once

#include "model/current_range.hpp"
#include "model/jiles_atherton.hpp"
#include "model/slew_limiter.hpp"
#include "model/target_curve.hpp"

namespace mrd::model {

struct CompensatorLimits {
  double min_current = 0.0;  // [A]; 0 for a unipolar driver
  double max_current = 1.5;  // [A]; above Table 4's 1.2 A so the top target is reachable
  double slew_rate = 100.0;  // [A/s]
  double tolerance = 1e-5;   // B tolerance of the inverse [T]
  int max_iterations = 24;
};

// What the inverse J-A search found: the best current, the B it gives and whether that B is
// within the tolerance of the target.
struct InductionSearch {
  double current = 0.0;  // [A]
  double B = 0.0;        // after one period at that current [T]
  bool reached = false;
  int evaluations = 0;   // trial integrations of Eq. 10: at most 2 + max_iterations
};

// Inverse Jiles-Atherton. The schedule's current names a target B on the TargetCurve; the
// compensator finds the coil current that takes the present J-A state to that B by the end
// of the period. B after one period is monotone in the end current (dM/dH >= 0 on every
// physical branch of Eq. 10), so a bracketed Illinois (modified regula falsi) search over the
// interval the slew limit allows always converges; a target outside it saturates at the
// nearer end. No heap: each trial integrates a scratch copy of the state.
//
// Worst case of one search: 2 + max_iterations integrations of Eq. 10, each over at most the
// interval's width in current (sub-steps of max_field_step_fraction min(a (1 - alpha Ms/3a), k) in H).
class HysteresisCompensator {
 public:
  HysteresisCompensator(const JilesAtherton& prototype, const TargetCurve& target,
                        const CompensatorLimits& limits, double sample_period);

  // The current to command this period, given the core's present state.
  double command(double scheduled_current, const JilesAtherton& core);
  // The current in `interval` that takes `core` to `target_B` [T] by the end of the period,
  // or the best the search found within its cap. Leaves the slew limiter alone: the caller
  // knows what stands between this current and the driver's command (a coil lag).
  InductionSearch current_for(double target_B, const JilesAtherton& core, const CurrentRange& interval);

  [[nodiscard]] double target_B() const { return target_B_; }
  [[nodiscard]] const TargetCurve& target() const { return target_; }
  [[nodiscard]] double last_command() const { return limiter_.value(); }
  [[nodiscard]] int last_iterations() const { return iterations_; }
  void reset(double current = 0.0) { limiter_.reset(current); }

 private:
  // A bracket of the target: B_after(lo) - target < 0 < B_after(hi) - target.
  struct Bracket {
    double lo, f_lo, hi, f_hi;
  };
  double B_after(double current, const JilesAtherton& core);
  InductionSearch bracketed(double target_B, const JilesAtherton& core, Bracket b, int evaluations);

  JilesAtherton scratch_;
  TargetCurve target_;
  CompensatorLimits limits_;
  SlewLimiter limiter_;
  double target_B_ = 0.0;
  int iterations_ = 0;
};

}  // namespace mrd::model
