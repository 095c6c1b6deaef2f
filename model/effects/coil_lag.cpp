#include "model/effects/coil_lag.hpp"

#include <cmath>
#include <cstdio>

namespace mrd::model {

ValidationReport validate(const CoilLagParams& p) {
  ValidationReport report;
  report.require_in_range("time_constant", p.time_constant, 0.0, 10.0, false);
  return report;
}

CoilLag::CoilLag(const CoilLagParams& params, double sample_period)
    : gain_(params.time_constant > 0.0 ? -std::expm1(-sample_period / params.time_constant) : 1.0) {}

double CoilLag::step(double command) {
  if (std::isfinite(command)) current_ += gain_ * (command - current_);
  return current_;
}

std::optional<std::string> CoilLagEffect::implausible(const Params& p, const RunScales& s) {
  if (p.time_constant < s.sample_period) return "time constant below one sample";
  return std::nullopt;
}

std::string CoilLagEffect::size_summary(const Params& p) {
  char text[64];
  std::snprintf(text, sizeof text, "tau = %.3g ms", p.time_constant * 1e3);
  return text;
}

}  // namespace mrd::model
