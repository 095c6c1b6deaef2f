#include "sim/displacement_profile.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace mrd::sim {

SineSequenceProfile::SineSequenceProfile(double amplitude, std::vector<double> frequencies, int cycles_each)
    : amplitude_(amplitude), frequencies_(std::move(frequencies)), duration_(0.0) {
  for (const double f : frequencies_) {
    starts_.push_back(duration_);
    duration_ += cycles_each / f;
  }
}

SineProfile SineSequenceProfile::segment(double t, double& local) const {
  std::size_t i = 0;
  while (i + 1 < starts_.size() && t >= starts_[i + 1]) ++i;
  local = t - starts_[i];
  return {amplitude_, frequencies_[i]};
}

double SineSequenceProfile::displacement(double t) const {
  double local = 0.0;
  return segment(t, local).displacement(local);
}

double SineSequenceProfile::velocity(double t) const {
  double local = 0.0;
  return segment(t, local).velocity(local);
}

RandomProfile::RandomProfile(double peak, double low, double high, double duration, double sample_period,
                             std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> frequency(low, high);
  std::uniform_real_distribution<double> phase(0.0, 2.0 * std::numbers::pi);
  for (int i = 0; i < kComponents; ++i) {
    const double f = frequency(rng);
    components_.push_back({2.0 * std::numbers::pi * f, phase(rng)});
  }
  double largest = 0.0;
  const auto samples = static_cast<long>(std::ceil(duration / sample_period));
  for (long k = 0; k <= samples; ++k) {
    largest = std::max(largest, std::fabs(displacement(static_cast<double>(k) * sample_period)));
  }
  scale_ = largest > 0.0 ? peak / largest : 0.0;
}

double RandomProfile::displacement(double t) const {
  double x = 0.0;
  for (const auto& c : components_) x += std::sin(c.omega * t + c.phase);
  return scale_ * x;
}

double RandomProfile::velocity(double t) const {
  double v = 0.0;
  for (const auto& c : components_) v += c.omega * std::cos(c.omega * t + c.phase);
  return scale_ * v;
}

PlaybackProfile::PlaybackProfile(std::vector<double> time, std::vector<double> displacement)
    : time_(std::move(time)), displacement_(std::move(displacement)) {
  const double t0 = time_.front();
  for (double& t : time_) t -= t0;
}

std::size_t PlaybackProfile::segment(double t) const {
  const auto after = std::upper_bound(time_.begin(), time_.end(), t);
  const auto i = static_cast<std::size_t>(after - time_.begin());
  return std::clamp<std::size_t>(i, 1, time_.size() - 1) - 1;
}

double PlaybackProfile::displacement(double t) const {
  if (t <= 0.0) return displacement_.front();
  if (t >= duration()) return displacement_.back();
  const std::size_t i = segment(t);
  const double w = (t - time_[i]) / (time_[i + 1] - time_[i]);
  return displacement_[i] + w * (displacement_[i + 1] - displacement_[i]);
}

double PlaybackProfile::velocity(double t) const {
  if (t < 0.0 || t >= duration()) return 0.0;
  const std::size_t i = segment(t);
  return (displacement_[i + 1] - displacement_[i]) / (time_[i + 1] - time_[i]);
}

double DisplacementProfile::duration() const {
  return std::visit(
      [](const auto& p) -> double {
        if constexpr (requires { p.duration(); }) {
          return p.duration();
        } else {
          return 0.0;
        }
      },
      profile_);
}

}  // namespace mrd::sim
