#pragma once

namespace mrd::model {

// Velocity from displacement when the rig has no velocity sensor: a fading-memory
// alpha-beta-gamma tracker (the steady-state Kalman filter of a constant-acceleration
// motion). Unlike a low-passed derivative it has no lag for motion of constant acceleration,
// which is what a sine looks like at its reversals, where the Bingham force flips sign and a
// late velocity sign costs twice the yield force. With theta = exp(-2 pi f_c T):
//   g = 1 - theta^3, h = 1.5 (1 - theta)^2 (1 + theta), k = 0.5 (1 - theta)^3
// The cutoff f_c sets the trade between LVDT noise and response to jerk (default 20 Hz).
class VelocityFilter {
 public:
  VelocityFilter(double sample_period, double cutoff_frequency);

  double update(double displacement);  // returns velocity [m/s]
  [[nodiscard]] double velocity() const { return velocity_; }
  [[nodiscard]] double acceleration() const { return acceleration_; }  // [m/s^2]
  void reset() { primed_ = false; position_ = velocity_ = acceleration_ = 0.0; }

 private:
  double period_;
  double g_;
  double h_over_T_;
  double two_k_over_T2_;
  double position_ = 0.0;
  double velocity_ = 0.0;
  double acceleration_ = 0.0;
  bool primed_ = false;
};

}  // namespace mrd::model
