#include "model/velocity_filter.hpp"

#include <cmath>
#include <numbers>

namespace mrd::model {

VelocityFilter::VelocityFilter(double sample_period, double cutoff_frequency)
    : period_(sample_period) {
  const double theta = std::exp(-2.0 * std::numbers::pi * cutoff_frequency * sample_period);
  const double one_minus = 1.0 - theta;
  g_ = 1.0 - theta * theta * theta;
  h_over_T_ = 1.5 * one_minus * one_minus * (1.0 + theta) / sample_period;
  two_k_over_T2_ = one_minus * one_minus * one_minus / (sample_period * sample_period);
}

double VelocityFilter::update(double displacement) {
  if (!primed_) {  // the first sample has no history: assume the rig was at rest
    position_ = displacement;
    primed_ = true;
    return velocity_;
  }
  const double T = period_;
  const double predicted_position = position_ + T * (velocity_ + 0.5 * T * acceleration_);
  const double predicted_velocity = velocity_ + T * acceleration_;
  const double residual = displacement - predicted_position;
  position_ = predicted_position + g_ * residual;
  velocity_ = predicted_velocity + h_over_T_ * residual;
  acceleration_ += two_k_over_T2_ * residual;
  return velocity_;
}

}  // namespace mrd::model
