#pragma once

#include <span>
#include <string>
#include <vector>

#include "common/validation_report.hpp"
#include "hal/io_thread.hpp"
#include "runtime/cpu_dma_latency.hpp"

namespace mrd::runtime {

struct RealtimeConfig {
  int priority = 80;        // SCHED_FIFO priority 1..99 for the loop thread; 0: stay SCHED_OTHER
  int cpu = -1;             // pin the loop thread to this CPU; -1: no affinity
  bool lock_memory = true;  // mlockall(MCL_CURRENT | MCL_FUTURE)
  // SCHED_FIFO priority of the bus I/O threads, below the loop's so they never preempt it but
  // above everything SCHED_OTHER, so a loaded host cannot starve the samples past
  // safety.stale_periods. 0, or a loop under SCHED_OTHER (priority 0): SCHED_OTHER.
  int io_priority = 60;
  // The power-management QoS limit held on /dev/cpu_dma_latency for the whole run [us]: 0 keeps
  // the CPUs out of every idle state with an exit latency, as cyclictest does; -1 leaves it.
  int cpu_dma_latency = 0;

  [[nodiscard]] ValidationReport validate() const;  // field paths relative to [realtime]
};

// What the set-up achieved. Each step that could not be done leaves a warning saying what was
// asked, why it failed and what runs instead; the controller runs on regardless.
struct RtSetupResult {
  bool memory_locked = false;
  bool fifo = false;
  bool pinned = false;
  std::size_t io_fifo = 0;  // bus I/O threads switched to SCHED_FIFO io_priority
  CpuDmaLatency dma_latency;  // held until this result is destroyed
  std::vector<std::string> warnings;
};

// Process-wide, before the threads start: mlockall and a pre-faulted heap.
void lock_memory(const RealtimeConfig& config, RtSetupResult& result);
// Process-wide, for the run: the CPU wake-up latency limit (realtime.cpu_dma_latency).
void hold_cpu_dma_latency(const RealtimeConfig& config, RtSetupResult& result,
                          const std::string& device = CpuDmaLatency::kDevice);
// On the loop thread itself: SCHED_FIFO, affinity, and a pre-faulted stack.
void make_current_thread_realtime(const RealtimeConfig& config, RtSetupResult& result);
// The bus I/O threads, once started: SCHED_FIFO io_priority when the loop has a priority.
void make_io_threads_realtime(const RealtimeConfig& config, std::span<hal::IoThread* const> threads,
                              RtSetupResult& result);

}  // namespace mrd::runtime
