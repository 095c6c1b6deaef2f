#pragma once

#include "common/validation_report.hpp"

namespace mrd::model {

// The coil (and its driver) lag behind the commanded current: a first-order lag
//   tau di/dt = u - i,
// the L/R time constant of the coil and the driver's current loop lumped into one tau.
// Spencer et al. (1997) model the same lag for Dyke's damper as u' = -eta (u - v) with
// eta = 190 1/s, i.e. tau = 1/eta = 5.3 ms.
struct CoilLagParams {
  bool enabled = false;
  double time_constant = 5e-3;  // tau [s]; 0 means no lag

  bool operator==(const CoilLagParams&) const = default;
};

ValidationReport validate(const CoilLagParams& params);

// Exact zero-order-hold discretisation: a command held over one period T moves the current by
// (1 - exp(-T/tau)) of the distance to it, whatever T/tau is, so the lag is stable and exact at
// any sample rate. No heap, no exceptions.
class CoilLag {
 public:
  CoilLag(const CoilLagParams& params, double sample_period);

  // `command` [A] held over this period; returns the current at its end [A]. A non-finite
  // command holds the present current (the observer must not be poisoned by one bad value).
  double step(double command);
  [[nodiscard]] double current() const { return current_; }
  void reset(double current = 0.0) { current_ = current; }

 private:
  double gain_;  // 1 - exp(-T/tau)
  double current_ = 0.0;
};

}  // namespace mrd::model
