// Levenberg-Marquardt over a space's coordinates (the base fit's chains and polish): it finds a
// known parameter from far off in few observer passes, holds a coordinate whose optimum lies past
// its bound on the bound while the others still converge, and never ends worse than it started.
#include "tools/residual/least_squares_refine.hpp"

#include <gtest/gtest.h>

#include "tests/tools/residual/residual_test_support.hpp"
#include "tools/residual/candidate_effects.hpp"

namespace {

using namespace mrd::tools;

FitSeries coil_lag_series() {
  // tau 20 ms on the 50 kN class; the load cell's noise is 25 N.
  return make_fit_series(
      {residual_testing::simulated_recorded_run(RunProfile::kTable4, "50kN", {{"coil_lag", 1.0}}, 4.0)}, {});
}

ParameterSpace coil_lag_space(const FitSeries& s) {
  return effect_space(*mrd::model::find_effect("coil_lag"), mrd::model::DamperModel{}, series_scales(s));
}

TEST(LeastSquaresRefine, FindsTheCoilTimeConstantFromTheFarEndOfItsRange) {
  const FitSeries s = coil_lag_series();
  const ParameterSpace space = coil_lag_space(s);
  ASSERT_EQ(space.bounds.dimension(), 1);
  const Point start = space.bounds.upper;  // the longest time constant the range allows
  const FittedModel fit = refine_least_squares(space, s, start, 60);
  EXPECT_NEAR(fit.model.effects.get<mrd::model::CoilLagEffect>().time_constant, 0.020, 0.001);
  EXPECT_LT(fit.fitting_rms, 40.0);
  EXPECT_LE(fit.evaluations, 61);
  WorkerPool pool(2);  // the Jacobian's columns on a pool: the same answer
  const FittedModel pooled = refine_least_squares(space, s, start, 60, &pool);
  EXPECT_EQ(pooled.theta, fit.theta);
}

// The coil lag with a sensor delay the run does not have: the delay's optimum (none) lies below
// its range, so it ends on its lower bound, and the time constant is found all the same.
TEST(LeastSquaresRefine, ACoordinatePushedPastItsBoundStaysThereWhileTheOthersConverge) {
  const FitSeries s = coil_lag_series();
  const SeriesScales scales = series_scales(s);
  const ParameterSpace space =
      combine(coil_lag_space(s), effect_space(*mrd::model::find_effect("sensor_delay"), mrd::model::DamperModel{}, scales));
  ASSERT_EQ(space.bounds.dimension(), 2);
  const Point start = 0.5 * (space.bounds.lower + space.bounds.upper);
  const FittedModel fit = refine_least_squares(space, s, start, 120);
  EXPECT_EQ(fit.theta[1], space.bounds.lower[1]);
  EXPECT_NEAR(fit.model.effects.get<mrd::model::CoilLagEffect>().time_constant, 0.020, 0.001);
  // The least delay still costs (0.1 ms on a 50 kN damper); Nelder-Mead from there finds no
  // better point.
  const FittedModel simplex = refine_space(space, s, fit.theta, 60, 0.02);
  EXPECT_GT(simplex.fitting_rms, 0.995 * fit.fitting_rms);
}

// A budget too small for a step: the start comes back, as fitted there.
TEST(LeastSquaresRefine, WithoutTheBudgetForAStepTheStartComesBack) {
  const FitSeries s = coil_lag_series();
  const ParameterSpace space = coil_lag_space(s);
  const Point start = space.bounds.upper;
  const FittedModel fit = refine_least_squares(space, s, start, 1);
  EXPECT_EQ(fit.theta, start);
  std::vector<double> buffer;
  EXPECT_DOUBLE_EQ(fit.fitting_rms, space_fitness(space, s, start, buffer));
}

}  // namespace
