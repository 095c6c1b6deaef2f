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

TEST(ForceModeConfig, TheDemandOverCanTurnsOnItsFrameWithAnIdThatMustNotClash) {
  LoadedConfig c = load_config_text(
      "[control]\nmode = \"force\"\n[backends]\nlvdt = \"can\"\ndemand = \"can\"\n[can]\ndemand_id = 0x121\n",
      "can.toml");
  ASSERT_TRUE(c.ok()) << c.report();
  EXPECT_EQ(c.config.backends.demand, DeviceBackend::kCan);
  EXPECT_TRUE(c.config.can.use_demand);
  EXPECT_EQ(c.config.can.demand_id, 0x121u);

  c = load_config_text("[control]\nmode = \"force\"\n[backends]\nlvdt = \"can\"\ndemand = \"can\"\n[can]\n"
                       "demand_id = 0x110\n",
                       "clash.toml");
  EXPECT_TRUE(mrd::test::has_error(c, "clash.toml:7: can.demand_id: must differ from lvdt_id, command_id and "
                                      "feedback_id"))
      << c.report();
  // In table4 mode the demand is not received, so its id is not checked either.
  c = load_config_text("[backends]\nlvdt = \"can\"\n[can]\ndemand_id = 0x110\n", "table4.toml");
  EXPECT_TRUE(c.ok()) << c.report();
  EXPECT_FALSE(c.config.can.use_demand);
}

TEST(ForceModeConfig, TheDemandOverModbusReadsItsRegisterWhichMustNotOverlapTheOthers) {
  const std::string head = "[control]\nmode = \"force\"\n[backends]\nlvdt = \"modbus\"\ndemand = \"modbus\"\n"
                           "[modbus.registers]\n";
  LoadedConfig c = load_config_text(head + "demand_address = 7\ndemand_kind = \"input\"\n[modbus.registers.demand]\n"
                                           "type = \"float32\"\nscale = 1.0\n",
                                    "modbus.toml");
  ASSERT_TRUE(c.ok()) << c.report();
  const auto& r = c.config.modbus.registers;
  EXPECT_TRUE(r.has_demand);
  EXPECT_EQ(r.demand_address, 7);
  EXPECT_EQ(r.demand_kind, mrd::hal::modbus::RegisterKind::kInput);
  EXPECT_EQ(r.demand.type, mrd::hal::modbus::RegisterType::kFloat32);
  EXPECT_EQ(r.demand.scale, 1.0);

  c = load_config_text(head + "demand_address = 1\ndemand_kind = \"input\"\n", "lvdt.toml");
  EXPECT_TRUE(mrd::test::has_error(c, "lvdt.toml:7: modbus.registers.demand_address: overlaps the LVDT's registers"))
      << c.report();
  c = load_config_text(head + "demand_address = 0\n", "setpoint.toml");
  EXPECT_TRUE(mrd::test::has_error(c, "setpoint.toml:7: modbus.registers.demand_address: overlaps the setpoint's "
                                      "holding registers"))
      << c.report();
  c = load_config_text(head + "has_current_feedback = true\ncurrent_feedback_address = 5\ndemand_kind = \"input\"\n"
                              "demand_address = 4\n",
                       "feedback.toml");
  EXPECT_TRUE(mrd::test::has_error(c, "feedback.toml:10: modbus.registers.demand_address: overlaps the current "
                                      "feedback's registers"))
      << c.report();
  // In table4 mode the register is not read, so it may sit anywhere.
  c = load_config_text("[backends]\nlvdt = \"modbus\"\n[modbus.registers]\ndemand_address = 0\n", "table4.toml");
  EXPECT_TRUE(c.ok()) << c.report();
  EXPECT_FALSE(c.config.modbus.registers.has_demand);
}

// The optional counter word beside the demand: read in force mode, -1 (none) by default, in
// range, and clear of the other values' registers, the demand's own included.
TEST(ForceModeConfig, TheDemandCounterRegisterIsOptionalInRangeAndOverlapsNothing) {
  const std::string head = "[control]\nmode = \"force\"\n[backends]\nlvdt = \"modbus\"\ndemand = \"modbus\"\n"
                           "[modbus.registers]\n";
  LoadedConfig c = load_config_text(head, "none.toml");
  ASSERT_TRUE(c.ok()) << c.report();
  EXPECT_EQ(c.config.modbus.registers.demand_counter_address, -1);
  EXPECT_FALSE(c.config.modbus.registers.has_demand_counter());

  c = load_config_text(head + "demand_counter_address = 4\n", "counter.toml");
  ASSERT_TRUE(c.ok()) << c.report();
  EXPECT_EQ(c.config.modbus.registers.demand_counter_address, 4);
  EXPECT_TRUE(c.config.modbus.registers.has_demand_counter());

  c = load_config_text(head + "demand_counter_address = 65536\n", "range.toml");
  EXPECT_TRUE(mrd::test::has_error(c, "range.toml:7: modbus.registers.demand_counter_address: must be -1 (none) "
                                      "or in 0..65535"))
      << c.report();
  c = load_config_text(head + "demand_counter_address = -2\n", "negative.toml");
  EXPECT_TRUE(mrd::test::has_error(c, "negative.toml:7: modbus.registers.demand_counter_address: must be -1 "
                                      "(none) or in 0..65535"))
      << c.report();
  // The demand's second word (holding 2-3 by default).
  c = load_config_text(head + "demand_counter_address = 3\n", "demand.toml");
  EXPECT_TRUE(mrd::test::has_error(c, "demand.toml:7: modbus.registers.demand_counter_address: overlaps the "
                                      "demand's registers"))
      << c.report();
  c = load_config_text(head + "demand_counter_address = 0\n", "setpoint.toml");
  EXPECT_TRUE(mrd::test::has_error(c, "setpoint.toml:7: modbus.registers.demand_counter_address: overlaps the "
                                      "setpoint's holding registers"))
      << c.report();
  // Same kind as the demand: an input-register counter at the LVDT's address collides with it.
  c = load_config_text(head + "demand_kind = \"input\"\ndemand_address = 8\ndemand_counter_address = 1\n",
                       "lvdt.toml");
  EXPECT_TRUE(mrd::test::has_error(c, "lvdt.toml:9: modbus.registers.demand_counter_address: overlaps the LVDT's "
                                      "registers"))
      << c.report();
  // In table4 mode nothing of the demand is read.
  c = load_config_text("[backends]\nlvdt = \"modbus\"\n[modbus.registers]\ndemand_counter_address = 0\n", "t4.toml");
  EXPECT_TRUE(c.ok()) << c.report();
  EXPECT_FALSE(c.config.modbus.registers.has_demand_counter());
}

}  // namespace
