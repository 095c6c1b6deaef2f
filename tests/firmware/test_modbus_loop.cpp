// The loop on the Modbus TCP back end, configured from TOML, against a real libmodbus server on
// 127.0.0.1 started by the test, paced by the real-time runner (this is real I/O, so real time).
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <string>

#include "config/config_loader.hpp"
#include "firmware/control_loop.hpp"
#include "firmware/hal_set.hpp"
#include "runtime/rt_runner.hpp"
#include "tests/hal/modbus/modbus_test_server.hpp"
#include "tests/hal/test_wait.hpp"

namespace {

TEST(ModbusLoop, ConfiguredFromTomlTheLoopReadsTheLvdtWritesTheSetpointAndEndsAtFailSafe) {
  mrd::test::ModbusTestServer server;
  ASSERT_TRUE(server.listening());
  server.set_input_registers(0, {0, 15000});  // 15 mm as int32, 1 um per count: Table 4 level 2

  const auto loaded = mrd::config::load_config_text(
      "[backends]\nlvdt = \"modbus\"\ndriver = \"modbus\"\n[modbus.tcp]\nport = " +
          std::to_string(server.port()) + "\n[safety]\nrecovery_periods = 20\n"
          // This test is about the bus, not about timing on a loaded machine.
          "overrun_limit = 1000000\nstale_periods = 100\nwrite_failure_periods = 100\n",
      "modbus.toml");
  ASSERT_TRUE(loaded.ok()) << loaded.report();

  const mrd::hal::MonotonicClock clock;
  mrd::firmware::HalSet hal(loaded.config, clock);
  ASSERT_EQ(hal.mock() != nullptr, true) << "the lines stay on the mock";
  ASSERT_TRUE(hal.start().ok);
  mrd::firmware::ControlLoop loop(loaded.config.law, loaded.config.safety, hal.devices());

  // Run until the loop has been in RUN for a while (bounded), then stop as on SIGTERM.
  std::atomic<bool> stop{false};
  mrd::runtime::LoopStatistics stats;
  mrd::runtime::RealTimeRunner runner(loaded.config.period());
  std::uint64_t run_cycles = 0;
  const auto next = runner.run(
      [&](mrd::hal::Timestamp release) {
        hal.mock()->clock.set(release);
        loop.step(release);
        if (loop.state() == mrd::control::SupervisorState::kRun && ++run_cycles >= 200) stop = true;
      },
      stop, 20000, stats);

  EXPECT_GE(run_cycles, 200u) << "never ran 200 cycles in RUN within 20 s";
  EXPECT_DOUBLE_EQ(loop.last().displacement, 0.015);
  EXPECT_EQ(loop.last().scheduled_current, 0.4);
  // The compensated command of the last cycle reaches the device's holding register, in mA.
  const double command = loop.last().setpoint;
  EXPECT_GT(command, 0.1);
  const auto counts = static_cast<std::uint16_t>(std::lround(command * 1000.0));
  EXPECT_TRUE(mrd::test::wait_for([&] { return server.holding_register(0) == counts; }))
      << server.holding_register(0) << " != " << counts;

  // Stop as on SIGTERM: one cycle in SAFE, and the fail-safe 0 A reaches the device.
  loop.request_shutdown();
  loop.step(next);
  EXPECT_EQ(loop.last().setpoint, 0.0);
  EXPECT_TRUE(mrd::test::wait_for([&] { return server.holding_register(0) == 0; }));
  hal.stop();
}

}  // namespace
