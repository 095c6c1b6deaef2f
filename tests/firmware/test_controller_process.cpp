// mrd-controller as systemd runs it, a process of its own: READY=1 then WATCHDOG=1 on the
// notify socket while it runs, a stop signal (SIGTERM, SIGINT) through the fail-safe cycle to
// exit code 0, SIGHUP a check of the config file that never stops it, and each start's own
// telemetry file. Every wait is for an event, bounded.
#include <gtest/gtest.h>
#include <fcntl.h>
#include <signal.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <string>

#include "tests/hil/child_process.hpp"
#include "tests/support/notify_socket.hpp"
#include "tests/support/test_files.hpp"

namespace {

using mrd::test::ChildProcess;
using std::chrono::milliseconds;
using std::chrono::seconds;

// Under user-mode emulation without binfmt registration (the arm64 tests under qemu) the test
// cannot execute another arm64 program; that is the environment, not the controller.
constexpr const char* kCannotRun = "cannot execute mrd-controller here (a foreign architecture without binfmt?)";

class ControllerProcess : public ::testing::Test {
 protected:
  void SetUp() override {
    // The embedded config's mock back ends, without SCHED_FIFO (a test), telemetry into this test's directory.
    std::ofstream(config()) << "[backends]\nlvdt = \"mock\"\ndriver = \"mock\"\nlines = \"mock\"\n"
                               "[realtime]\npriority = 0\n[safety]\noverrun_limit = 1000000\n"
                               "[telemetry]\npath = \"telemetry.csv\"\ndirectory = \""
                            << dir_.path().string() << "\"\n";
  }
  [[nodiscard]] std::string config() const { return (dir_ / "mrd.toml").string(); }

