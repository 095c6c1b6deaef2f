#include "model/target_curve.hpp"

#include <algorithm>
#include <cmath>

#include "model/physical_constants.hpp"

namespace mrd::model {

TargetCurve::TargetCurve(const JilesAtherton& prototype, double max_current, Kind kind)
    : max_current_(max_current), step_(max_current / static_cast<double>(kPoints - 1)), kind_(kind) {
  JilesAtherton core = prototype;
  core.demagnetise();
  for (std::size_t i = 0; i < kPoints; ++i) {
    const double H = core.circuit().field_from_current(step_ * static_cast<double>(i));
    B_[i] = kind == Kind::kAnhysteretic ? kMu0 * (H + core.anhysteretic_magnetisation(H))
                                        : core.apply_field(H);
  }
}

double TargetCurve::B(double current) const {
  const double magnitude = std::min(std::fabs(current), max_current_);
  const double position = magnitude / step_;
  const auto i = std::min(static_cast<std::size_t>(position), kPoints - 2);
  const double fraction = position - static_cast<double>(i);
  const double b = B_[i] + fraction * (B_[i + 1] - B_[i]);
  return current < 0.0 ? -b : b;
}

}  // namespace mrd::model
