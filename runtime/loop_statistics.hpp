#pragma once

#include <cstdint>

#include "common/single_writer_counter.hpp"

#include "runtime/latency_histogram.hpp"

namespace mrd::runtime {

// What the real-time runner measures. Written by the loop thread, read by the printing thread.
struct LoopStatistics {
  LatencyHistogram wake_latency;  // actual wake-up - release time [ns]
  LatencyHistogram execution;     // cycle end - wake-up [ns]
  SingleWriterCounter cycles;
  SingleWriterCounter overruns;  // sum of ceil(elapsed / period) - 1 over the cycles

  void add_cycle(std::uint64_t missed) {
    cycles.add();
    if (missed > 0) overruns.add(missed);
  }
};

}  // namespace mrd::runtime
