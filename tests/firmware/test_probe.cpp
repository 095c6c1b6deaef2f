// mrd-controller --probe's judgement on the mock HAL, time scripted: the driver is held off and
// never commanded, healthy buses pass, and each fault commissioning should catch is named.
#include "firmware/probe.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <string>

#include "hal/mock/mock_hal.hpp"

namespace {

using mrd::firmware::Probe;
using mrd::firmware::ProbeExpectations;
using mrd::hal::mock::FaultKind;
using mrd::hal::mock::FaultScript;
using mrd::hal::mock::MockHal;
using std::chrono::milliseconds;

constexpr auto kForever = std::chrono::hours(1);

// 100 polls, 10 ms apart, with the LVDT at `displacement`.
std::string probe(MockHal& hal, double displacement = 0.012, const ProbeExpectations& expect = {}) {
  Probe p({hal.lvdt, hal.driver, hal.lines}, expect);
  p.disable_driver();
  for (int i = 1; i <= 100; ++i) {
    hal.clock.set(milliseconds(10 * i));
    hal.lvdt.set_value(displacement);
    p.poll(hal.clock.now());
  }
  EXPECT_EQ(hal.driver.writes(), 0u) << "the probe must never command the coil";
  EXPECT_FALSE(hal.lines.enabled());
  return p.problems();
}

TEST(Probe, HealthyBusesPassWithTheDriverHeldOff) {
  MockHal hal;
  hal.lines.set_enable(true);  // whatever it was, the probe drives it low
  EXPECT_EQ(probe(hal), "");
}

TEST(Probe, ASilentLvdtIsNamed) {
  MockHal hal(FaultScript{{FaultKind::kSensorTimeout, {}, kForever}});
  EXPECT_EQ(probe(hal), "lvdt: no sample in 100 polls (check the bus, the address and the wiring)\n");
}

TEST(Probe, CorruptedSamplesAreCountedAndNamed) {
  MockHal hal(FaultScript{{FaultKind::kCorruptedFrame, {}, kForever}});
  EXPECT_NE(probe(hal).find("lvdt: 0 usable samples of 100 (100 flagged invalid/corrupted/sensor fault, 0 not finite)"),
            std::string::npos);
}

TEST(Probe, AReadingOutsideTheSafetyRangePointsAtTheScale) {
  MockHal hal;
  const std::string problems = probe(hal, 12.0);  // 12 m: a scale of 1e-3 where 1e-6 was meant
  EXPECT_NE(problems.find("lvdt: reads 12000.000..12000.000 mm, outside safety.displacement_min..max "
                          "(-50.000..50.000 mm): check the scale"),
            std::string::npos)
      << problems;
}

TEST(Probe, CurrentWithTheEnableLowIsWrong) {
  MockHal hal(FaultScript{{FaultKind::kCurrentBias, {}, kForever, 0.4}});
  const std::string problems = probe(hal);
  EXPECT_NE(problems.find("current: the driver reports 0.400..0.400 A with its enable low"), std::string::npos)
      << problems;
}

TEST(Probe, FaultLineSetOrUnreadableIsNamed) {
  MockHal set(FaultScript{{FaultKind::kDriverFault, milliseconds(500), kForever}});
  EXPECT_EQ(probe(set), "fault line: set in 51 of 100 polls (the supervisor would go SAFE)\n");
  MockHal unreadable(FaultScript{{FaultKind::kFaultLineUnreadable, {}, kForever}});
  EXPECT_EQ(probe(unreadable), "fault line: unreadable in 100 of 100 polls\n");
}

TEST(Probe, ReadingsPrintDecoded) {
  MockHal hal;
  Probe p({hal.lvdt, hal.driver, hal.lines}, {});
  hal.clock.set(milliseconds(10));
  hal.lvdt.set_value(-0.0125);
  EXPECT_EQ(Probe::format(p.poll(hal.clock.now()), {}),
            "  t  0.010 s  lvdt  -12.5000 mm (seq 1)  current  0.0000 A  fault clear\n");
  EXPECT_NE(p.summary().find("lvdt: 1 samples in 1 polls, 1 usable, range -12.500..-12.500 mm"), std::string::npos)
      << p.summary();
}

}  // namespace
