#include "model/effects/coil_lag.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace mrd::model {

ValidationReport validate(const CoilLagParams& p) {
  ValidationReport report;
  report.require_in_range("time_constant", p.time_constant, 0.0, 10.0, false);
  return report;
}

namespace {

// The share of the distance to the command covered in dt: 1 - exp(-dt/tau), 1 without a lag.
double lag_gain(double dt, double time_constant) {
  return time_constant > 0.0 ? -std::expm1(-dt / time_constant) : 1.0;
}

}  // namespace

CoilLag::CoilLag(const CoilLagParams& params, double sample_period)
    : time_constant_(params.time_constant),
      period_(sample_period),
      gain_(lag_gain(sample_period, params.time_constant)) {}

double CoilLag::gain_over(double dt) const { return dt == period_ ? gain_ : lag_gain(dt, time_constant_); }

void CoilLag::set_step(double dt) {
  gain_ = lag_gain(dt, time_constant_);
  period_ = dt;
}

double CoilLag::step(double command) {
  if (std::isfinite(command)) current_ += gain_ * (command - current_);
  return current_;
}

double CoilLag::command_for(double target_current, double dt, const CurrentRange& driver) const {
  const double command = current_ + (target_current - current_) / gain_over(dt);
  // A NaN target (or dt = 0 with no distance to go) holds the present current.
  return std::clamp(std::isnan(command) ? current_ : command, driver.lowest, driver.highest);
}

CurrentRange CoilLag::reachable(double dt, const CurrentRange& driver) const {
  const double gain = gain_over(dt);
  return {.lowest = current_ + gain * (driver.lowest - current_),
          .highest = current_ + gain * (driver.highest - current_)};
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
