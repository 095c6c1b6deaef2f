// mrd-plant as force mode's outer controller: plant.demand_damping is refused unless the
// controller reads a demand from a bus, and the plant's Modbus server serves the demand in the
// controller's register format, read back by the controller's own back end; the demand faults
// (demand_stale, demand_invalid) on Modbus and in the Force_Demand frame.
#include <gtest/gtest.h>

#include <fstream>
#include <memory>
#include <optional>
#include <string>

#include "control/demand_check.hpp"
#include "hal/can/can_codec.hpp"
#include "hal/modbus/modbus_backend.hpp"
#include "record/csv.hpp"
#include "sim/plant/can_node.hpp"
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

// The plant's Modbus server on a free port with a first demand served, and the controller's
// back end reading it in the same register layout.
class ServedDemand {
 public:
  ServedDemand(mrd::hal::modbus::ModbusConfig layout, double first_demand)
      : layout_(std::move(layout)), server_(layout_, "127.0.0.1", 0, "", 1) {
    const auto started = server_.start();
    if (!started.ok) {
      error_ = started.error;
      return;
    }
    server_.publish({.lvdt = 0.001, .coil_current = 0.0, .demand = first_demand}, mrd::plant::ActiveFaults{});
    layout_.tcp.port = server_.port();
    backend_ = std::make_unique<mrd::hal::modbus::ModbusBackend>(layout_, clock_);
    if (!backend_->start().ok) error_ = "the back end did not start";
  }
  ~ServedDemand() {
    if (backend_) backend_->stop();
    server_.stop();
  }
  ServedDemand(const ServedDemand&) = delete;
  ServedDemand& operator=(const ServedDemand&) = delete;

  [[nodiscard]] const std::string& error() const { return error_; }
  [[nodiscard]] mrd::plant::ModbusServer& server() { return server_; }
  [[nodiscard]] mrd::hal::modbus::ModbusBackend& backend() { return *backend_; }
  [[nodiscard]] mrd::hal::Timestamp now() const { return clock_.now(); }
  // The next demand the back end gives (bounded wait); none when it gives none in time.
  std::optional<mrd::hal::Sample> next_demand() {
    std::optional<mrd::hal::Sample> d;
    mrd::test::wait_for([&] { return (d = backend_->demand().latest()).has_value(); });
    return d;
  }
  // True when the back end read at least four more polls' worth and gave no demand.
  bool no_demand_over_polls() {
    const auto reads = backend_->counters()[mrd::hal::modbus::ModbusEvent::kReadsOk];
    const bool polled = mrd::test::wait_for(
        [&] { return backend_->counters()[mrd::hal::modbus::ModbusEvent::kReadsOk] >= reads + 8; });
    return polled && !backend_->demand().latest().has_value();
  }

 private:
  mrd::hal::modbus::ModbusConfig layout_;
  const mrd::hal::MonotonicClock clock_;
  mrd::plant::ModbusServer server_;
  std::unique_ptr<mrd::hal::modbus::ModbusBackend> backend_;
  std::string error_;
};

TEST(PlantDemand, TheModbusServerServesTheDemandTheControllersBackEndReads) {
  mrd::hal::modbus::ModbusConfig layout;
  layout.registers.has_demand = true;
  layout.registers.demand_address = 6;
  ServedDemand served(layout, -1234.5);
  ASSERT_EQ(served.error(), "");
  const auto d = served.next_demand();
  ASSERT_TRUE(d.has_value());
  EXPECT_TRUE(d->usable());
  EXPECT_DOUBLE_EQ(d->value, -1234.5);
}

mrd::plant::ActiveFaults faults_with(mrd::plant::FaultKind kind, double value = 0.0) {
  mrd::plant::ActiveFaults a;
  a.on[static_cast<std::size_t>(kind)] = true;
  a.value[static_cast<std::size_t>(kind)] = value;
  return a;
}