  mrd::test::TestDirectory dir_{"mrd_controller_process"};
};

// Waits for the first datagram that starts with `prefix`, skipping others.
std::optional<std::string> wait_message(mrd::test::FakeNotifySocket& systemd, const std::string& prefix) {
  const auto deadline = std::chrono::steady_clock::now() + seconds(10);
  while (std::chrono::steady_clock::now() < deadline) {
    const auto m = systemd.next(milliseconds(500));
    if (m && m->starts_with(prefix)) return m;
  }
  return std::nullopt;
}

class StopSignal : public ControllerProcess, public ::testing::WithParamInterface<int> {};

TEST_P(StopSignal, EndsTheRunThroughTheFailSafeCycleWithExitCodeZero) {
  mrd::test::FakeNotifySocket systemd;
  ASSERT_TRUE(systemd.ok());
  setenv("WATCHDOG_USEC", "200000", 1);  // WatchdogSec=0.2 (no WATCHDOG_PID: any pid may take it)
  ChildProcess controller({MRD_CONTROLLER_BINARY, "--config", config()});
  unsetenv("WATCHDOG_USEC");
  if (!controller.started()) GTEST_SKIP() << kCannotRun;

  const auto ready = wait_message(systemd, "READY=1");
  ASSERT_TRUE(ready) << controller.output();
  EXPECT_NE(ready->find("STATUS=INIT, 1000 Hz"), std::string::npos) << *ready;
  EXPECT_TRUE(wait_message(systemd, "WATCHDOG=1")) << "no watchdog kick while the loop runs";

  controller.signal(GetParam());
  const auto code = controller.wait_exit(seconds(10));
  ASSERT_TRUE(code) << controller.output();
  EXPECT_EQ(*code, 0) << controller.output();
  const std::string& out = controller.output();
  const std::string name = GetParam() == SIGINT ? "SIGINT" : "SIGTERM";
  EXPECT_TRUE(std::regex_search(out, std::regex("supervisor: (INIT|RUN|DEGRADED) -> SAFE \\(shutdown\\) at cycle")))
      << out;
  EXPECT_NE(out.find("stopped on " + name + ", fail-safe current written"), std::string::npos) << out;
  EXPECT_NE(out.find("final setpoint 0.000 A (fail-safe 0.000 A), enable off"), std::string::npos) << out;
  const auto stopping = wait_message(systemd, "STOPPING=1");
  ASSERT_TRUE(stopping);
  EXPECT_EQ(*stopping, "STOPPING=1\nSTATUS=stopped on " + name);
}

INSTANTIATE_TEST_SUITE_P(IntAndTerm, StopSignal, ::testing::Values(SIGINT, SIGTERM),
                         [](const ::testing::TestParamInfo<int>& p) { return std::string(p.param == SIGINT ? "SIGINT" : "SIGTERM"); });

// A logrotate `kill -HUP`: a bad file is reported and the run goes on, a changed good one is named
// for the next start; the controller stops only on SIGTERM, with exit code 0.
TEST_F(ControllerProcess, SighupChecksTheConfigFileAndNeverStops) {
  ChildProcess controller({MRD_CONTROLLER_BINARY, "--config", config()});
  if (!controller.started()) GTEST_SKIP() << kCannotRun;
  ASSERT_TRUE(controller.wait_for_line(std::regex("^real-time: "), seconds(10))) << controller.output();
  std::string good;
  {
    std::ifstream in(config());
    good.assign(std::istreambuf_iterator<char>(in), {});
  }
  std::ofstream(config()) << "[safety]\nstale_periods = 0\n";
  controller.signal(SIGHUP);
  ASSERT_TRUE(controller.wait_for_line(std::regex("SIGHUP: .* is not valid \\(4 error\\(s\\)\\), the running config stays"),
                                       seconds(10)))
      << controller.output();
  std::ofstream(config()) << good << "[loop]\nrate = 500.0\n";
  controller.signal(SIGHUP);
  ASSERT_TRUE(controller.wait_for_line(std::regex("SIGHUP: .* is valid and differs from the running config"), seconds(10)))
      << controller.output();
  controller.signal(SIGTERM);
  const auto code = controller.wait_exit(seconds(10));
  ASSERT_TRUE(code) << controller.output();
  EXPECT_EQ(*code, 0) << controller.output();
  EXPECT_NE(controller.output().find("stopped on SIGTERM, fail-safe current written"), std::string::npos)
      << controller.output();
}

// A telemetry FIFO whose reader goes away: SIGPIPE would kill the process before its statistics
// (exit 141); ignored, the writes fail with EPIPE, counted, and the exit code says so.
TEST_F(ControllerProcess, ATelemetryReaderThatGoesAwayIsAnIoFailureNotADeath) {
  const std::string fifo = (dir_ / "reader.csv").string();
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  // O_CLOEXEC: the controller must not hold a read end of its own.
  const int reader = open(fifo.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  ASSERT_GE(reader, 0);
  ChildProcess controller({MRD_CONTROLLER_BINARY, "--config", config(), "--telemetry", fifo, "--duration", "0.3"});
  if (!controller.started()) GTEST_SKIP() << kCannotRun;
  // The writer has opened the FIFO once the controller names its file.
  const bool opened = controller.wait_for_line(std::regex("telemetry " + fifo), seconds(10)).has_value();
  close(reader);
  ASSERT_TRUE(opened) << controller.output();
  const auto code = controller.wait_exit(seconds(10));
  ASSERT_TRUE(code) << controller.output();
  EXPECT_EQ(*code, 3) << controller.output();
  const std::string& out = controller.output();
  EXPECT_NE(out.find("--- mrd-controller statistics ---"), std::string::npos) << out;
  EXPECT_NE(out.find("telemetry: FAILED"), std::string::npos) << out;
  EXPECT_NE(out.find("(last: Broken pipe)"), std::string::npos) << out;
}

TEST_F(ControllerProcess, TwoStartsKeepTwoTelemetryFiles) {
  for (int run = 0; run < 2; ++run) {
    ChildProcess controller({MRD_CONTROLLER_BINARY, "--config", config(), "--duration", "0.1"});
    if (!controller.started()) GTEST_SKIP() << kCannotRun;
    const auto code = controller.wait_exit(seconds(10));
    ASSERT_TRUE(code);
    ASSERT_EQ(*code, 0) << controller.output();
  }
  for (const char* name : {"telemetry-0001.csv", "telemetry-0002.csv"}) {
    std::ifstream in(dir_ / name);
    std::size_t lines = 0;
    for (std::string line; std::getline(in, line);) ++lines;
    EXPECT_EQ(lines, 103u) << name << ": the header, the time origin, 100 cycles and the shutdown cycle";
  }
}

}  // namespace
