// mrd-controller's run on the embedded default config (the mock HAL, its LVDT on the [simulation] sine), in process and
// briefly. Real time on a shared machine: only what does not depend on timing is asserted.
#include "firmware/controller.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <regex>
#include <string>

#include "config/config_loader.hpp"

namespace {

// Runs the controller and returns what it printed.
std::string run(const mrd::config::ControllerConfig& config, double seconds,
                bool stop_at_once = false) {
  std::FILE* out = std::tmpfile();
  mrd::runtime::ProcessSignals signals;
  signals.stop.store(stop_at_once);  // as if SIGTERM arrived before the first cycle
  mrd::firmware::RunOptions options;
  options.duration_s = seconds;
  EXPECT_EQ(mrd::firmware::run_controller(config, options, signals, out), 0);
  std::rewind(out);
  std::string text;
  char buf[4096];
  while (std::fgets(buf, sizeof buf, out) != nullptr) text += buf;
  std::fclose(out);
  return text;
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

TEST(ControllerRun, StopSignalFlagEndsTheRunWithTheFailSafeCycle) {
  auto config = mrd::config::load_default_config().config;
  config.realtime.priority = 0;
  config.safety.overrun_limit = 1000000;  // as above: SAFE only by the stop
  const std::string text = run(config, 0.0, true);  // no duration: runs until the flag
  EXPECT_NE(text.find("INIT -> SAFE (shutdown): 1"), std::string::npos) << text;
  EXPECT_NE(text.find("enable off"), std::string::npos) << text;
}

}  // namespace
