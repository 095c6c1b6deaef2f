#include "model/effects/gas_spring.hpp"

#include <cmath>
#include <cstdio>

namespace mrd::model {

ValidationReport validate(const GasSpringParams& p) {
  ValidationReport report;
  if (!std::isfinite(p.preload)) report.error("preload", "must be finite");
  if (!std::isfinite(p.stiffness)) report.error("stiffness", "must be finite");
  return report;
}

std::optional<std::string> GasSpringEffect::implausible(const Params& p, const RunScales&) {
  if (p.stiffness < 0.0) return "negative stiffness (a gas spring stiffens as it compresses)";
  return std::nullopt;
}

std::string GasSpringEffect::size_summary(const Params& p) {
  char text[64];
  std::snprintf(text, sizeof text, "F0 = %.4g N, k = %.4g N/m", p.preload, p.stiffness);
  return text;
}

}  // namespace mrd::model
