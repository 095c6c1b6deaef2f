// control.mode and the [force] table: the default is table4 with no demand channel; force mode
// opens one and maps its limits into the supervisor; bad values name file, line and key.
#include <gtest/gtest.h>

#include "config/config_loader.hpp"
#include "tests/config/config_errors.hpp"

namespace {

using mrd::config::DeviceBackend;
using mrd::config::LoadedConfig;
using mrd::config::load_config_text;
using mrd::control::ControlMode;

TEST(ForceModeConfig, TheDefaultIsTable4WithNoDemandChannel) {
  const LoadedConfig c = mrd::config::load_default_config();
  ASSERT_TRUE(c.ok()) << c.report();
  EXPECT_EQ(c.config.law.mode, ControlMode::kTable4);
  EXPECT_FALSE(c.config.backends.demand.has_value());
  EXPECT_FALSE(c.config.backends.uses(DeviceBackend::kCan));
}

TEST(ForceModeConfig, ForceModeOpensTheDemandAndMapsItsLimitsIntoTheSupervisor) {
  const LoadedConfig c = load_config_text(R"(
[control]
mode = "force"
[backends]
demand = "mock"
[force]
demand_range = 45000.0
demand_max_age = 7
invert_coil_lag = false
)", "force.toml");
  ASSERT_TRUE(c.ok()) << c.report();
  EXPECT_EQ(c.config.law.mode, ControlMode::kForce);
  EXPECT_EQ(c.config.backends.demand, DeviceBackend::kMock);
  EXPECT_EQ(c.config.safety.demand_range, 45000.0);
  EXPECT_EQ(c.config.safety.demand_stale_periods, 7);
  EXPECT_FALSE(c.config.law.force.invert_coil_lag);
}

TEST(ForceModeConfig, BadForceSettingsNameFileLineAndKey) {
  const LoadedConfig c = load_config_text(R"(
[control]
mode = "forse"
[force]
demand_range = -1.0
demand_max_age = 0
invert_coil_lag = 1
)", "bad.toml");
  EXPECT_TRUE(mrd::test::has_error(c, "bad.toml:3: control.mode: must be one of table4, force, got \"forse\""))
      << c.report();
  EXPECT_TRUE(mrd::test::has_error(c, "bad.toml:5: force.demand_range: must be a finite value > 0 N")) << c.report();
  EXPECT_TRUE(mrd::test::has_error(c, "bad.toml:6: force.demand_max_age: must be >= 1, got 0")) << c.report();
  EXPECT_TRUE(mrd::test::has_error(c, "bad.toml:7: force.invert_coil_lag: must be true or false, got an integer"))
      << c.report();
}

TEST(ForceModeConfig, AMockDemandNeedsTheMockLvdtItsVelocityComesFrom) {
  const LoadedConfig c = load_config_text(R"(
[control]
mode = "force"
[backends]
lvdt = "modbus"
demand = "mock"
)", "mixed.toml");
  EXPECT_TRUE(mrd::test::has_error(c, "mixed.toml:6: backends.demand: \"mock\" asks for simulation.demand_damping "
                                      "times the mock LVDT's velocity: it needs backends.lvdt = \"mock\""))
      << c.report();
}

}  // namespace

namespace {

TEST(ForceModeConfig, TheDemandOverABusIsRefusedUntilItIsImplemented) {
  const LoadedConfig c = load_config_text("[control]\nmode = \"force\"\n[backends]\ndemand = \"can\"\n", "can.toml");
  EXPECT_TRUE(mrd::test::has_error(c, "can.toml:4: backends.demand: the demand over Modbus or CAN is not implemented "
                                      "yet: use \"mock\""))
      << c.report();
}

}  // namespace
