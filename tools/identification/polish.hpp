#pragma once

#include <cstdint>

#include "tools/identification/bh_objective.hpp"

namespace mrd::tools {

struct PolishResult {
  Point best;
  double rmse = 0.0;            // Eq. 15 after the polish [T]
  std::int64_t evaluations = 0;  // model simulations the polish spent, Jacobians included
  int status = 0;                // Eigen's LevenbergMarquardt status
};

// Levenberg-Marquardt (Eigen unsupported, forward-difference Jacobian) from `start`, on the
// residuals B_sim - B_meas, in coordinates scaled by the start so the five parameters have
// comparable steps. It stays inside `bounds` by clamping every trial point.
PolishResult polish_levenberg_marquardt(const BHObjective& objective, const Point& start,
                                        const Bounds& bounds, int max_evaluations = 3000);

}  // namespace mrd::tools
