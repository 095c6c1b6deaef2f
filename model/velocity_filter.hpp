#pragma once

namespace mrd::model {

// Velocity from displacement when the rig has no velocity sensor: a fading-memory
// alpha-beta-gamma tracker (the steady-state Kalman filter of a constant-acceleration
// motion). Unlike a low-passed derivative it has no lag for motion of constant acceleration,
// which is what a sine looks like at its reversals, where the Bingham force flips sign and a
// late velocity sign costs twice the yield force. With theta = exp(-2 pi f_c T):
//   g = 1 - theta^3, h = 1.5 (1 - theta)^2 (1 + theta), k = 0.5 (1 - theta)^3
// The cutoff f_c sets the trade between LVDT noise and response to jerk (default 20 Hz).
// Samples that arrive at uneven intervals (a bus polled on its own clock) are tracked with the
// gains of their own interval; the velocity is then carried to the moment it is needed.
class VelocityFilter {
 public:
  VelocityFilter(double sample_period, double cutoff_frequency);

  double update(double displacement);  // one sample period after the last; returns velocity [m/s]
  // A sample taken `interval` [s] after the previous one (> 0; otherwise only a first sample
  // counts, which primes the tracker).
  double update(double displacement, double interval);
  [[nodiscard]] double velocity() const { return velocity_; }
  // The velocity `elapsed` [s] after the last sample, at its tracked acceleration.
  [[nodiscard]] double velocity_after(double elapsed) const { return velocity_ + acceleration_ * elapsed; }
  [[nodiscard]] double acceleration() const { return acceleration_; }  // [m/s^2]
  void reset() { primed_ = false; position_ = velocity_ = acceleration_ = 0.0; }

 private:
  struct Gains {
    double g;
    double h_over_T;
    double two_k_over_T2;
  };
  static Gains gains_for(double cutoff_frequency, double interval);
  double track(double displacement, double interval, const Gains& gains);

  double period_;
  double cutoff_;
  Gains nominal_;  // of the sample period
  double position_ = 0.0;
  double velocity_ = 0.0;
  double acceleration_ = 0.0;
  bool primed_ = false;
};

}  // namespace mrd::model
