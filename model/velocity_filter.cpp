#include "model/velocity_filter.hpp"

#include <cmath>
#include <numbers>

namespace mrd::model {

VelocityFilter::Gains VelocityFilter::gains_for(double cutoff_frequency, double interval) {
  const double theta = std::exp(-2.0 * std::numbers::pi * cutoff_frequency * interval);
  const double one_minus = 1.0 - theta;
  return {1.0 - theta * theta * theta, 1.5 * one_minus * one_minus * (1.0 + theta) / interval,
          one_minus * one_minus * one_minus / (interval * interval)};
}

VelocityFilter::VelocityFilter(double sample_period, double cutoff_frequency)
    : period_(sample_period),
      cutoff_(cutoff_frequency),
      nominal_(gains_for(cutoff_frequency, sample_period)) {}

double VelocityFilter::update(double displacement) { return track(displacement, period_, nominal_); }

double VelocityFilter::update(double displacement, double interval) {
  if (!primed_ || interval == period_) return track(displacement, period_, nominal_);
  if (!(interval > 0.0)) return velocity_;
  return track(displacement, interval, gains_for(cutoff_, interval));
}

double VelocityFilter::track(double displacement, double T, const Gains& gains) {
  if (!primed_) {  // the first sample has no history: assume the rig was at rest
    position_ = displacement;
    primed_ = true;
    return velocity_;
  }
  const double predicted_position = position_ + T * (velocity_ + 0.5 * T * acceleration_);
  const double predicted_velocity = velocity_ + T * acceleration_;
  const double residual = displacement - predicted_position;
  position_ = predicted_position + gains.g * residual;
  velocity_ = predicted_velocity + gains.h_over_T * residual;
  acceleration_ += gains.two_k_over_T2 * residual;
  return velocity_;
}

}  // namespace mrd::model
