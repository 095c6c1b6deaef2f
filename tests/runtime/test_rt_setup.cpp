// The bus I/O threads' scheduling: SCHED_FIFO at realtime.io_priority when the loop has a
// priority, or a warning saying why not; nothing when the loop stays SCHED_OTHER.
#include "runtime/rt_setup.hpp"

#include <gtest/gtest.h>
#include <pthread.h>
#include <sched.h>

#include <atomic>
#include <chrono>

#include "hal/io_thread.hpp"

namespace {

using mrd::runtime::RealtimeConfig;
using mrd::runtime::RtSetupResult;

// An I/O thread that idles until stopped, then records the scheduling it ended with.
struct IdleThread {
  mrd::hal::IoThread thread;
  std::atomic<int> policy{-1};
  std::atomic<int> priority{-1};

  IdleThread() {
    thread.start("mrd-test-io", [this] {
      while (thread.wait_for(std::chrono::hours(1))) {
      }
      int p = 0;
      sched_param param{};
      pthread_getschedparam(pthread_self(), &p, &param);
      policy.store(p);
      priority.store(param.sched_priority);
    });
  }
};

TEST(RtSetup, BusThreadsGoFifoBelowTheLoopOrSayWhyNot) {
  IdleThread idle;
  RealtimeConfig config;  // loop 80, bus threads 60
  RtSetupResult result;
  mrd::hal::IoThread* threads[] = {&idle.thread};
  mrd::runtime::make_io_threads_realtime(config, threads, result);
  idle.thread.stop();
  if (result.io_fifo == 1) {
    EXPECT_TRUE(result.warnings.empty());
    EXPECT_EQ(idle.policy.load(), SCHED_FIFO);
    EXPECT_EQ(idle.priority.load(), 60);
  } else {  // not permitted here: it stays SCHED_OTHER and says so
    EXPECT_EQ(result.io_fifo, 0u);
    ASSERT_EQ(result.warnings.size(), 1u);
    EXPECT_NE(result.warnings[0].find("cannot switch the bus thread mrd-test-io to SCHED_FIFO priority 60"),
              std::string::npos)
        << result.warnings[0];
    EXPECT_EQ(idle.policy.load(), SCHED_OTHER);
  }
}

TEST(RtSetup, LoopUnderSchedOtherLeavesTheBusThreadsThere) {
  IdleThread idle;
  RealtimeConfig config;
  config.priority = 0;
  RtSetupResult result;
  mrd::hal::IoThread* threads[] = {&idle.thread};
  mrd::runtime::make_io_threads_realtime(config, threads, result);
  idle.thread.stop();
  EXPECT_EQ(result.io_fifo, 0u);
  EXPECT_TRUE(result.warnings.empty());
  EXPECT_EQ(idle.policy.load(), SCHED_OTHER);
}

}  // namespace
