#include "model/jiles_atherton_params.hpp"

#include <string>

namespace mrd::model {

ValidationReport validate(const JilesAthertonParams& p) {
  ValidationReport report;
  report.require_positive("Ms", p.Ms);
  report.require_positive("a", p.a);
  report.require_non_negative("alpha", p.alpha);
  report.require_positive("k", p.k);
  report.require_in_range("c", p.c, 0.0, 1.0, /*hi_open=*/true);
  if (report.ok() && p.mean_field_gain() >= 1.0) {
    report.warning("alpha", "alpha*Ms/(3a) = " + std::to_string(p.mean_field_gain()) +
                                " >= 1: the anhysteretic curve folds back and Eq. 10 can run away "
                                "at some loop amplitudes (docs/MODEL.md)");
  }
  return report;
}

ValidationReport validate(const MagneticCircuit& circuit) {
  ValidationReport report;
  report.require_positive("turns", circuit.turns);
  report.require_positive("effective_length", circuit.effective_length);
  return report;
}

}  // namespace mrd::model
