#pragma once

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>

namespace mrd::hal {

// Counters a bus thread bumps and any thread reads, keyed by an enum class that ends in kCount.
// Relaxed atomics: each count is exact, but a snapshot is not one instant across all counters.
template <typename Event>
class EventCounters {
 public:
  static constexpr std::size_t kSize = static_cast<std::size_t>(Event::kCount);

  class Snapshot {
   public:
    [[nodiscard]] std::uint64_t operator[](Event e) const {
      return values_[static_cast<std::size_t>(e)];
    }

   private:
    friend class EventCounters;
    std::array<std::uint64_t, kSize> values_{};
  };

  void bump(Event e) { counts_[static_cast<std::size_t>(e)].fetch_add(1, std::memory_order_relaxed); }
  [[nodiscard]] std::uint64_t get(Event e) const {
    return counts_[static_cast<std::size_t>(e)].load(std::memory_order_relaxed);
  }
  [[nodiscard]] Snapshot snapshot() const {
    Snapshot s;
    for (std::size_t i = 0; i < kSize; ++i) s.values_[i] = counts_[i].load(std::memory_order_relaxed);
    return s;
  }

 private:
  std::array<std::atomic<std::uint64_t>, kSize> counts_{};
};

}  // namespace mrd::hal
