// The loop's velocity when the LVDT comes over a bus polled on its own clock: every sample is
// tracked at its own timestamp, so the beat between the poll and the loop does not reach the
// observer (docs/HIL.md, "In the test suite").
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <optional>

#include "firmware/control_loop.hpp"
#include "hal/mock/mock_hal.hpp"

namespace {

using namespace std::chrono_literals;
using mrd::hal::Timestamp;

constexpr double kSpeed = 0.1;  // [m/s]

double ramp(Timestamp t) { return -0.02 + kSpeed * std::chrono::duration<double>(t).count(); }

// A bus thread that polls every 0.51 ms: the loop (1 ms) finds the newest poll, its age drifting
// from 0 to 0.51 ms and back every 50 periods, the interval between them now and then 0.51 or
// 1.53 ms instead of 1.02.
class PolledLvdt final : public mrd::hal::SampleSource {
 public:
  explicit PolledLvdt(const mrd::hal::Clock& clock) : clock_(clock) {}
  std::optional<mrd::hal::Sample> latest() override {
    const auto polls = clock_.now() / kPoll;
    const Timestamp at = polls * kPoll;
    return mrd::hal::Sample{ramp(at), at, static_cast<std::uint32_t>(polls), mrd::hal::kSampleValid};
  }
  static constexpr Timestamp kPoll = 510us;

 private:
  const mrd::hal::Clock& clock_;
};

TEST(BusSampleTiming, VelocityHoldsSteadyWhileThePollBeatsWithTheLoop) {
  mrd::hal::mock::MockHal hal;
  PolledLvdt lvdt(hal.clock);
  mrd::firmware::ControlLoop loop(mrd::control::ControlLawConfig{}, mrd::control::SupervisorConfig{},
                                  {lvdt, hal.driver, hal.lines}, nullptr);
  double lo = 1.0, hi = -1.0;
  for (int cycle = 0; cycle < 300; ++cycle) {  // 0.3 s: -20 to +10 mm
    const Timestamp now = cycle * 1ms;
    hal.clock.set(now);
    const auto& record = loop.step(now);
    if (cycle >= 200) {
      lo = std::min(lo, record.velocity);
      hi = std::max(hi, record.velocity);
    }
  }
  // A tracker on the loop's period sees 0.51 to 1.53 ms of motion per period: +-2.4 %.
  EXPECT_NEAR(lo, kSpeed, 1e-3 * kSpeed);
  EXPECT_NEAR(hi, kSpeed, 1e-3 * kSpeed);
}

}  // namespace
