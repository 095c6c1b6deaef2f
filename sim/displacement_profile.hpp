#pragma once

#include <cstdint>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "common/sine_motion.hpp"

namespace mrd::sim {

// The paper's rig motion: x = A sin(2 pi f t), the LVDT reading in metres.
using SineProfile = SineMotion;

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

// Any one of the profiles above: the motion both the simulated rig (sim/plant) and the run
// generator (tools/simulation) drive sim::DamperPlant with.
class DisplacementProfile {
 public:
  using Variant = std::variant<SineProfile, SineSequenceProfile, RandomProfile, PlaybackProfile>;

  template <typename Profile>
    requires std::is_constructible_v<Variant, Profile&&>
  DisplacementProfile(Profile&& profile) : profile_(std::forward<Profile>(profile)) {}  // NOLINT: a profile is one

  [[nodiscard]] double displacement(double t) const {
    return std::visit([t](const auto& p) { return p.displacement(t); }, profile_);
  }
  [[nodiscard]] double velocity(double t) const {
    return std::visit([t](const auto& p) { return p.velocity(t); }, profile_);
  }
  // [s] of a profile with an end (a sequence, a playback); 0 for an endless one (a sine, a
  // random motion, which keeps moving past the span it was scaled on).
  [[nodiscard]] double duration() const;

 private:
  Variant profile_;
};

}  // namespace mrd::sim
