#pragma once

#include <atomic>
#include <cstdint>

namespace mrd {

// A count that exactly one thread writes and any thread reads. The writer does a relaxed load
// and store, not a locked read-modify-write, so the real-time loop never pays for a bus lock;
// a reader sees each value exactly, though two counters are not read at one instant. Bus
// threads that share a counter with another writer use hal::EventCounters (fetch_add) instead.
class SingleWriterCounter {
 public:
  void add(std::uint64_t n = 1) { value_.store(value_.load(std::memory_order_relaxed) + n, std::memory_order_relaxed); }
  // For maxima: keeps the larger of the count and v.
  void raise_to(std::uint64_t v) {
    if (v > value_.load(std::memory_order_relaxed)) value_.store(v, std::memory_order_relaxed);
  }
  [[nodiscard]] std::uint64_t get() const { return value_.load(std::memory_order_relaxed); }

 private:
  std::atomic<std::uint64_t> value_{0};
};

}  // namespace mrd
