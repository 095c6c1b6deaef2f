#include "sim/displacement_profile.hpp"

#include <cmath>
#include <numbers>

namespace mrd::sim {

double SineProfile::displacement(double t) const {
  return amplitude * std::sin(2.0 * std::numbers::pi * frequency * t);
}

double SineProfile::velocity(double t) const {
  const double w = 2.0 * std::numbers::pi * frequency;
  return amplitude * w * std::cos(w * t);
}

}  // namespace mrd::sim
