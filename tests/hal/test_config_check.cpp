#include "hal/config_check.hpp"

#include <gtest/gtest.h>

namespace {

TEST(ConfigReport, CollectsProblemsWithNestedFieldPaths) {
  mrd::hal::ConfigReport inner;
  EXPECT_TRUE(inner.check(true, "port", "unused"));
  EXPECT_FALSE(inner.check(false, "port", "must be in 1..65535"));
  mrd::hal::ConfigReport outer;
  EXPECT_TRUE(outer.ok());
  outer.merge(inner, "modbus.tcp");
  EXPECT_FALSE(outer.ok());
  EXPECT_TRUE(outer.mentions("modbus.tcp.port"));
  EXPECT_EQ(outer.to_string(), "modbus.tcp.port: must be in 1..65535\n");
}

}  // namespace
