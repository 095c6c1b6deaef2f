#pragma once

#include <atomic>
#include <cstdint>

#include "runtime/latency_histogram.hpp"

namespace mrd::runtime {

// What the real-time runner measures. Written by the loop thread, read by the printing thread.
struct LoopStatistics {
  LatencyHistogram wake_latency;  // actual wake-up - release time [ns]
  LatencyHistogram execution;     // cycle end - wake-up [ns]
  std::atomic<std::uint64_t> cycles{0};
  std::atomic<std::uint64_t> overruns{0};  // sum of ceil(elapsed / period) - 1 over the cycles

  void add_cycle(std::uint64_t missed) {
    cycles.store(cycles.load(std::memory_order_relaxed) + 1, std::memory_order_relaxed);
    if (missed > 0) {
      overruns.store(overruns.load(std::memory_order_relaxed) + missed, std::memory_order_relaxed);
    }
  }
};

}  // namespace mrd::runtime
