#include "model/effects/sensor_delay.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace mrd::model {

ValidationReport validate(const SensorDelayParams& p) {
  ValidationReport report;
  report.require_in_range("delay", p.delay, 0.0, kMaxSensorDelay, false);
  return report;
}

SensorDelay::SensorDelay(const SensorDelayParams& params, double sample_period) {
  const double periods = std::clamp(params.delay / sample_period, 0.0, double{kCapacity - 2});
  whole_ = static_cast<int>(std::floor(periods));
  fraction_ = periods - whole_;
}

double SensorDelay::at(int age) const {
  const int i = head_ - age;
  return ring_[static_cast<std::size_t>(i < 0 ? i + kCapacity : i)];
}

double SensorDelay::step(double value) {
  if (!primed_) {
    ring_.fill(value);
    primed_ = true;
  }
  head_ = head_ + 1 == kCapacity ? 0 : head_ + 1;
  ring_[static_cast<std::size_t>(head_)] = value;
  // Linear interpolation between the samples whole_ and whole_ + 1 periods old.
  return at(whole_) + fraction_ * (at(whole_ + 1) - at(whole_));
}

std::optional<std::string> SensorDelayEffect::implausible(const Params& p, const RunScales& s) {
  if (p.delay < 0.25 * s.sample_period) return "delay below a quarter sample";
  return std::nullopt;
}

std::string SensorDelayEffect::size_summary(const Params& p) {
  char text[64];
  std::snprintf(text, sizeof text, "%.3g ms", p.delay * 1e3);
  return text;
}

}  // namespace mrd::model
