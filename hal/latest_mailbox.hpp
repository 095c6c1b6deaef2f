#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <optional>
#include <type_traits>

namespace mrd::hal {

// Single-writer/single-reader "newest value wins" mailbox (a triple buffer). Unlike a ring it
// can never be full, so the newest value is never the one dropped: this is how the loop hands
// setpoints to a bus thread. Wait-free on both sides, no allocation.
template <typename T>
class LatestMailbox {
  static_assert(std::is_trivially_copyable_v<T>, "values cross threads by copy");

 public:
  // Writer side: publishes `value`, replacing any value the reader has not taken yet.
  void publish(const T& value) {
    slots_[back_] = value;
    const std::uint8_t old = middle_.exchange(static_cast<std::uint8_t>(back_ | kFresh),
                                              std::memory_order_acq_rel);
    back_ = static_cast<std::uint8_t>(old & kIndexMask);
  }

  // Reader side: the newest value published since the previous take, if any.
  std::optional<T> take() {
    if ((middle_.load(std::memory_order_relaxed) & kFresh) == 0) return std::nullopt;
    const std::uint8_t old = middle_.exchange(front_, std::memory_order_acq_rel);
    front_ = static_cast<std::uint8_t>(old & kIndexMask);
    return slots_[front_];
  }

 private:
  static constexpr std::uint8_t kFresh = 0x4;
  static constexpr std::uint8_t kIndexMask = 0x3;

  std::array<T, 3> slots_{};
  alignas(64) std::atomic<std::uint8_t> middle_{1};  // slot index, plus kFresh when unread
  alignas(64) std::uint8_t back_ = 0;                // owned by the writer
  alignas(64) std::uint8_t front_ = 2;               // owned by the reader
};

}  // namespace mrd::hal
