#pragma once

#include "common/validation_report.hpp"

namespace mrd::model {

// The gas accumulator of a single-tube damper: its pressure on the rod adds a force that does not
// depend on velocity or field,
//   F_gas = F0 + k x,
// F0 the preload at x = 0 and k the gas stiffness (rod volume entering the accumulator). Spencer
// et al. (1997) model it the same way, k1 (x - x0), on Dyke's damper: k1 = 500 N/m, k1 x0 = 71.5 N.
// Both carry the sign convention of the force measurement, so either may be negative.
struct GasSpringParams {
  bool enabled = false;
  double preload = 0.0;    // F0 [N]
  double stiffness = 0.0;  // k [N/m]
};

ValidationReport validate(const GasSpringParams& params);

class GasSpring {
 public:
  explicit GasSpring(const GasSpringParams& params)
      : preload_(params.preload), stiffness_(params.stiffness) {}
  [[nodiscard]] double force(double displacement) const { return preload_ + stiffness_ * displacement; }

 private:
  double preload_;
  double stiffness_;
};

}  // namespace mrd::model
