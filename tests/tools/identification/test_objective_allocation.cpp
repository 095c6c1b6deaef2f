#include <gtest/gtest.h>

#include <cmath>

#include "tests/support/allocation_counter.hpp"
#include "tools/identification/bh_objective.hpp"
#include "tools/identification/synthetic_curve.hpp"

namespace {

// The J-A simulation inside the identification objective runs thousands of times per fit,
// on every core: it must not touch the heap.
TEST(IdentificationObjective, EvaluationDoesNotAllocate) {
  const mrd::model::JilesAthertonParams steel{1.6e6, 1100.0, 1.6e-3, 400.0, 0.2};
  const auto curve = mrd::tools::synthetic_loop(steel, 5000.0, 500);
  const mrd::tools::BHObjective objective(curve);
  std::vector<double> scratch(objective.points());
  std::vector<mrd::tools::Point> points;
  for (int i = 0; i < 50; ++i) points.push_back(mrd::tools::to_point(steel) * (0.6 + 0.02 * i));
  double sink = 0.0;
  mrd::test::start_counting_allocations();
  for (const auto& x : points) sink += objective.evaluate(x, scratch).fitness;
  for (const auto& x : points) sink += objective.evaluate(x, scratch, 1e-3).fitness;
  EXPECT_EQ(mrd::test::stop_counting_allocations(), 0u);
  EXPECT_TRUE(std::isfinite(sink));
}

}  // namespace
