#include "model/effects/stroke_end_air.hpp"

#include <cmath>
#include <cstdio>

namespace mrd::model {

ValidationReport validate(const StrokeEndAirParams& p) {
  ValidationReport report;
  report.require_positive("threshold", p.threshold);
  report.require_in_range("depth", p.depth, 0.0, 1.0, false);
  report.require_positive("length", p.length);
  report.require_non_negative("dead_travel", p.dead_travel);
  report.require_in_range("ramp_share", p.ramp_share, 0.0, 1.0, false);
  report.require_non_negative("reversal_travel", p.reversal_travel);
  return report;
}

StrokeEndAir::StrokeEndAir(const StrokeEndAirParams& p)
    : threshold_(p.threshold),
      depth_(p.depth),
      inv_length_(1.0 / p.length),
      dead_travel_(p.dead_travel),
      ramp_share_(p.ramp_share),
      reversal_travel_(p.reversal_travel) {}

void StrokeEndAir::reset() {
  started_ = false;
  direction_ = 0;
  armed_ = false;
  reversals_ = 0;
  factor_ = 1.0;
}

double StrokeEndAir::step(double x) {
  if (!std::isfinite(x)) return factor_;
  if (!started_) {
    started_ = true;
    extreme_ = x;
    return factor_;
  }
  if (direction_ == 0) {  // the first move that exceeds the reversal travel sets the direction
    if (std::fabs(x - extreme_) > reversal_travel_) {
      direction_ = x > extreme_ ? 1 : -1;
      extreme_ = x;
    }
    return factor_;
  }
  const double pullback = (extreme_ - x) * direction_;  // > 0: come back from the extreme
  if (pullback <= 0.0) {
    extreme_ = x;
  } else if (pullback > reversal_travel_) {
    reversal_ = extreme_;
    armed_ = std::fabs(reversal_) > threshold_;
    ++reversals_;
    direction_ = -direction_;
    extreme_ = x;
  }
  if (!armed_) {
    factor_ = 1.0;
    return factor_;
  }
  const double u = std::max(std::fabs(x - reversal_) - dead_travel_, 0.0) * inv_length_;  // in lengths
  const double exponential = ramp_share_ < 1.0 ? std::exp(-u) : 0.0;
  const double ramp = std::max(1.0 - u, 0.0);
  factor_ = 1.0 - depth_ * ((1.0 - ramp_share_) * exponential + ramp_share_ * ramp);
  return factor_;
}

std::optional<std::string> StrokeEndAirEffect::implausible(const Params& p, const RunScales&) {
  if (p.depth < 0.05) return "depth below 5 %";
  return std::nullopt;
}

std::string StrokeEndAirEffect::size_summary(const Params& p) {
  char text[160];
  std::snprintf(text, sizeof text, "depth %.2f after reversals beyond %.3g mm, recovery %.3g mm%s", p.depth,
                p.threshold * 1e3, p.length * 1e3,
                p.dead_travel > 0.0 || p.ramp_share > 0.0 ? " (with dead travel / ramp)" : "");
  return text;
}

}  // namespace mrd::model
