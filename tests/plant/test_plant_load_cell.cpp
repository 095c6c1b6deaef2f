// mrd-plant's load cell for force mode's feedback: the plant's Modbus server serves the rig's
// measured force in the controller's load-cell register format, read back by the controller's
// own back end; nothing is served where the controller reads no load cell.
#include <gtest/gtest.h>

#include <optional>

#include "hal/modbus/modbus_backend.hpp"
#include "sim/plant/modbus_server.hpp"
#include "tests/hal/test_wait.hpp"

namespace {

TEST(PlantLoadCell, TheModbusServerServesTheMeasuredForceTheControllersBackEndReads) {
  mrd::hal::modbus::ModbusConfig layout;
  layout.registers.has_load_cell = true;
  layout.registers.load_cell_address = 30;  // past the server's other registers: the map must grow
  layout.registers.load_cell_kind = mrd::hal::modbus::RegisterKind::kInput;
  mrd::plant::ModbusServer server(layout, "127.0.0.1", 0, "", 1);
  const auto started = server.start();
  ASSERT_TRUE(started.ok) << started.error;
  server.publish({.lvdt = 0.001, .coil_current = 0.0, .demand = 0.0}, mrd::plant::ActiveFaults{});
  server.publish_load_cell(-27182.8);

  layout.tcp.port = server.port();
  const mrd::hal::MonotonicClock clock;
  mrd::hal::modbus::ModbusBackend backend(layout, clock);
  ASSERT_TRUE(backend.start().ok);
  std::optional<mrd::hal::Sample> f;
  ASSERT_TRUE(mrd::test::wait_for([&] { return (f = backend.load_cell().latest()).has_value(); }));
  EXPECT_TRUE(f->usable());
  EXPECT_DOUBLE_EQ(f->value, -27182.8);
  server.publish_load_cell(1500.0);
  ASSERT_TRUE(mrd::test::wait_for([&] { return (f = backend.load_cell().latest()) && f->value > 0.0; }));
  EXPECT_DOUBLE_EQ(f->value, 1500.0);
  backend.stop();
  server.stop();
}

}  // namespace
