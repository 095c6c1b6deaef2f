#pragma once

#include <cstdint>

#include "tools/optimisation/worker_pool.hpp"
#include "tools/residual/model_fit.hpp"

namespace mrd::tools {

// Levenberg-Marquardt on the fitting samples' residuals from `start` inside the space's bounds
// (trial points clamped), the linear terms solved at every point (a variable projection). The
// Jacobian is a forward difference of kJacobianStep of each coordinate's range, stepped toward
// the interior: J-A's sub-step grid moves B by about 1e-5 T as k or the field gain change, and a
// step much shorter would read that grid instead of the slope. Its columns are evaluated on
// `pool` when given (each is one observer pass), serially otherwise. Stops after
// `max_evaluations` observer passes, when a step lowers the sum of squares by less than
// kLeastSquaresTolerance of it, or when no damping finds a lower one.
// Not Eigen's LevenbergMarquardt, which mrd-identify's polish uses (tools/identification/polish):
// here a coordinate at its bound leaves the step (the base often rests on a range's edge, where
// clamping alone stalls the damped step), a point the model refuses is a rejected step rather
// than a residual, and the Jacobian's columns, an observer pass each, run side by side.
inline constexpr double kJacobianStep = 1e-3;
inline constexpr double kLeastSquaresTolerance = 1e-6;
FittedModel refine_least_squares(const ParameterSpace& space, const FitSeries& series, const Point& start,
                                 int max_evaluations, WorkerPool* pool = nullptr);

}  // namespace mrd::tools
