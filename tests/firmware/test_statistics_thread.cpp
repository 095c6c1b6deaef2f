// The SIGUSR1 path while the loop runs: the main thread prints the statistics and the
// supervisor's state, and logs transitions, as the real-time thread changes them. Built and run
// under ThreadSanitizer too (`cmake --workflow --preset tsan-threads`): a read of the loop's
// state that is not an atomic or the feed's snapshot is a data race it reports, and its report
// fails the test (TSAN_OPTIONS halt_on_error).
#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <string>
#include <thread>

#include "config/config_loader.hpp"
#include "firmware/controller.hpp"
#include "runtime/rt_main.hpp"
#include "tests/support/test_files.hpp"

namespace {

using mrd::test::read_and_close;

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(StatisticsThread, Sigusr1WhileTheSupervisorChangesStateReadsOnlyWhatTheLoopPublishes) {
  auto config = mrd::config::load_default_config().config;
  config.realtime.priority = 0;           // a test: no SCHED_FIFO
  config.realtime.cpu_dma_latency = -1;   // and no power-management request
  config.rate = 2000.0;
  config.safety.recovery_periods = 20;    // INIT -> RUN early, then the state changes below
  config.safety.degraded_clear_periods = 1;
  config.safety.overrun_limit = 1000000;  // overruns (TSan is slow) only flip RUN <-> DEGRADED
  mrd::runtime::ProcessSignals signals;
  const sigset_t mask = mrd::runtime::install_process_signals(signals);

  // SIGUSR1 to the process, as an operator's kill -USR1 would, until the run ends.
  std::atomic<bool> done{false};
  std::thread operator_thread([&] {
    while (!done.load()) {
      kill(getpid(), SIGUSR1);
      std::this_thread::sleep_for(std::chrono::milliseconds(15));  // pacing the requests, not waiting
    }
  });
  std::FILE* out = std::tmpfile();
  std::FILE* log = std::tmpfile();
  mrd::firmware::RunOptions options;
  options.duration_s = 0.4;
  options.log = log;
  const int code = mrd::firmware::run_controller(config, options, signals, out, &mask);
  done.store(true);
  operator_thread.join();

  EXPECT_EQ(code, 0);
  const std::string text = read_and_close(out);
  const std::string logged = read_and_close(log);
  EXPECT_GE(count(text, "--- mrd-controller statistics ---"), 3u) << text;  // at least two while running
  // Whether INIT -> RUN came in time depends on the machine's load (an overrun restarts the
  // count of good periods); the shutdown's transition always comes.
  EXPECT_NE(logged.find("-> SAFE (shutdown) at cycle"), std::string::npos) << logged;
}

}  // namespace
