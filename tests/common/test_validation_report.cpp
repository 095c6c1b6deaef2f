#include "common/validation_report.hpp"

#include <gtest/gtest.h>

namespace {

TEST(ValidationReport, CollectsProblemsWithNestedFieldPaths) {
  mrd::ValidationReport inner;
  EXPECT_TRUE(inner.check(true, "port", "unused"));
  EXPECT_FALSE(inner.check(false, "port", "must be in 1..65535"));
  mrd::ValidationReport outer;
  EXPECT_TRUE(outer.ok());
  outer.merge(inner, "modbus.tcp");
  EXPECT_FALSE(outer.ok());
  EXPECT_TRUE(outer.mentions("modbus.tcp.port"));
  EXPECT_EQ(outer.to_string(), "error: modbus.tcp.port: must be in 1..65535\n");
}

TEST(ValidationReport, WarningsLeaveItOk) {
  mrd::ValidationReport r;
  r.warning("modbus.poll_period", "longer than the period");
  EXPECT_TRUE(r.ok());
  EXPECT_EQ(r.to_string(), "warning: modbus.poll_period: longer than the period\n");
  r.require_positive("gap", 0.0);
  EXPECT_FALSE(r.ok());
}

}  // namespace
