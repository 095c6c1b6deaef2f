// HalSet hands the loop the demand channel the config names: the CAN back end itself with
// backends.demand = "can" or "modbus" (the same back end as the LVDT on that bus), none in
// table4 mode.
#include <gtest/gtest.h>

#include "config/config_loader.hpp"
#include "firmware/hal_set.hpp"

namespace {

using mrd::hal::can::SocketCanBackend;

TEST(HalSetDemand, TheCanDemandIsTheCanBackEndThatAlsoReadsTheLvdt) {
  const auto loaded = mrd::config::load_config_text(
      "[control]\nmode = \"force\"\n[backends]\nlvdt = \"can\"\ndemand = \"can\"\n", "can.toml");
  ASSERT_TRUE(loaded.ok()) << loaded.report();
  const mrd::hal::MonotonicClock clock;
  mrd::firmware::HalSet hal(loaded.config, clock);  // not started: no CAN on the build machine
  const auto devices = hal.devices();
  ASSERT_NE(devices.demand, nullptr);
  auto* can = dynamic_cast<SocketCanBackend*>(devices.demand);
  ASSERT_NE(can, nullptr);
  EXPECT_EQ(can, dynamic_cast<SocketCanBackend*>(&devices.lvdt));
  EXPECT_FALSE(devices.demand->latest_demand().has_value());
}

TEST(HalSetDemand, TheModbusDemandIsTheModbusBackEndThatAlsoReadsTheLvdt) {
  const auto loaded = mrd::config::load_config_text(
      "[control]\nmode = \"force\"\n[backends]\nlvdt = \"modbus\"\ndemand = \"modbus\"\n", "modbus.toml");
  ASSERT_TRUE(loaded.ok()) << loaded.report();
  const mrd::hal::MonotonicClock clock;
  mrd::firmware::HalSet hal(loaded.config, clock);  // not started: nothing to connect to
  const auto devices = hal.devices();
  ASSERT_NE(devices.demand, nullptr);
  auto* modbus = dynamic_cast<mrd::hal::modbus::ModbusBackend*>(devices.demand);
  ASSERT_NE(modbus, nullptr);
  EXPECT_EQ(modbus, dynamic_cast<mrd::hal::modbus::ModbusBackend*>(&devices.lvdt));
}

TEST(HalSetDemand, TheLoadCellIsTheBusBackEndOrTheMockTheConfigNames) {
  const mrd::hal::MonotonicClock clock;
  auto loaded = mrd::config::load_config_text(
      "[control]\nmode = \"force\"\n[backends]\nlvdt = \"can\"\ndemand = \"can\"\nload_cell = \"can\"\n", "can.toml");
  ASSERT_TRUE(loaded.ok()) << loaded.report();
  {
    mrd::firmware::HalSet hal(loaded.config, clock);  // not started
    const auto devices = hal.devices();
    ASSERT_NE(devices.load_cell, nullptr);
    EXPECT_EQ(dynamic_cast<SocketCanBackend*>(devices.load_cell), dynamic_cast<SocketCanBackend*>(&devices.lvdt));
    EXPECT_FALSE(devices.load_cell->latest_load_cell().has_value());
  }
  loaded = mrd::config::load_config_text(
      "[control]\nmode = \"force\"\n[backends]\nlvdt = \"modbus\"\ndemand = \"modbus\"\nload_cell = \"modbus\"\n",
      "modbus.toml");
  ASSERT_TRUE(loaded.ok()) << loaded.report();
  {
    mrd::firmware::HalSet hal(loaded.config, clock);
    const auto devices = hal.devices();
    ASSERT_NE(devices.load_cell, nullptr);
    EXPECT_EQ(dynamic_cast<mrd::hal::modbus::ModbusBackend*>(devices.load_cell),
              dynamic_cast<mrd::hal::modbus::ModbusBackend*>(&devices.lvdt));
  }
  loaded = mrd::config::load_config_text("[control]\nmode = \"force\"\n[backends]\nload_cell = \"mock\"\n", "mock.toml");
  ASSERT_TRUE(loaded.ok()) << loaded.report();
  {
    mrd::firmware::HalSet hal(loaded.config, clock);
    const auto devices = hal.devices();
    ASSERT_NE(devices.load_cell, nullptr);
    EXPECT_NE(dynamic_cast<mrd::hal::mock::MockLoadCellSource*>(devices.load_cell), nullptr);
  }
  // Without the key (none), force mode has no load cell.
  loaded = mrd::config::load_config_text("[control]\nmode = \"force\"\n", "none.toml");
  ASSERT_TRUE(loaded.ok()) << loaded.report();
  mrd::firmware::HalSet hal(loaded.config, clock);
  EXPECT_EQ(hal.devices().load_cell, nullptr);
}

TEST(HalSetDemand, Table4ModeHasNoDemandChannel) {
  const auto loaded = mrd::config::load_config_text("[backends]\nlvdt = \"can\"\n", "table4.toml");
  ASSERT_TRUE(loaded.ok()) << loaded.report();
  const mrd::hal::MonotonicClock clock;
  mrd::firmware::HalSet hal(loaded.config, clock);
  EXPECT_EQ(hal.devices().demand, nullptr);
}

}  // namespace

namespace {

// The CAN link's problem line asks only for the frames this config has the bus carry: the
// driver's feedback only with can.use_feedback, the LVDT only when it is on CAN.
TEST(HalSetLinks, TheCanLinkLooksOnlyForTheFramesTheConfigExpects) {
  const mrd::hal::MonotonicClock clock;
  const auto problems = [&](const char* text) {
    const auto loaded = mrd::config::load_config_text(text, "links.toml");
    EXPECT_TRUE(loaded.ok()) << loaded.report();
    return mrd::firmware::HalSet(loaded.config, clock).link_problems();  // not started: no frame yet
  };
  EXPECT_EQ(problems("[backends]\nlvdt = \"mock\"\ndriver = \"can\"\nlines = \"mock\"\n"),
            std::vector<std::string>{"can: can0: no current feedback frame (id 0x211) received"});
  EXPECT_TRUE(problems("[backends]\nlvdt = \"mock\"\ndriver = \"can\"\nlines = \"mock\"\n[can]\nuse_feedback = false\n").empty());
  EXPECT_EQ(problems("[backends]\nlvdt = \"can\"\ndriver = \"mock\"\nlines = \"mock\"\n"),
            std::vector<std::string>{"can: can0: no LVDT frame (id 0x110) received"});
}

}  // namespace
