#include "hal/modbus/modbus_backend.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <optional>

#include "tests/hal/modbus/modbus_test_server.hpp"
#include "tests/hal/test_wait.hpp"

namespace {

using namespace std::chrono_literals;
using mrd::hal::Sample;
using mrd::hal::IoStatus;
using mrd::hal::MonotonicClock;
using mrd::hal::modbus::ModbusBackend;
using mrd::hal::modbus::ModbusConfig;
using mrd::hal::modbus::ModbusEvent;
using mrd::test::ModbusTestServer;
using mrd::test::wait_for;

using mrd::test::kFeedbackAddress;
using mrd::test::kLvdtAddress;
using mrd::test::kSetpointAddress;
ModbusConfig config_for(int port) { return mrd::test::client_config(port); }

// Drains the back end until a sample satisfying `pred` arrives (bounded).
template <typename Pred>
std::optional<Sample> sample_where(ModbusBackend& backend, Pred pred) {
  std::optional<Sample> found;
  wait_for([&] {
    if (auto s = backend.lvdt().latest(); s && pred(*s)) found = s;
    return found.has_value();
  });
  return found;
}

std::optional<Sample> any_sample(ModbusBackend& backend) {
  return sample_where(backend, [](const Sample&) { return true; });
}

class ModbusBackendTest : public ::testing::Test {
 protected:
  MonotonicClock clock;
};

TEST_F(ModbusBackendTest, ReadsTimestampedSamplesAndWritesSetpoints) {
  ModbusTestServer server;
  ASSERT_TRUE(server.listening());
  server.set_input_registers(kLvdtAddress, {0x0000, 12345});
  auto config = config_for(server.port());
  config.registers.has_current_feedback = true;
  config.registers.current_feedback_address = kFeedbackAddress;
  server.set_input_registers(kFeedbackAddress, {1100});

  ModbusBackend backend(config, clock);
  const auto before = clock.now();
  ASSERT_TRUE(backend.start().ok);

  const auto first = any_sample(backend);
  ASSERT_TRUE(first.has_value());
  EXPECT_NEAR(first->value, 0.012345, 1e-12);
  EXPECT_TRUE(first->usable());
  EXPECT_GE(first->timestamp, before);
  EXPECT_TRUE(backend.connected());

  // A later sample carries a later sequence number and the register's new value.
  server.set_input_registers(kLvdtAddress, {0xFFFF, 0xFFFF});  // -1 um
  const auto second = sample_where(backend, [](const auto& s) { return s.value < 0.0; });
  ASSERT_TRUE(second.has_value());
  EXPECT_NEAR(second->value, -1e-6, 1e-15);
  EXPECT_GT(second->sequence, first->sequence);
  EXPECT_GE(second->timestamp, first->timestamp);

  EXPECT_EQ(backend.write_setpoint(1.234), IoStatus::kOk);
  EXPECT_TRUE(wait_for([&] { return server.holding_register(kSetpointAddress) == 1234; }));
  EXPECT_EQ(backend.write_setpoint(-0.5), IoStatus::kOk);  // int16 register: signed
  EXPECT_TRUE(wait_for([&] {
    return server.holding_register(kSetpointAddress) == static_cast<std::uint16_t>(-500);
  }));

  std::optional<mrd::hal::CurrentReading> current;
  EXPECT_TRUE(wait_for([&] { return (current = backend.measured()).has_value(); }));
  EXPECT_NEAR(current->value, 1.1, 1e-12);

  // The server stores a register before it answers, so the client's count can trail it.
  EXPECT_TRUE(wait_for([&] { return backend.counters()[ModbusEvent::kWritesOk] >= 2; }));
  const auto counters = backend.counters();
  EXPECT_EQ(counters[ModbusEvent::kConnects], 1u);
  EXPECT_EQ(counters[ModbusEvent::kReadErrors], 0u);
  backend.stop();
  EXPECT_FALSE(backend.connected());
}

TEST_F(ModbusBackendTest, ReadsWordSwappedFloatFromHoldingRegisters) {
  ModbusTestServer server;
  ASSERT_TRUE(server.listening());
  server.set_holding_registers(kLvdtAddress, {0x0000, 0x3FC0});  // 1.5f, low word first
  auto config = config_for(server.port());
  config.registers.lvdt_kind = mrd::hal::modbus::RegisterKind::kHolding;
  config.registers.lvdt = {mrd::hal::modbus::RegisterType::kFloat32,
                           mrd::hal::modbus::WordOrder::kLowFirst,
                           mrd::hal::modbus::ByteOrder::kNormal, 1e-3, 0.0};  // mm -> m
  ModbusBackend backend(config, clock);
  ASSERT_TRUE(backend.start().ok);
  const auto s = any_sample(backend);
  ASSERT_TRUE(s.has_value());
  EXPECT_DOUBLE_EQ(s->value, 1.5e-3);
}

TEST_F(ModbusBackendTest, NonFiniteRegisterGivesACorruptedSampleNotACrash) {
  ModbusTestServer server;
  ASSERT_TRUE(server.listening());
  server.set_input_registers(kLvdtAddress, {0x7FC0, 0x0000});  // NaN
  auto config = config_for(server.port());
  config.registers.lvdt.type = mrd::hal::modbus::RegisterType::kFloat32;
  ModbusBackend backend(config, clock);
  ASSERT_TRUE(backend.start().ok);
  const auto s = any_sample(backend);
  ASSERT_TRUE(s.has_value());
  EXPECT_FALSE(s->usable());
  EXPECT_NE(s->flags & mrd::hal::kSampleCorrupted, 0);
  EXPECT_GE(backend.counters()[ModbusEvent::kDecodeErrors], 1u);
  EXPECT_TRUE(backend.connected());
}

// The outer controller's demand in a holding-register pair, 0.1 N per count, read with the
// LVDT each poll; a value that does not decode is a corrupted demand.
TEST_F(ModbusBackendTest, ReadsTheDemandRegisterAsSamplesInNewtons) {
  constexpr int kDemandAddress = 40;
  ModbusTestServer server;
  ASSERT_TRUE(server.listening());
  server.set_input_registers(kLvdtAddress, {0x0000, 1000});
  server.set_holding_registers(kDemandAddress, {0xFFFF, 0xCFC7});  // -12345 counts
  auto config = config_for(server.port());
  config.registers.has_demand = true;
  config.registers.demand_address = kDemandAddress;
  ModbusBackend backend(config, clock);
  ASSERT_TRUE(backend.start().ok);

  std::optional<mrd::hal::Sample> d;
  ASSERT_TRUE(wait_for([&] { return (d = backend.demand().latest()).has_value(); }));
  EXPECT_TRUE(d->usable());
  EXPECT_DOUBLE_EQ(d->value, -1234.5);
  const auto lvdt = any_sample(backend);
  ASSERT_TRUE(lvdt.has_value());
  EXPECT_DOUBLE_EQ(lvdt->value, 1e-3) << "the LVDT is still read";

  server.set_holding_registers(kDemandAddress, {0x0000, 0x2710});  // 1000.0 N
  ASSERT_TRUE(wait_for([&] { return (d = backend.demand().latest()) && d->value > 0.0; }));
  EXPECT_DOUBLE_EQ(d->value, 1000.0);

  ModbusTestServer nan_server;
  nan_server.set_input_registers(kLvdtAddress, {0x0000, 1000});
  nan_server.set_holding_registers(kDemandAddress, {0x7FC0, 0x0000});  // NaN as float32
  config = config_for(nan_server.port());
  config.registers.has_demand = true;
  config.registers.demand_address = kDemandAddress;
  config.registers.demand.type = mrd::hal::modbus::RegisterType::kFloat32;
  config.registers.demand.scale = 1.0;
  ModbusBackend nan_backend(config, clock);
  ASSERT_TRUE(nan_backend.start().ok);
  ASSERT_TRUE(wait_for([&] { return (d = nan_backend.demand().latest()).has_value(); }));
  EXPECT_FALSE(d->usable());
  EXPECT_TRUE(d->flags & mrd::hal::kSampleCorrupted);
  EXPECT_GE(nan_backend.counters()[ModbusEvent::kDecodeErrors], 1u);
}

// With a demand counter register, a poll yields a demand only when the counter moved since the
// previous one, with the counter as its sequence: an outer controller that stops counting goes
// silent (missing, then stale in the checker) instead of repeating its last value as fresh.
// Each layout: the counter right after the value (one read), right before it (one read), and
// apart (two reads).
TEST_F(ModbusBackendTest, ADemandCounterGivesADemandOnlyWhenItAdvancesAndWrapsAround) {
  constexpr int kDemandAddress = 40;
  struct Layout {
    const char* name;
    int counter_address;
  };
  for (const Layout layout : {Layout{"after", kDemandAddress + 2}, Layout{"before", kDemandAddress - 1},
                              Layout{"apart", kDemandAddress + 10}}) {
    SCOPED_TRACE(layout.name);
    ModbusTestServer server;
    ASSERT_TRUE(server.listening());
    server.set_input_registers(kLvdtAddress, {0x0000, 1000});
    // The outer controller's write: the value, then its count (one call where they are adjacent).
    const auto publish = [&](std::uint16_t low_word, std::uint16_t counter) {
      if (layout.counter_address == kDemandAddress + 2) {
        server.set_holding_registers(kDemandAddress, {0x0000, low_word, counter});
      } else if (layout.counter_address == kDemandAddress - 1) {
        server.set_holding_registers(layout.counter_address, {counter, 0x0000, low_word});
      } else {
        server.set_holding_registers(kDemandAddress, {0x0000, low_word});
        server.set_holding_registers(layout.counter_address, {counter});
      }
    };
    publish(100, 7);  // 10.0 N, count 7
    auto config = config_for(server.port());
    config.registers.has_demand = true;
    config.registers.demand_address = kDemandAddress;
    config.registers.demand_counter_address = layout.counter_address;
    ModbusBackend backend(config, clock);
    ASSERT_TRUE(backend.start().ok);

    // What the registers held at the start is no demand: the first count is the reference.
    // Each poll reads at least the LVDT and the counter, so 8 good reads are at least 4 polls.
    const auto polls_later = [&] {
      const auto reads = backend.counters()[ModbusEvent::kReadsOk];
      return wait_for([&] { return backend.counters()[ModbusEvent::kReadsOk] >= reads + 8; });
    };
    ASSERT_TRUE(polls_later());
    EXPECT_FALSE(backend.demand().latest().has_value()) << "the count found at the start gave a demand";

    std::optional<mrd::hal::Sample> d;
    publish(150, 8);
    ASSERT_TRUE(wait_for([&] { return (d = backend.demand().latest()).has_value(); }));
    EXPECT_DOUBLE_EQ(d->value, 15.0);
    EXPECT_EQ(d->sequence, 8u);
    EXPECT_TRUE(d->usable());

    // Frozen: polls go on (reads counted) but no demand comes.
    ASSERT_TRUE(polls_later());
    EXPECT_FALSE(backend.demand().latest().has_value()) << "a frozen counter gave a demand";
    EXPECT_TRUE(any_sample(backend).has_value()) << "the LVDT is still read";

    // Advances: one demand with the new value; a jump of 3 shows in the sequence.
    publish(200, 10);
    ASSERT_TRUE(wait_for([&] { return (d = backend.demand().latest()).has_value(); }));
    EXPECT_DOUBLE_EQ(d->value, 20.0);
    EXPECT_EQ(d->sequence, 10u);

    // Wrap: 65535 -> 0 is an advance, not a frozen counter.
    publish(300, 65535);
    ASSERT_TRUE(wait_for([&] { return (d = backend.demand().latest()) && d->sequence == 65535u; }));
    EXPECT_DOUBLE_EQ(d->value, 30.0);
    publish(400, 0);
    ASSERT_TRUE(wait_for([&] { return (d = backend.demand().latest()).has_value(); }));
    EXPECT_EQ(d->sequence, 0u);
    EXPECT_DOUBLE_EQ(d->value, 40.0);

    // A counter that moves with an unchanged value is a new demand: a held demand is fair.
    publish(400, 1);
    ASSERT_TRUE(wait_for([&] { return (d = backend.demand().latest()).has_value(); }));
    EXPECT_EQ(d->sequence, 1u);
    EXPECT_DOUBLE_EQ(d->value, 40.0);
    EXPECT_EQ(backend.counters()[ModbusEvent::kReadErrors], 0u);
  }
}

TEST_F(ModbusBackendTest, WithoutHasDemandNoDemandIsRead) {
  ModbusTestServer server;
  ASSERT_TRUE(server.listening());
  server.set_input_registers(kLvdtAddress, {0x0000, 1000});
  ModbusBackend backend(config_for(server.port()), clock);
  ASSERT_TRUE(backend.start().ok);
  ASSERT_TRUE(any_sample(backend).has_value());
  EXPECT_FALSE(backend.demand().latest().has_value());
}

TEST_F(ModbusBackendTest, ReconnectsWhenTheServerGoesAwayAndComesBack) {
  auto server = std::make_unique<ModbusTestServer>();
  ASSERT_TRUE(server->listening());
  const int port = server->port();
  server->set_input_registers(kLvdtAddress, {0, 100});
  ModbusBackend backend(config_for(port), clock);
  ASSERT_TRUE(backend.start().ok);
  ASSERT_TRUE(any_sample(backend).has_value());

  server.reset();  // the device goes away
  EXPECT_TRUE(wait_for([&] { return backend.counters()[ModbusEvent::kDisconnects] >= 1; }));
  EXPECT_TRUE(wait_for([&] { return backend.counters()[ModbusEvent::kConnectFailures] >= 2; }));
  EXPECT_FALSE(backend.connected());
  EXPECT_TRUE(backend.link_problem().value_or("").ends_with(", link lost")) << backend.link_problem().value_or("none");
  // While it is away, setpoints are queued and the loop is told.
  EXPECT_EQ(backend.write_setpoint(0.25), IoStatus::kNotConnected);
  (void)backend.lvdt().latest();  // drop what arrived before the outage
  EXPECT_FALSE(backend.lvdt().latest().has_value());

  server = std::make_unique<ModbusTestServer>(ModbusTestServer::Mode::kReply, port);
  ASSERT_TRUE(server->listening());
  server->set_input_registers(kLvdtAddress, {0, 200});
  const auto s = sample_where(backend, [](const auto& x) { return x.value > 150e-6; });
  ASSERT_TRUE(s.has_value());
  EXPECT_NEAR(s->value, 200e-6, 1e-12);
  // The setpoint queued during the outage lands after reconnecting.
  EXPECT_TRUE(wait_for([&] { return server->holding_register(kSetpointAddress) == 250; }));

  const auto counters = backend.counters();
  EXPECT_GE(counters[ModbusEvent::kConnects], 2u);
  EXPECT_GE(counters[ModbusEvent::kReadErrors] + counters[ModbusEvent::kWriteErrors], 1u);
  EXPECT_TRUE(backend.connected());
  EXPECT_FALSE(backend.link_problem().has_value());
}

TEST_F(ModbusBackendTest, SilentServerCountsTimeoutsAndStillStops) {
  ModbusTestServer server(ModbusTestServer::Mode::kSilent);
  ASSERT_TRUE(server.listening());
  auto config = config_for(server.port());
  config.response_timeout = 30ms;
  ModbusBackend backend(config, clock);
  ASSERT_TRUE(backend.start().ok);
  EXPECT_TRUE(wait_for([&] { return backend.counters()[ModbusEvent::kTimeouts] >= 2; }));
  EXPECT_FALSE(backend.lvdt().latest().has_value());
  EXPECT_EQ(backend.last_errno(), ETIMEDOUT);
  const auto counters = backend.counters();
  EXPECT_GE(counters[ModbusEvent::kDisconnects], 1u);
  EXPECT_EQ(counters[ModbusEvent::kReadsOk], 0u);
  backend.stop();  // returns within one response timeout
}

TEST_F(ModbusBackendTest, ExceptionResponseIsCountedWithoutDroppingTheLink) {
  ModbusTestServer server;
  ASSERT_TRUE(server.listening());
  auto config = config_for(server.port());
  config.registers.lvdt_address = ModbusTestServer::kRegisters + 100;  // illegal data address
  ModbusBackend backend(config, clock);
  ASSERT_TRUE(backend.start().ok);
  EXPECT_TRUE(wait_for([&] { return backend.counters()[ModbusEvent::kExceptionResponses] >= 3; }));
  const auto counters = backend.counters();
  EXPECT_EQ(counters[ModbusEvent::kConnects], 1u);
  EXPECT_EQ(counters[ModbusEvent::kDisconnects], 0u);
  EXPECT_FALSE(backend.lvdt().latest().has_value());
}

TEST_F(ModbusBackendTest, NoServerMeansConnectFailuresWithBackOff) {
  int port = 0;
  {
    ModbusTestServer probe;  // find a port nobody listens on once it closes
    port = probe.port();
  }
  ModbusBackend backend(config_for(port), clock);
  ASSERT_TRUE(backend.start().ok);
  EXPECT_TRUE(wait_for([&] { return backend.counters()[ModbusEvent::kConnectFailures] >= 3; }));
  EXPECT_FALSE(backend.connected());
  EXPECT_FALSE(backend.lvdt().latest().has_value());
  // Where and why, as mbpoll says it.
  const auto problem = backend.link_problem();
  ASSERT_TRUE(problem.has_value());
  EXPECT_TRUE(problem->starts_with("127.0.0.1:" + std::to_string(port) + " (slave 1): Connection refused, "))
      << *problem;
  EXPECT_TRUE(problem->ends_with("failed connect attempts, never connected")) << *problem;
}

TEST_F(ModbusBackendTest, MissingSerialDeviceIsRetriedNotFatal) {
  ModbusConfig config = config_for(502);
  config.transport = mrd::hal::modbus::Transport::kRtu;
  config.rtu.device = "/dev/mrd-no-such-tty";
  ModbusBackend backend(config, clock);
  ASSERT_TRUE(backend.start().ok);
  EXPECT_TRUE(wait_for([&] { return backend.counters()[ModbusEvent::kConnectFailures] >= 1; }));
  EXPECT_FALSE(backend.connected());
  const auto problem = backend.link_problem();
  ASSERT_TRUE(problem.has_value());
  EXPECT_TRUE(problem->starts_with("/dev/mrd-no-such-tty 115200 8N1 (slave 1): No such file or directory, "))
      << *problem;
}

TEST_F(ModbusBackendTest, BadConfigAndBadSetpointsAreRefusedClearly) {
  ModbusConfig config = config_for(0);  // port 0 is invalid for a client
  config.registers.setpoint.scale = 0.0;
  ModbusBackend bad(config, clock);
  const auto result = bad.start();
  EXPECT_FALSE(result.ok);
  EXPECT_NE(result.error.find("tcp.port"), std::string::npos) << result.error;
  EXPECT_NE(result.error.find("registers.setpoint.scale"), std::string::npos) << result.error;

  ModbusBackend backend(config_for(1), clock);  // never started: write path still answers
  EXPECT_EQ(backend.write_setpoint(std::nan("")), IoStatus::kInvalidArgument);
  EXPECT_EQ(backend.write_setpoint(40.0), IoStatus::kInvalidArgument);  // > 32.767 A in int16 mA
  EXPECT_EQ(backend.write_setpoint(1.0), IoStatus::kNotConnected);
}

}  // namespace
