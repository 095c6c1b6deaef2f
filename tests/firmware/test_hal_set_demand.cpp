// HalSet hands the loop each sample channel from the back end the config names: the demand
// from the CAN or Modbus back end that also reads the LVDT, none in table4 mode; the load cell
// from a bus back end or the mock.
#include <gtest/gtest.h>

#include "config/config_loader.hpp"
#include "firmware/hal_set.hpp"

namespace {

TEST(HalSetDemand, TheCanDemandIsTheCanBackEndThatAlsoReadsTheLvdt) {
  const auto loaded = mrd::config::load_config_text(
      "[control]\nmode = \"force\"\n[backends]\nlvdt = \"can\"\ndemand = \"can\"\n", "can.toml");
  ASSERT_TRUE(loaded.ok()) << loaded.report();
  const mrd::hal::MonotonicClock clock;
  mrd::firmware::HalSet hal(loaded.config, clock);  // not started: no CAN on the build machine
  const auto devices = hal.devices();
  ASSERT_NE(hal.can(), nullptr);
  EXPECT_EQ(devices.demand, &hal.can()->demand());
  EXPECT_EQ(&devices.lvdt, &hal.can()->lvdt());
  EXPECT_FALSE(devices.demand->latest().has_value());
}

TEST(HalSetDemand, TheModbusDemandIsTheModbusBackEndThatAlsoReadsTheLvdt) {
  const auto loaded = mrd::config::load_config_text(
      "[control]\nmode = \"force\"\n[backends]\nlvdt = \"modbus\"\ndemand = \"modbus\"\n", "modbus.toml");
  ASSERT_TRUE(loaded.ok()) << loaded.report();
  const mrd::hal::MonotonicClock clock;
  mrd::firmware::HalSet hal(loaded.config, clock);  // not started: nothing to connect to
  const auto devices = hal.devices();
  ASSERT_NE(hal.modbus(), nullptr);
  EXPECT_EQ(devices.demand, &hal.modbus()->demand());
  EXPECT_EQ(&devices.lvdt, &hal.modbus()->lvdt());
}

TEST(HalSetDemand, TheLoadCellIsTheBusBackEndOrTheMockTheConfigNames) {
  const mrd::hal::MonotonicClock clock;
  auto loaded = mrd::config::load_config_text(
      "[control]\nmode = \"force\"\n[backends]\nlvdt = \"can\"\ndemand = \"can\"\nload_cell = \"can\"\n", "can.toml");
  ASSERT_TRUE(loaded.ok()) << loaded.report();
  {
    mrd::firmware::HalSet hal(loaded.config, clock);  // not started
    const auto devices = hal.devices();
    ASSERT_NE(hal.can(), nullptr);
    EXPECT_EQ(devices.load_cell, &hal.can()->load_cell());
    EXPECT_FALSE(devices.load_cell->latest().has_value());
  }
  loaded = mrd::config::load_config_text(
      "[control]\nmode = \"force\"\n[backends]\nlvdt = \"modbus\"\ndemand = \"modbus\"\nload_cell = \"modbus\"\n",
      "modbus.toml");
  ASSERT_TRUE(loaded.ok()) << loaded.report();
  {
    mrd::firmware::HalSet hal(loaded.config, clock);
    ASSERT_NE(hal.modbus(), nullptr);
    EXPECT_EQ(hal.devices().load_cell, &hal.modbus()->load_cell());
  }
  loaded = mrd::config::load_config_text("[control]\nmode = \"force\"\n[backends]\nload_cell = \"mock\"\n", "mock.toml");
  ASSERT_TRUE(loaded.ok()) << loaded.report();
  {
    mrd::firmware::HalSet hal(loaded.config, clock);
    ASSERT_NE(hal.mock(), nullptr);
    EXPECT_EQ(hal.devices().load_cell, &hal.mock()->load_cell);
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