// The plant as outer controller of etc/mrd/hil-force-modbus.toml (demand and its counter over
// Modbus TCP), with `faults` appended.
std::string force_plant(const std::string& faults) {
  return "[plant]\ndemand_damping = 250e3\ncontroller_config = \"" MRD_SOURCE_DIR
         "/etc/mrd/hil-force-modbus.toml\"\n" + faults;
}

TEST(PlantDemand, TheDemandFaultsParseAndAnInvalidDemandLiesBeyondTheControllersRange) {
  auto c = load_plant_config_text(force_plant("[faults.quiet]\nkind = \"demand_stale\"\n"
                                              "start = 2.0\n[faults.bad]\nkind = \"demand_invalid\"\nstart = 3.0\n"),
                                  "plant.toml");
  ASSERT_TRUE(c.ok()) << c.report();
  ASSERT_EQ(c.config.faults.size(), 2u);
  // In the tables' key order: bad, quiet.
  EXPECT_EQ(c.config.faults[1].kind, mrd::plant::FaultKind::kDemandStale);
  EXPECT_EQ(to_string(c.config.faults[1].kind), "demand_stale");
  EXPECT_EQ(c.config.faults[0].kind, mrd::plant::FaultKind::kDemandInvalid);
  EXPECT_EQ(to_string(c.config.faults[0].kind), "demand_invalid");
  // The controller's force.demand_range is the default 60 kN: twice it.
  EXPECT_DOUBLE_EQ(c.config.controller.safety.demand_range, 60e3);
  EXPECT_DOUBLE_EQ(c.config.faults[0].value, 120e3);

  c = load_plant_config_text(force_plant("[faults.bad]\nkind = \"demand_invalid\"\nvalue = -50e3\n"), "fair.toml");
  EXPECT_NE(c.report().find("fair.toml:6: faults.bad.value: must lie beyond the controller's force.demand_range"),
            std::string::npos)
      << c.report();
  c = load_plant_config_text(force_plant("[faults.bad]\nkind = \"demand_invalid\"\nvalue = -70e3\n"),
                             "negative.toml");
  EXPECT_TRUE(c.ok()) << c.report();
}

// A demand fault that could inject nothing is refused where it is named.
TEST(PlantDemand, ADemandFaultWithNoDemandToSpoilIsAnError) {
  auto c = load_plant_config_text("[plant]\ncontroller_config = \"\"\n[faults.quiet]\nkind = \"demand_stale\"\n",
                                  "silent.toml");
  EXPECT_NE(c.report().find("silent.toml:4: faults.quiet.kind: the plant sends no demand"), std::string::npos)
      << c.report();
  // Over Modbus without the controller's counter a frozen demand reads as fresh.
  const std::string no_counter = testing::TempDir() + "mrd_force_no_counter.toml";
  {
    std::string text = mrd::record::read_text_file(MRD_SOURCE_DIR "/etc/mrd/hil-force-modbus.toml");
    const std::string counter = "demand_counter_address = 4";
    ASSERT_NE(text.find(counter), std::string::npos);
    text.replace(text.find(counter), counter.size(), "demand_counter_address = -1");
    std::ofstream(no_counter) << text;
  }
  c = load_plant_config_text("[plant]\ndemand_damping = 250e3\ncontroller_config = \"" + no_counter +
                                 "\"\n[faults.quiet]\nkind = \"demand_stale\"\n",
                             "uncounted.toml");
  EXPECT_NE(c.report().find("uncounted.toml:5: faults.quiet.kind: over Modbus a stale demand is invisible"),
            std::string::npos)
      << c.report();
}

