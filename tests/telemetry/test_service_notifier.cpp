// systemd's service protocol against a fake notify socket: READY=1 first, WATCHDOG=1 only while
// the loop's cycle count advances, STATUS= with the state, rate, p99 and overruns. Time is
// scripted; nothing sleeps.
#include "telemetry/service_notifier.hpp"

#include <gtest/gtest.h>
#include <stdlib.h>
#include <unistd.h>

#include <chrono>
#include <string>
#include <vector>

#include "tests/support/notify_socket.hpp"

namespace {

using mrd::control::SupervisorState;
using mrd::telemetry::ServiceNotifier;
using mrd::telemetry::ServiceStatus;
using std::chrono::milliseconds;

// systemd passes the watchdog interval to the main process only (WATCHDOG_PID).
struct WatchdogEnv {
  explicit WatchdogEnv(const char* usec) {
    setenv("WATCHDOG_USEC", usec, 1);
    setenv("WATCHDOG_PID", std::to_string(getpid()).c_str(), 1);
  }
  ~WatchdogEnv() {
    unsetenv("WATCHDOG_USEC");
    unsetenv("WATCHDOG_PID");
  }
};

ServiceStatus status(std::uint64_t cycles, SupervisorState state = SupervisorState::kRun) {
  return {.state = state, .rate = 1000.0, .cycles = cycles, .overruns = 2, .wake_p99_ns = 42'100};
}

std::vector<std::string> only(const std::vector<std::string>& messages, const std::string& prefix) {
  std::vector<std::string> out;
  for (const auto& m : messages) {
    if (m.starts_with(prefix)) out.push_back(m);
  }
  return out;
}

TEST(ServiceNotifier, StatusLineNamesStateRateP99AndOverruns) {
  EXPECT_EQ(format_status(status(120000)), "RUN, 1000 Hz, wake-up p99 42.1 us, overruns 2, cycles 120000");
}

TEST(ServiceNotifier, ALatchedSafeSaysHowToClearIt) {
  ServiceStatus latched = status(5000, SupervisorState::kSafe);
  latched.latched = true;
  EXPECT_EQ(format_status(latched),
            "SAFE latched (clear: SIGUSR2), 1000 Hz, wake-up p99 42.1 us, overruns 2, cycles 5000");
  EXPECT_EQ(format_status(status(5000, SupervisorState::kSafe)),
            "SAFE, 1000 Hz, wake-up p99 42.1 us, overruns 2, cycles 5000");
}

TEST(ServiceNotifier, ReadyFirstThenWatchdogOnlyWhileCyclesAdvance) {
  mrd::test::FakeNotifySocket systemd;
  ASSERT_TRUE(systemd.ok());
  const WatchdogEnv env("1000000");  // WatchdogSec=1
  ServiceNotifier notifier(std::chrono::seconds(10));
  EXPECT_EQ(notifier.watchdog_interval(), std::chrono::seconds(1));

  notifier.ready(status(0, SupervisorState::kInit), milliseconds(0));
  EXPECT_EQ(systemd.messages(),
            std::vector<std::string>{"READY=1\nSTATUS=INIT, 1000 Hz, wake-up p99 42.1 us, overruns 2, cycles 0"});

  notifier.tick(milliseconds(20), status(20));  // before half the interval: nothing
  EXPECT_TRUE(systemd.messages().empty());
  notifier.tick(milliseconds(500), status(500));
  EXPECT_EQ(systemd.messages(), std::vector<std::string>{"WATCHDOG=1"});

  // The loop stops at 600 cycles: one more kick for the cycles run since the last, then none
  // however long the main thread goes on ticking.
  notifier.tick(milliseconds(600), status(600));
  for (int t = 1000; t <= 1400; t += 100) notifier.tick(milliseconds(t), status(600));
  EXPECT_EQ(systemd.messages(), std::vector<std::string>{"WATCHDOG=1"});  // at 1000 ms, for 500..600
  notifier.tick(milliseconds(1500), status(600));
  EXPECT_TRUE(systemd.messages().empty());
  EXPECT_EQ(notifier.watchdog_kicks(), 2u);
  EXPECT_GT(notifier.withheld_kicks(), 0u);

  // It moves again: kicks resume.
  notifier.tick(milliseconds(1600), status(700));
  EXPECT_EQ(systemd.messages(), std::vector<std::string>{"WATCHDOG=1"});
}

// A hung bus thread: the loop still cycles (SAFE, its setpoints going nowhere), so the cycle
// count alone would feed the watchdog; the stall withholds it, and STATUS= says why.
TEST(ServiceNotifier, AStalledBusThreadStarvesTheWatchdogWhileTheLoopCycles) {
  mrd::test::FakeNotifySocket systemd;
  ASSERT_TRUE(systemd.ok());
  const WatchdogEnv env("1000000");
  ServiceNotifier notifier(std::chrono::seconds(10));
  notifier.ready(status(0, SupervisorState::kInit), milliseconds(0));
  systemd.messages();
  ServiceStatus stalled = status(500, SupervisorState::kSafe);
  stalled.bus_stalled = true;
  EXPECT_EQ(format_status(stalled),
            "SAFE, bus thread stalled, 1000 Hz, wake-up p99 42.1 us, overruns 2, cycles 500");
  for (int t = 500; t <= 2000; t += 100) {
    stalled.cycles = static_cast<std::uint64_t>(t);
    notifier.tick(milliseconds(t), stalled);
  }
  EXPECT_TRUE(only(systemd.messages(), "WATCHDOG=").empty());
  EXPECT_EQ(notifier.watchdog_kicks(), 0u);
  EXPECT_GT(notifier.withheld_kicks(), 0u);
  notifier.tick(milliseconds(2100), status(2100));  // the thread moves again
  EXPECT_EQ(systemd.messages(), std::vector<std::string>{"WATCHDOG=1"});
}

TEST(ServiceNotifier, StatusEveryPeriodAndStoppingAtTheEnd) {
  mrd::test::FakeNotifySocket systemd;
  ServiceNotifier notifier(std::chrono::seconds(1));  // no WATCHDOG_USEC: no watchdog
  EXPECT_EQ(notifier.watchdog_interval().count(), 0);
  notifier.ready(status(0, SupervisorState::kInit), milliseconds(0));
  systemd.messages();
  for (int t = 100; t <= 2000; t += 100) notifier.tick(milliseconds(t), status(static_cast<std::uint64_t>(t)));
  const auto sent = systemd.messages();
  EXPECT_TRUE(only(sent, "WATCHDOG=").empty());
  EXPECT_EQ(sent, (std::vector<std::string>{"STATUS=RUN, 1000 Hz, wake-up p99 42.1 us, overruns 2, cycles 1000",
                                            "STATUS=RUN, 1000 Hz, wake-up p99 42.1 us, overruns 2, cycles 2000"}));
  notifier.stopping("stopping on SIGHUP");
  EXPECT_EQ(systemd.messages(), std::vector<std::string>{"STOPPING=1\nSTATUS=stopping on SIGHUP"});
}

TEST(ServiceNotifier, OutsideSystemdEveryCallIsHarmless) {
  unsetenv("NOTIFY_SOCKET");
  ServiceNotifier notifier;
  notifier.ready(status(0), milliseconds(0));
  notifier.tick(milliseconds(5000), status(5000));
  notifier.stopping("done");
  SUCCEED();
}

}  // namespace
