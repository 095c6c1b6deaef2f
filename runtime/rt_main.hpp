#pragma once

#include <signal.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <span>
#include <string>
#include <thread>

#include "hal/io_thread.hpp"
#include "runtime/loop_statistics.hpp"
#include "runtime/rt_runner.hpp"
#include "runtime/rt_setup.hpp"

namespace mrd::runtime {

// Flags the process's signal handlers set (async-signal-safe: lock-free atomics only).
struct ProcessSignals {
  std::atomic<bool> stop{false};         // SIGTERM, SIGINT: end the run through the final cycle
  std::atomic<int> stop_signal{0};       // which of them came first (0: none yet)
  std::atomic<bool> reload{false};       // SIGHUP: the hooks' reload(), or a stop where it declines
  std::atomic<bool> print_stats{false};  // SIGUSR1
  std::atomic<bool> clear_latch{false};  // SIGUSR2: an operator clears a latched SAFE
};

// "SIGHUP" for a stop signal's number.
[[nodiscard]] const char* signal_name(int signal);
// CLOCK_MONOTONIC now: the time the hooks' `tick` gets.
[[nodiscard]] hal::Timestamp monotonic_now();

// Installs the handlers for `signals` (and ignores SIGPIPE) and blocks those signals on the calling thread, so the
// threads it starts afterwards inherit a mask without them and only the main thread takes
// them. Returns the blocked set, for run_real_time to unblock once the threads run.
sigset_t install_process_signals(ProcessSignals& signals);

struct RealTimeRun {
  const RealtimeConfig& realtime;
  std::chrono::nanoseconds period;
  std::uint64_t max_cycles = 0;                 // 0: until a stop signal
  std::span<hal::IoThread* const> io_threads;   // already started
  std::chrono::milliseconds poll_period{20};    // how often the main thread looks at the flags
};

// What a real-time program does besides its cycle, as methods it overrides (each a no-op
// otherwise). All but finish() run on the calling (non-real-time) thread.
class RealTimeHooks {
 public:
  virtual ~RealTimeHooks() = default;

  virtual void finish(hal::Timestamp /*next_release*/) {}  // on the loop thread, after the stop
  virtual void ready(const RtSetupResult& /*rt*/) {}        // once the loop thread is set up
  virtual void print_stats() {}                             // on SIGUSR1
  virtual void clear_latch() {}                             // on SIGUSR2
  virtual bool reload() { return false; }                   // on SIGHUP; false: SIGHUP stops the run
  virtual void tick(hal::Timestamp /*now*/) {}              // every poll period, while the loop runs
};

// The one skeleton of mrd-controller and mrd-plant: the bus threads at their priority, the
// loop on its own thread (SCHED_FIFO, pinned, pre-faulted stack) releasing `cycle` on a fixed
// period, the calling thread polling the signal flags; on stop, finish() runs one last time on
// the loop thread (the controller drives the fail-safe current there) before it ends.
// lock_memory() is the caller's, before it allocates the run's buffers; the CPU wake-up latency
// limit is held here, in `rt`, until the caller destroys it.
template <typename Cycle>
void run_real_time(const RealTimeRun& run, ProcessSignals& signals, const sigset_t* unblock,
                   RtSetupResult& rt, LoopStatistics& stats, Cycle&& cycle, RealTimeHooks& hooks) {
  hold_cpu_dma_latency(run.realtime, rt);
  make_io_threads_realtime(run.realtime, run.io_threads, rt);
  std::atomic<bool> stop{false};
  std::atomic<bool> setup_done{false};
  std::atomic<bool> finished{false};
  std::thread loop_thread([&] {
    make_current_thread_realtime(run.realtime, rt);
    setup_done.store(true);
    RealTimeRunner runner(run.period);
    const hal::Timestamp next = runner.run(cycle, stop, run.max_cycles, stats);
    hooks.finish(next);
    finished.store(true);
  });
  if (unblock != nullptr) pthread_sigmask(SIG_UNBLOCK, unblock, nullptr);
  while (!setup_done.load()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  hooks.ready(rt);
  while (!finished.load()) {
    std::this_thread::sleep_for(run.poll_period);
    if (signals.reload.exchange(false) && !hooks.reload()) {
      int none = 0;
      signals.stop_signal.compare_exchange_strong(none, SIGHUP);
      signals.stop.store(true);
    }
    if (signals.stop.load()) stop.store(true);
    if (signals.print_stats.exchange(false)) hooks.print_stats();
    if (signals.clear_latch.exchange(false)) hooks.clear_latch();
    hooks.tick(monotonic_now());
  }
  loop_thread.join();
}

// "real-time: memory locked, scheduling SCHED_FIFO 80, cpu any, bus threads SCHED_FIFO 60".
[[nodiscard]] std::string describe_rt_setup(const RealtimeConfig& config, const RtSetupResult& rt,
                                            std::size_t io_threads);

}  // namespace mrd::runtime
