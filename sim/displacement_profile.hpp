#pragma once

#include <cstdint>
#include <vector>

namespace mrd::sim {

// The paper's rig motion: x = A sin(2 pi f t), the LVDT reading in metres.
struct SineProfile {
  double amplitude = 0.040;  // [m]
  double frequency = 0.5;    // [Hz]

  [[nodiscard]] double displacement(double t) const;
  [[nodiscard]] double velocity(double t) const;
};

// The paper's sine tests one after the other: whole cycles at each frequency in turn, every
// segment starting at x = 0 moving up, so the motion is continuous at the joins and keeps its
// direction (the speed steps with the frequency).
class SineSequenceProfile {
 public:
  SineSequenceProfile(double amplitude, std::vector<double> frequencies, int cycles_each);

  [[nodiscard]] double displacement(double t) const;
  [[nodiscard]] double velocity(double t) const;
  [[nodiscard]] double duration() const { return duration_; }

 private:
  [[nodiscard]] SineProfile segment(double t, double& local) const;

  double amplitude_;
  std::vector<double> frequencies_;
  std::vector<double> starts_;  // segment start times [s]
  double duration_;
};

// Band-limited random motion: a sum of sines at random frequencies, uniform in
// [low, high] Hz, with random phases and equal amplitudes (a flat spectrum over the band),
// deterministic for a seed. Smooth, so its velocity is exact. Scaled so that the largest |x| on
// the sample grid of [0, duration] is `peak`: the run uses the whole stroke and never leaves it.
class RandomProfile {
 public:
  static constexpr int kComponents = 64;

  RandomProfile(double peak, double low, double high, double duration, double sample_period,
                std::uint64_t seed);

  [[nodiscard]] double displacement(double t) const;
  [[nodiscard]] double velocity(double t) const;

 private:
  struct Component {
    double omega;  // [rad/s]
    double phase;  // [rad]
  };
  std::vector<Component> components_;
  double scale_ = 1.0;  // amplitude of each component [m]
};

// Playback of a recorded displacement: linear interpolation between the samples, time shifted
// so that the first sample is at t = 0, held at the last value after the end. The velocity is
// the slope of the segment t falls in (the interpolant's own derivative), 0 outside the run.
class PlaybackProfile {
 public:
  // `time` strictly increasing [s], `displacement` [m], at least two samples of each.
  PlaybackProfile(std::vector<double> time, std::vector<double> displacement);

  [[nodiscard]] double displacement(double t) const;
  [[nodiscard]] double velocity(double t) const;
  [[nodiscard]] double duration() const { return time_.back(); }

 private:
  [[nodiscard]] std::size_t segment(double t) const;  // i with time_[i] <= t < time_[i + 1]

  std::vector<double> time_;
  std::vector<double> displacement_;
};

}  // namespace mrd::sim
