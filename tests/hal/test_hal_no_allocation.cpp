// Per-cycle HAL calls must not touch the heap: the loop calls them 1e3-1e4 times a second.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>

#include "hal/can/can_codec.hpp"
#include "hal/latest_mailbox.hpp"
#include "hal/mock/mock_hal.hpp"
#include "hal/modbus/register_codec.hpp"
#include "hal/sample_channel.hpp"
#include "tests/support/allocation_counter.hpp"

namespace {

using namespace std::chrono_literals;
using mrd::test::start_counting_allocations;
using mrd::test::stop_counting_allocations;
using namespace mrd::hal;

constexpr int kCycles = 100000;

TEST(HalRealTime, MockHalCycleDoesNotAllocateEvenUnderFaults) {
  mock::FaultScript script;
  std::int64_t c = 0;
  for (int k = 0; k < static_cast<int>(mock::FaultKind::kCount); ++k) {
    const auto kind = static_cast<mock::FaultKind>(k);
    script.add({kind, c * 1ms, (c + 500) * 1ms, kind == mock::FaultKind::kDroppedSample ? 3.0 : 0.1});
    c += 1000;
  }
  mock::MockHal hal{script};
  double sink = 0.0;
  start_counting_allocations();
  for (int i = 0; i < kCycles; ++i) {
    hal.clock.advance(1ms);
    hal.lvdt.set_value(0.01 * std::sin(i * 1e-3));
    for (SampleSource* channel : {&hal.lvdt, &hal.demand, &hal.load_cell}) {
      if (const auto s = channel->latest()) sink += s->usable() ? s->value : 0.0;
    }
    (void)hal.driver.write_setpoint(1.0);
    if (const auto m = hal.driver.measured()) sink += m->value;
    sink += hal.lines.driver_fault().value_or(true) ? 1.0 : 0.0;
    (void)hal.lines.set_enable(i % 2 == 0);
    (void)hal.lines.toggle_heartbeat();
  }
  EXPECT_EQ(stop_counting_allocations(), 0u);
  EXPECT_EQ(hal.driver.writes() + hal.driver.failed_writes() + hal.driver.setpoint_acks().refused,
            static_cast<std::uint64_t>(kCycles));
  volatile double keep = sink;  // the NaN fault makes it NaN; it only keeps the calls alive
  (void)keep;
}

TEST(HalRealTime, RingsMailboxesAndCodecsDoNotAllocate) {
  SampleChannel channel;
  LatestMailbox<modbus::EncodeResult> mailbox;
  const modbus::RegisterFormat format{modbus::RegisterType::kInt32, modbus::WordOrder::kLowFirst,
                                      modbus::ByteOrder::kSwapped, 1e-6, 0.0};
  can::RollingCounterCheck counter;
  can::RollingCounterCheck demand_counter;
  can::RollingCounterCheck load_cell_counter;
  double sink = 0.0;
  start_counting_allocations();
  for (int i = 0; i < kCycles; ++i) {
    (void)channel.push({i * 1e-6, Timestamp{i}, channel.next_sequence(), kSampleValid});
    if (const auto s = channel.latest()) sink += s->value;
    const auto encoded = modbus::encode_register(i * 1e-6, format);
    mailbox.publish(encoded);
    if (const auto e = mailbox.take()) sink += modbus::decode_register(e->view(), format).value;
    const auto frame = can::encode_lvdt(can::kDefaultLvdtId,
                                        {i * 1e-6, false, static_cast<std::uint8_t>(i & 0xF)});
    sink += can::decode_lvdt(frame.frame.id, frame.frame.data, can::kDefaultLvdtId, &counter)
                .value.displacement;
    const auto demand = can::encode_demand(can::kDefaultDemandId,
                                           {i * 0.1, false, static_cast<std::uint8_t>(i & 0xF)});
    sink += can::decode_demand(demand.frame.id, demand.frame.data, can::kDefaultDemandId, &demand_counter)
                .value.demand;
    const auto load_cell = can::encode_load_cell(can::kDefaultLoadCellId,
                                                 {i * -0.1, false, static_cast<std::uint8_t>(i & 0xF)});
    sink += can::decode_load_cell(load_cell.frame.id, load_cell.frame.data, can::kDefaultLoadCellId,
                                  &load_cell_counter)
                .value.force;
  }
  EXPECT_EQ(stop_counting_allocations(), 0u);
  EXPECT_TRUE(std::isfinite(sink));
}

}  // namespace
