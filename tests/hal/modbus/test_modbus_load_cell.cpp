// Force mode's optional load cell over Modbus: a register pair read with the LVDT each poll
// (modbus.registers.load_cell_*), next to the demand's, as samples in N.
#include <gtest/gtest.h>

#include <optional>

#include "hal/modbus/modbus_backend.hpp"
#include "tests/hal/modbus/modbus_test_server.hpp"
#include "tests/hal/test_wait.hpp"

namespace {

using mrd::hal::Sample;
using mrd::hal::MonotonicClock;
using mrd::hal::modbus::ModbusBackend;
using mrd::hal::modbus::ModbusEvent;
using mrd::test::ModbusTestServer;
using mrd::test::wait_for;
using mrd::test::kLvdtAddress;

TEST(ModbusLoadCell, ReadsTheLoadCellRegistersAsSamplesInNewtonsApartFromTheDemand) {
  constexpr int kLoadCellAddress = 44;
  constexpr int kDemandAddress = 40;
  MonotonicClock clock;
  ModbusTestServer server;
  ASSERT_TRUE(server.listening());
  server.set_input_registers(kLvdtAddress, {0x0000, 1000});
  server.set_input_registers(kLoadCellAddress, {0x0000, 0xA8CA});    // 43210 counts of 0.1 N
  server.set_holding_registers(kDemandAddress, {0xFFFF, 0xCFC7});    // -12345 counts
  auto config = mrd::test::client_config(server.port());
  config.registers.has_demand = true;
  config.registers.demand_address = kDemandAddress;
  config.registers.has_load_cell = true;
  config.registers.load_cell_address = kLoadCellAddress;
  ModbusBackend backend(config, clock);
  ASSERT_TRUE(backend.start().ok);

  std::optional<Sample> f;
  ASSERT_TRUE(wait_for([&] { return (f = backend.load_cell().latest()).has_value(); }));
  EXPECT_TRUE(f->usable());
  EXPECT_DOUBLE_EQ(f->value, 4321.0);
  std::optional<mrd::hal::Sample> d;
  ASSERT_TRUE(wait_for([&] { return (d = backend.demand().latest()).has_value(); }));
  EXPECT_DOUBLE_EQ(d->value, -1234.5) << "the load cell is not the demand";

  server.set_input_registers(kLoadCellAddress, {0xFFFF, 0xD8F0});  // -10000 counts: -1000 N
  ASSERT_TRUE(wait_for([&] { return (f = backend.load_cell().latest()) && f->value < 0.0; }));
  EXPECT_DOUBLE_EQ(f->value, -1000.0);
  const std::uint32_t before = f->sequence;
  ASSERT_TRUE(wait_for([&] { return (f = backend.load_cell().latest()).has_value(); }));
  EXPECT_GT(f->sequence, before) << "one new sample per poll";
}

TEST(ModbusLoadCell, AValueThatDoesNotDecodeIsACorruptedSample) {
  constexpr int kLoadCellAddress = 44;
  MonotonicClock clock;
  ModbusTestServer server;
  ASSERT_TRUE(server.listening());
  server.set_input_registers(kLvdtAddress, {0x0000, 1000});
  server.set_input_registers(kLoadCellAddress, {0x7FC0, 0x0000});  // NaN as float32
  auto config = mrd::test::client_config(server.port());
  config.registers.has_load_cell = true;
  config.registers.load_cell_address = kLoadCellAddress;
  config.registers.load_cell.type = mrd::hal::modbus::RegisterType::kFloat32;
  config.registers.load_cell.scale = 1.0;
  ModbusBackend backend(config, clock);
  ASSERT_TRUE(backend.start().ok);
  std::optional<Sample> f;
  ASSERT_TRUE(wait_for([&] { return (f = backend.load_cell().latest()).has_value(); }));
  EXPECT_FALSE(f->usable());
  EXPECT_TRUE(f->flags & mrd::hal::kSampleCorrupted);
  EXPECT_GE(backend.counters()[ModbusEvent::kDecodeErrors], 1u);
}

TEST(ModbusLoadCell, WithoutHasLoadCellNoLoadCellIsRead) {
  MonotonicClock clock;
  ModbusTestServer server;
  ASSERT_TRUE(server.listening());
  server.set_input_registers(kLvdtAddress, {0x0000, 1000});
  ModbusBackend backend(mrd::test::client_config(server.port()), clock);
  ASSERT_TRUE(backend.start().ok);
  ASSERT_TRUE(wait_for([&] { return backend.lvdt().latest().has_value(); }));
  EXPECT_FALSE(backend.load_cell().latest().has_value());
}

// A device that refuses the load cell's registers (exception: past its map) still serves the
// LVDT and the current readback every poll, and the load cell reads as corrupted samples: a
// refused load cell freezes the correction, it must not starve the readback (readback_lost ->
// SAFE).
TEST(ModbusLoadCell, ARefusedLoadCellLeavesTheLvdtAndTheReadbackFlowing) {
  using mrd::test::kFeedbackAddress;
  MonotonicClock clock;
  ModbusTestServer server;
  ASSERT_TRUE(server.listening());
  server.set_input_registers(kLvdtAddress, {0x0000, 1000});
  server.set_input_registers(kFeedbackAddress, {0x0000, 1234});
  auto config = mrd::test::client_config(server.port());
  config.registers.has_current_feedback = true;
  config.registers.current_feedback_address = kFeedbackAddress;
  config.registers.current_feedback_kind = mrd::hal::modbus::RegisterKind::kInput;
  config.registers.has_load_cell = true;
  config.registers.load_cell_address = ModbusTestServer::kRegisters;  // past the device's map
  ModbusBackend backend(config, clock);
  ASSERT_TRUE(backend.start().ok);

  std::optional<Sample> f;
  ASSERT_TRUE(wait_for([&] { return (f = backend.load_cell().latest()).has_value(); }));
  EXPECT_FALSE(f->usable());
  EXPECT_TRUE(f->flags & mrd::hal::kSampleCorrupted);
  // Polls go on past the refusal: new LVDT samples and readings keep coming.
  std::optional<mrd::hal::Sample> first;
  ASSERT_TRUE(wait_for([&] { return (first = backend.lvdt().latest()).has_value(); }));
  ASSERT_TRUE(wait_for([&] {
    const auto next = backend.lvdt().latest();
    return next && next->sequence > first->sequence + 3;
  })) << "reads ok " << backend.counters()[ModbusEvent::kReadsOk];
  ASSERT_TRUE(wait_for([&] { return backend.measured().has_value(); }));
  EXPECT_TRUE(backend.connected()) << "a refused register is not a lost link";
}

}  // namespace
