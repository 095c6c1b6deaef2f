#pragma once

#include <optional>

#include "control/sample_check.hpp"
#include "hal/clock.hpp"
#include "hal/sample.hpp"

namespace mrd::control {

// What the force demand must satisfy (force mode).
struct DemandLimits {
  double range = 60e3;       // [N] |demand| above is out of range
  hal::Timestamp max_age{};  // older is stale; this far ahead of the release time is from the future
};

// Step 2 of a force-mode cycle for the demand: the LVDT's checks that mean something for a
// number an outer controller sends (missing, stale by sequence or age, from the future,
// corrupted, not finite, out of range), with the last good demand held, which the law keeps
// using while demands are missing or bad. No frozen or jump check: a held or stepped demand
// is a fair one. The results are SampleCheck's values; the supervisor names them as demand
// triggers.
class DemandChecker {
 public:
  explicit DemandChecker(const DemandLimits& limits)
      : checker_({.min = -limits.range, .max = limits.range, .max_age = limits.max_age}) {}

  SampleCheck check(const std::optional<hal::Sample>& demand, hal::Timestamp now) {  // value [N]
    return checker_.check(demand, now);
  }
  [[nodiscard]] double held_value() const { return checker_.held_value(); }  // [N], 0 before the first
  [[nodiscard]] bool has_value() const { return checker_.has_value(); }

 private:
  SampleChecker checker_;
};

}  // namespace mrd::control
