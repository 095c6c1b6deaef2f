// mrd-controller's run on the embedded default config (the mock HAL, its LVDT on the [simulation] sine), in process and
// briefly. Real time on a shared machine: only what does not depend on timing is asserted.
#include "firmware/controller.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <regex>
#include <string>

#include "common/cli/exit_code.hpp"
#include "config/config_loader.hpp"
#include "tests/support/notify_socket.hpp"
#include "tests/support/test_files.hpp"

namespace {

using mrd::test::read_and_close;

// Runs the controller and returns what it printed; its log (transitions) into `log`.
std::string run(const mrd::config::ControllerConfig& config, double seconds,
                bool stop_at_once = false, std::string* log = nullptr, int exit_code = 0) {
  std::FILE* out = std::tmpfile();
  std::FILE* log_file = std::tmpfile();
  mrd::runtime::ProcessSignals signals;
  signals.stop.store(stop_at_once);  // as if SIGTERM arrived before the first cycle
  mrd::firmware::RunOptions options;
  options.duration_s = seconds;
  options.log = log_file;
  EXPECT_EQ(mrd::firmware::run_controller(config, options, signals, out), exit_code);
  const std::string logged = read_and_close(log_file);
  if (log != nullptr) *log = logged;
  return read_and_close(out);
}

TEST(ControllerRun, DefaultConfigRunsOnTheMockHalAndStopsInSafeWithTelemetryAccounted) {
  auto config = mrd::config::load_default_config().config;
  const auto csv = std::filesystem::temp_directory_path() / "mrd_controller_run.csv";
  config.telemetry.path = csv.string();
  config.telemetry.per_run = false;
  config.realtime.priority = 0;  // a unit test does not ask for SCHED_FIFO
  config.safety.recovery_periods = 50;
  // SCHED_OTHER on a shared machine overruns now and then; this test is not about that.
  config.safety.overrun_limit = 1000000;
  const std::string text = run(config, 0.5);

  EXPECT_NE(text.find("mock LVDT on the simulation sine"), std::string::npos) << text;
  // Whether and when INIT -> RUN happens depends on the machine's load (overruns reset the
  // count of good periods); the supervisor's timing is tested deterministically elsewhere.
  EXPECT_NE(text.find("-> SAFE (shutdown): 1"), std::string::npos) << text;
  EXPECT_NE(text.find("final setpoint 0.000 A (fail-safe 0.000 A), enable off"), std::string::npos) << text;
  EXPECT_NE(text.find("cycles 500,"), std::string::npos) << text;
  EXPECT_NE(text.find("wake-up latency [us]"), std::string::npos) << text;

  std::smatch m;
  ASSERT_TRUE(std::regex_search(text, m, std::regex(R"(telemetry: (\d+) records offered, (\d+) written, (\d+) dropped)")))
      << text;
  const auto offered = std::stoull(m[1]);
  EXPECT_EQ(offered, 501u);  // 500 cycles and the shutdown cycle
  EXPECT_EQ(std::stoull(m[2]) + std::stoull(m[3]), offered);
  std::filesystem::remove(csv);
}

// A disk that takes nothing: the run goes on, the journal says so while it runs, the last line
// says the file is incomplete and the exit code is the I/O one.
TEST(ControllerRun, TelemetryToAFullDiskIsReportedAndTheExitCodeSaysSo) {
  auto config = mrd::config::load_default_config().config;
  config.telemetry.directory = "/dev";
  config.telemetry.path = "full";
  config.telemetry.per_run = false;
  config.realtime.priority = 0;
  config.safety.overrun_limit = 1000000;
  std::string log;
  const std::string text = run(config, 0.1, false, &log, mrd::cli::kIo);
  EXPECT_NE(text.find("telemetry: 101 records offered, 0 written, 0 dropped, 0 over the size cap, 101 lost to I/O -> /dev/full"),
            std::string::npos)
      << text;
  EXPECT_TRUE(std::regex_search(
      text, std::regex(R"(telemetry: FAILED, \d+ write\(s\) failed \(last: No space left on device\); /dev/full is incomplete)")))
      << text;
  EXPECT_TRUE(std::regex_search(log, std::regex(R"(mrd-controller: telemetry: \d+ lost to I/O \(No space left on device\) so far)")))
      << log;
  EXPECT_NE(text.find("enable off"), std::string::npos) << text;  // the statistics all the same
}

TEST(ControllerRun, StopSignalFlagEndsTheRunWithTheFailSafeCycle) {
  auto config = mrd::config::load_default_config().config;
  config.realtime.priority = 0;
  config.safety.overrun_limit = 1000000;  // as above: SAFE only by the stop
  std::string log;
  const std::string text = run(config, 0.0, true, &log);  // no duration: runs until the flag
  EXPECT_NE(text.find("INIT -> SAFE (shutdown): 1"), std::string::npos) << text;
  EXPECT_NE(text.find("enable off"), std::string::npos) << text;
  // The transition reached the log as a line of its own, then the stop.
  EXPECT_NE(log.find("mrd-controller: supervisor: INIT -> SAFE (shutdown) at cycle "), std::string::npos) << log;
  EXPECT_NE(log.find("mrd-controller: stopped on request, fail-safe current written"),
            std::string::npos)
      << log;
}

// SIGHUP (its flag, as the handler sets it) never stops the run: the main thread answers it in
// the log and the run goes on to its duration.
TEST(ControllerRun, AReloadRequestNeverStopsTheRun) {
  auto config = mrd::config::load_default_config().config;
  config.realtime.priority = 0;
  config.safety.overrun_limit = 1000000;
  std::FILE* out = std::tmpfile();
  std::FILE* log_file = std::tmpfile();
  mrd::runtime::ProcessSignals signals;
  signals.reload.store(true);
  mrd::firmware::RunOptions options;
  options.duration_s = 0.05;
  options.log = log_file;
  EXPECT_EQ(mrd::firmware::run_controller(config, options, signals, out), 0);
  const std::string log = read_and_close(log_file);
  const std::string text = read_and_close(out);
  EXPECT_FALSE(signals.reload.load()) << "taken by the main thread";
  EXPECT_NE(log.find("mrd-controller: SIGHUP: the embedded config runs (no --config): nothing to re-read"),
            std::string::npos)
      << log;
  EXPECT_NE(log.find("stopped after the run's duration"), std::string::npos) << log;
  EXPECT_NE(text.find("cycles 50,"), std::string::npos) << text;
}

// Under systemd: READY=1 before anything else, STATUS= lines with the state and the rate,
// STOPPING=1 last (the watchdog's timing is ServiceNotifier's test, on scripted time).
TEST(ControllerRun, TellsSystemdReadyStatusAndStopping) {
  mrd::test::FakeNotifySocket systemd;
  ASSERT_TRUE(systemd.ok());
  auto config = mrd::config::load_default_config().config;
  config.realtime.priority = 0;
  config.safety.overrun_limit = 1000000;
  run(config, 0.05);
  const auto sent = systemd.messages();
  ASSERT_GE(sent.size(), 2u);
  EXPECT_TRUE(sent.front().starts_with("READY=1\nSTATUS=INIT, 1000 Hz, wake-up p99 ")) << sent.front();
  EXPECT_EQ(sent.back(), "STOPPING=1\nSTATUS=stopped after the run's duration");
  for (std::size_t i = 1; i + 1 < sent.size(); ++i) {
    EXPECT_TRUE(sent[i].starts_with("STATUS=") || sent[i] == "WATCHDOG=1") << sent[i];
  }
}

}  // namespace
