#include "model/jiles_atherton_params.hpp"

#include <string>

#include "model/typical_ranges.hpp"

namespace mrd::model {

ValidationReport validate(const JilesAthertonParams& p) {
  ValidationReport report;
  // Bounds past every known material (FeCo saturates near 2e6 A/m), so that only nonsense fails.
  report.require_positive("Ms", p.Ms, 1e7);
  report.require_positive("a", p.a, 1e6);
  report.require_in_range("alpha", p.alpha, 0.0, 1.0, false);
  report.require_positive("k", p.k, 1e6);
  report.require_in_range("c", p.c, 0.0, 1.0, /*hi_open=*/true);
  if (report.ok() && p.mean_field_gain() >= 1.0) {
    report.warning("alpha", "alpha*Ms/(3a) = " + format_value(p.mean_field_gain()) +
                                " >= 1: the anhysteretic curve folds back and Eq. 10 can run away "
                                "at some loop amplitudes (docs/MODEL.md)");
  } else if (report.ok()) {
    report.expect_typical("alpha", p.mean_field_gain(), kTypicalMeanFieldGain.lo, kTypicalMeanFieldGain.hi,
                          "soft and hard steels", "alpha*Ms/(3a)");
  }
  if (report.ok()) {
    report.expect_typical("k", p.k / p.a, kTypicalPinningOverShape.lo, kTypicalPinningOverShape.hi,
                          "soft irons to hard steels", "k/a");
    report.expect_typical("c", p.c, kTypicalReversibility.lo, kTypicalReversibility.hi, "soft irons to hard steels");
  }
  return report;
}

ValidationReport validate(const MagneticCircuit& circuit) {
  ValidationReport report;
  report.require_positive("turns", circuit.turns, 1e6);
  report.require_positive("effective_length", circuit.effective_length, 10.0);  // [m]
  return report;
}

}  // namespace mrd::model