// With the controller's counter register, the server counts each period it sends a demand;
// demand_stale freezes value and counter (the controller's back end then takes no demand),
// demand_invalid serves the fault's value, which the controller's checker calls out of range.
TEST(PlantDemand, TheModbusServerCountsDemandsAndServesTheDemandFaults) {
  using mrd::plant::FaultKind;
  mrd::hal::modbus::ModbusConfig layout;
  layout.registers.has_demand = true;
  layout.registers.demand_address = 6;
  layout.registers.demand_counter_address = 8;
  ServedDemand served(layout, 100.0);
  ASSERT_EQ(served.error(), "");
  // The first demand sent is count 1, which the back end takes as its reference.
  EXPECT_TRUE(served.no_demand_over_polls()) << "the count found at the start gave a demand";

  served.server().publish({.lvdt = 0.001, .coil_current = 0.0, .demand = 200.0}, mrd::plant::ActiveFaults{});
  auto d = served.next_demand();
  ASSERT_TRUE(d.has_value());
  EXPECT_DOUBLE_EQ(d->value, 200.0);
  EXPECT_EQ(d->sequence, 2u);

  // Stale: periods go by with new demands the server does not serve.
  for (int i = 0; i < 5; ++i) served.server().publish({.lvdt = 0.001, .coil_current = 0.0, .demand = 300.0 + i}, faults_with(FaultKind::kDemandStale));
  EXPECT_TRUE(served.no_demand_over_polls()) << "a stale demand was served as new";

  // Invalid: the fault's value, counted like any demand.
  served.server().publish({.lvdt = 0.001, .coil_current = 0.0, .demand = 400.0}, faults_with(FaultKind::kDemandInvalid, 120e3));
  d = served.next_demand();
  ASSERT_TRUE(d.has_value());
  EXPECT_DOUBLE_EQ(d->value, 120e3);
  EXPECT_EQ(d->sequence, 3u);
  mrd::control::DemandChecker checker({.range = 60e3, .max_age = std::chrono::seconds{1}});
  EXPECT_EQ(checker.check(d, served.now()), mrd::control::SampleCheck::kOutOfRange);

  // Not the outer controller: nothing counted, nothing new.
  served.server().publish({.lvdt = 0.001, .coil_current = 0.0, .demand = std::nullopt}, mrd::plant::ActiveFaults{});
  EXPECT_TRUE(served.no_demand_over_polls());
}

// The Force_Demand frame under the demand faults, decoded by the controller's codec.
TEST(PlantDemand, TheForceDemandFrameGoesSilentWhenStaleAndCarriesTheInvalidBit) {
  using mrd::plant::FaultKind;
  constexpr std::uint32_t kId = 0x120;
  std::uint8_t counter = 14;
  mrd::hal::can::RollingCounterCheck sequence;
  const auto decode = [&](const mrd::hal::can::Frame& f) {
    return mrd::hal::can::decode_demand(f.id, {f.data.data(), mrd::hal::can::kFrameLength}, kId, &sequence);
  };

  auto frame = mrd::plant::demand_frame(kId, -1234.5, mrd::plant::ActiveFaults{}, counter);
  ASSERT_TRUE(frame.has_value());
  auto d = decode(*frame);
  EXPECT_EQ(d.status, mrd::hal::can::DecodeStatus::kOk);
  EXPECT_DOUBLE_EQ(d.value.demand, -1234.5);
  EXPECT_FALSE(d.value.invalid);
  EXPECT_EQ(d.value.counter, 14);
  EXPECT_EQ(counter, 15);

  // Stale: no frame, and no count lost, so the next frame is in sequence.
  EXPECT_FALSE(mrd::plant::demand_frame(kId, 10.0, faults_with(FaultKind::kDemandStale), counter).has_value());
  EXPECT_EQ(counter, 15);

  frame = mrd::plant::demand_frame(kId, 500.0, faults_with(FaultKind::kDemandInvalid, 120e3), counter);
  ASSERT_TRUE(frame.has_value());
  d = decode(*frame);
  EXPECT_EQ(d.status, mrd::hal::can::DecodeStatus::kOk);
  EXPECT_TRUE(d.value.invalid);
  EXPECT_DOUBLE_EQ(d.value.demand, 500.0) << "on CAN the bit says it, the value stays";
  EXPECT_EQ(counter, 0) << "4-bit counter wraps";
}

}  // namespace
