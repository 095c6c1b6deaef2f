#pragma once

#include "common/validation_report.hpp"

namespace mrd::model {

// The five Jiles-Atherton parameters (Eq. 1-7, 10). SI units throughout.
struct JilesAthertonParams {
  double Ms = 1.3e6;    // saturation magnetisation [A/m]
  double a = 2000.0;    // Langevin shape parameter [A/m] (the paper's beta in Eq. 3)
  double alpha = 1e-3;  // domain-wall interaction coefficient [-] (Eq. 4)
  double k = 1500.0;    // pinning / hysteresis loss parameter [A/m] (Eq. 5-7)
  double c = 0.2;       // reversible magnetisation factor [-] (Eq. 2)

  // alpha*Ms/(3a): the slope of alpha*Man at He = 0. At or above 1 the anhysteretic curve
  // folds back on itself and Eq. 10 can run away (see docs/MODEL.md).
  [[nodiscard]] double mean_field_gain() const { return alpha * Ms / (3.0 * a); }

  bool operator==(const JilesAthertonParams&) const = default;
};

// Eq. 9: H = N I / Le, a lumped magnetic circuit.
struct MagneticCircuit {
  double turns = 600.0;            // N [-]
  double effective_length = 0.06;  // Le [m]

  [[nodiscard]] double field_from_current(double current) const {
    return turns * current / effective_length;
  }
  [[nodiscard]] double current_from_field(double field) const {
    return field * effective_length / turns;
  }

  bool operator==(const MagneticCircuit&) const = default;
};

// Errors for values outside physics, a warning for alpha*Ms/(3a) >= 1.
ValidationReport validate(const JilesAthertonParams& p);
ValidationReport validate(const MagneticCircuit& circuit);

}  // namespace mrd::model
