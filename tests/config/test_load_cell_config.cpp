// backends.load_cell and [force.load_cell]: none by default (the law runs open-loop on the
// model); in force mode a load cell opens its channel (the CAN frame, the Modbus registers) and
// the law's correction; bad values name file, line and key.
#include <gtest/gtest.h>

#include <string>

#include "config/config_loader.hpp"
#include "tests/config/config_errors.hpp"

namespace {

using mrd::config::DeviceBackend;
using mrd::config::LoadedConfig;
using mrd::config::load_config_text;

TEST(LoadCellConfig, TheDefaultIsNoLoadCellEvenInForceMode) {
  LoadedConfig c = mrd::config::load_default_config();
  ASSERT_TRUE(c.ok()) << c.report();
  EXPECT_FALSE(c.config.backends.load_cell.has_value());
  EXPECT_FALSE(c.config.law.has_load_cell);
  c = load_config_text("[control]\nmode = \"force\"\n", "force.toml");
  ASSERT_TRUE(c.ok()) << c.report();
  EXPECT_FALSE(c.config.backends.load_cell.has_value());
  EXPECT_FALSE(c.config.law.has_load_cell);
  EXPECT_FALSE(c.config.can.use_load_cell);
  EXPECT_FALSE(c.config.modbus.registers.has_load_cell);
}

TEST(LoadCellConfig, AMockLoadCellTurnsOnTheCorrectionWithItsSettings) {
  const LoadedConfig c = load_config_text(R"(
[control]
mode = "force"
[backends]
load_cell = "mock"
[force.load_cell]
time_constant = 8.0
max_correction = 0.2
min_force_fraction = 0.15
min_speed = 0.02
max_age = 9
)", "lc.toml");
  ASSERT_TRUE(c.ok()) << c.report();
  EXPECT_EQ(c.config.backends.load_cell, DeviceBackend::kMock);
  EXPECT_TRUE(c.config.law.has_load_cell);
  const auto& s = c.config.law.load_cell;
  EXPECT_EQ(s.time_constant, 8.0);
  EXPECT_EQ(s.max_correction, 0.2);
  EXPECT_EQ(s.min_force_fraction, 0.15);
  EXPECT_EQ(s.min_speed, 0.02);
  EXPECT_EQ(s.max_age_periods, 9);
}

TEST(LoadCellConfig, InTable4ModeNoLoadCellIsOpened) {
  const LoadedConfig c = load_config_text("[backends]\nload_cell = \"can\"\nlvdt = \"can\"\n[can]\nload_cell_id = 0x110\n",
                                          "table4.toml");
  ASSERT_TRUE(c.ok()) << c.report();
  EXPECT_FALSE(c.config.backends.load_cell.has_value());
  EXPECT_FALSE(c.config.can.use_load_cell);
}

// A bad value is an error even where no load cell reads it (table4 mode): the file is wrong.
TEST(LoadCellConfig, BadSettingsAreRefusedEvenWithoutALoadCell) {
  const LoadedConfig c = load_config_text("[force.load_cell]\ntime_constant = -1.0\n", "unused.toml");
  EXPECT_FALSE(c.ok());
  EXPECT_NE(c.report().find("unused.toml:2: force.load_cell.time_constant"), std::string::npos) << c.report();
}

TEST(LoadCellConfig, BadLoadCellSettingsNameFileLineAndKey) {
  const LoadedConfig c = load_config_text(R"(
[control]
mode = "force"
[backends]
load_cell = "strain"
)", "bad.toml");
  EXPECT_TRUE(mrd::test::has_error(c, "bad.toml:5: backends.load_cell: must be one of none, mock, modbus, can, got "
                                      "\"strain\""))
      << c.report();
  const LoadedConfig d = load_config_text(R"(
[control]
mode = "force"
[backends]
load_cell = "mock"
[force.load_cell]
time_constant = 0.0
max_correction = 0.95
min_force_fraction = -0.1
min_speed = "fast"
max_age = 0
)", "bad.toml");
  const std::string report = d.report();
  EXPECT_NE(report.find("bad.toml:7: force.load_cell.time_constant: must be a finite value > 0"), std::string::npos)
      << report;
  EXPECT_NE(report.find("bad.toml:8: force.load_cell.max_correction: must be in (0, 0.9]"), std::string::npos)
      << report;
  EXPECT_NE(report.find("bad.toml:9: force.load_cell.min_force_fraction: must lie in [0, 1)"), std::string::npos)
      << report;
  EXPECT_NE(report.find("bad.toml:10: force.load_cell.min_speed:"), std::string::npos) << report;
  EXPECT_NE(report.find("bad.toml:11: force.load_cell.max_age: must be >= 1"), std::string::npos) << report;
}

TEST(LoadCellConfig, AMockLoadCellNeedsTheMockRig) {
  const LoadedConfig c = load_config_text(R"(
[control]
mode = "force"
[backends]
lvdt = "modbus"
demand = "modbus"
load_cell = "mock"
)", "mixed.toml");
  EXPECT_TRUE(mrd::test::has_error(c, "mixed.toml:7: backends.load_cell: \"mock\" measures the simulated rig's force: "
                                      "it needs backends.lvdt = \"mock\""))
      << c.report();
}

TEST(LoadCellConfig, TheLoadCellOverCanTurnsOnItsFrameWithAnIdThatMustNotClash) {
  const std::string head = "[control]\nmode = \"force\"\n[backends]\nlvdt = \"can\"\ndemand = \"can\"\n"
                           "load_cell = \"can\"\n[can]\n";
  LoadedConfig c = load_config_text(head + "load_cell_id = 0x131\n", "can.toml");
  ASSERT_TRUE(c.ok()) << c.report();
  EXPECT_EQ(c.config.backends.load_cell, DeviceBackend::kCan);
  EXPECT_TRUE(c.config.can.use_load_cell);
  EXPECT_EQ(c.config.can.load_cell_id, 0x131u);
  EXPECT_TRUE(c.config.law.has_load_cell);

  c = load_config_text(head + "load_cell_id = 0x120\n", "clash.toml");
  EXPECT_TRUE(mrd::test::has_error(c, "clash.toml:8: can.load_cell_id: must differ from lvdt_id, command_id, "
                                      "feedback_id and demand_id"))
      << c.report();
}

TEST(LoadCellConfig, TheLoadCellOverModbusReadsItsRegistersWhichMustNotOverlapTheOthers) {
  const std::string head = "[control]\nmode = \"force\"\n[backends]\nlvdt = \"modbus\"\ndemand = \"modbus\"\n"
                           "load_cell = \"modbus\"\n[modbus.registers]\n";
  LoadedConfig c = load_config_text(head + "load_cell_address = 20\nload_cell_kind = \"holding\"\n"
                                           "[modbus.registers.load_cell]\ntype = \"float32\"\nscale = 1.0\n",
                                    "modbus.toml");
  ASSERT_TRUE(c.ok()) << c.report();
  const auto& r = c.config.modbus.registers;
  EXPECT_TRUE(r.has_load_cell);
  EXPECT_EQ(r.load_cell_address, 20);
  EXPECT_EQ(r.load_cell_kind, mrd::hal::modbus::RegisterKind::kHolding);
  EXPECT_EQ(r.load_cell.type, mrd::hal::modbus::RegisterType::kFloat32);

  // The defaults (input 4-5) sit clear of the LVDT (input 0-1), the feedback (input 2) and the
  // demand (holding 2-3).
  c = load_config_text(head + "has_current_feedback = true\n", "defaults.toml");
  EXPECT_TRUE(c.ok()) << c.report();
  c = load_config_text(head + "load_cell_address = 1\n", "lvdt.toml");
  EXPECT_TRUE(mrd::test::has_error(c, "lvdt.toml:8: modbus.registers.load_cell_address: overlaps the LVDT's registers"))
      << c.report();
  c = load_config_text(head + "load_cell_address = 3\nload_cell_kind = \"holding\"\n", "demand.toml");
  EXPECT_TRUE(mrd::test::has_error(c, "demand.toml:8: modbus.registers.load_cell_address: overlaps the demand's "
                                      "registers"))
      << c.report();
}

}  // namespace
