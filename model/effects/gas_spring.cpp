#include "model/effects/gas_spring.hpp"

#include <cmath>

namespace mrd::model {

ValidationReport validate(const GasSpringParams& p) {
  ValidationReport report;
  if (!std::isfinite(p.preload)) report.error("preload", "must be finite");
  if (!std::isfinite(p.stiffness)) report.error("stiffness", "must be finite");
  return report;
}

}  // namespace mrd::model
