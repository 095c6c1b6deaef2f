// mrd-plant as force mode's outer controller: plant.demand_damping is refused unless the
// controller reads a demand from a bus, and the plant's Modbus server serves the demand in the
// controller's register format, read back by the controller's own back end.
#include <gtest/gtest.h>

#include <optional>

#include "hal/modbus/modbus_backend.hpp"
#include "sim/plant/modbus_server.hpp"
#include "sim/plant/plant_config.hpp"
#include "tests/hal/test_wait.hpp"

namespace {

using mrd::plant::load_plant_config_text;

TEST(PlantDemand, DemandDampingNeedsAControllerThatReadsItsDemandFromABus) {
  auto c = load_plant_config_text("[plant]\ndemand_damping = 250e3\ncontroller_config = \"\"\n", "plant.toml");
  EXPECT_FALSE(c.ok());
  EXPECT_NE(c.report().find("plant.toml:2: plant.demand_damping: the controller config reads no demand from a bus"),
            std::string::npos)
      << c.report();
  c = load_plant_config_text("[plant]\ndemand_damping = -1.0\ncontroller_config = \"\"\n", "neg.toml");
  EXPECT_NE(c.report().find("neg.toml:2: plant.demand_damping: must be a finite value >= 0 N s/m"), std::string::npos)
      << c.report();
  c = load_plant_config_text("[plant]\ncontroller_config = \"\"\n", "off.toml");
  EXPECT_TRUE(c.ok()) << c.report();
  EXPECT_FALSE(c.config.sends_demand());
}

TEST(PlantDemand, TheModbusServerServesTheDemandTheControllersBackEndReads) {
  mrd::hal::modbus::ModbusConfig layout;
  layout.registers.has_demand = true;
  layout.registers.demand_address = 6;
  mrd::plant::ModbusServer server(layout, "127.0.0.1", 0, "", 1);
  const auto started = server.start();
  ASSERT_TRUE(started.ok) << started.error;
  server.publish(0.001, 0.0, -1234.5, mrd::plant::ActiveFaults{});

  layout.tcp.port = server.port();
  const mrd::hal::MonotonicClock clock;
  mrd::hal::modbus::ModbusBackend backend(layout, clock);
  ASSERT_TRUE(backend.start().ok);
  std::optional<mrd::hal::DemandSample> d;
  ASSERT_TRUE(mrd::test::wait_for([&] { return (d = backend.latest_demand()).has_value(); }));
  EXPECT_TRUE(d->usable());
  EXPECT_DOUBLE_EQ(d->value, -1234.5);
  backend.stop();
  server.stop();
}

}  // namespace
