// GasSpring: the accumulator's force F0 + k x.
#include "model/effects/gas_spring.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace {

using mrd::model::GasSpring;
using mrd::model::GasSpringParams;

TEST(GasSpring, OffsetAtZeroAndSlopeIsTheStiffness) {
  const GasSpring spring({true, 71.5, 500.0});  // Spencer's k1 (x - x0) for Dyke's damper
  EXPECT_DOUBLE_EQ(spring.force(0.0), 71.5);
  EXPECT_DOUBLE_EQ(spring.force(0.02) - spring.force(-0.02), 500.0 * 0.04);
}

TEST(GasSpring, ValidateRejectsNonFiniteValues) {
  EXPECT_TRUE(validate(GasSpringParams{true, -100.0, -10.0}).ok());  // signs follow the rig
  const auto report = validate(GasSpringParams{true, std::numeric_limits<double>::infinity(), 1.0});
  ASSERT_FALSE(report.ok());
  EXPECT_EQ(report.issues().front().field, "preload");
}

}  // namespace
