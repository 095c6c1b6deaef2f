#pragma once

#include <atomic>
#include <boost/lockfree/spsc_queue.hpp>
#include <cstddef>
#include <cstdint>

#include "runtime/telemetry_record.hpp"

namespace mrd::runtime {

// The lock-free SPSC ring between the loop (producer) and the telemetry writer (consumer).
// Its capacity comes from the config, so the storage is allocated once, at construction; push
// and pop never allocate. A full ring drops the new record and counts it, so
// written + dropped always equals offered.
class TelemetryQueue {
 public:
  explicit TelemetryQueue(std::size_t capacity) : queue_(capacity) {}

  // Loop side.
  void offer(const TelemetryRecord& r) {
    bump(offered_);
    if (!queue_.push(r)) bump(dropped_);
  }

  // Writer side: hands every queued record to `sink`, returns how many.
  template <typename Sink>
  std::size_t drain(Sink&& sink) {
    return queue_.consume_all(sink);
  }

  [[nodiscard]] std::uint64_t offered() const { return offered_.load(std::memory_order_relaxed); }
  [[nodiscard]] std::uint64_t dropped() const { return dropped_.load(std::memory_order_relaxed); }

 private:
  // Single writer: a relaxed load and store, no locked read-modify-write on the hot path.
  static void bump(std::atomic<std::uint64_t>& c) {
    c.store(c.load(std::memory_order_relaxed) + 1, std::memory_order_relaxed);
  }

  boost::lockfree::spsc_queue<TelemetryRecord> queue_;
  std::atomic<std::uint64_t> offered_{0};
  std::atomic<std::uint64_t> dropped_{0};
};

}  // namespace mrd::runtime
