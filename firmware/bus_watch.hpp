#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

#include "hal/clock.hpp"
#include "hal/current_driver.hpp"
#include "hal/io_thread.hpp"

namespace mrd::firmware {

// Whether the bus I/O threads are alive and take the setpoints the loop queues for them, judged
// on the loop's release times from their lock-free counters. No allocation, no locks.
class BusWatch {
 public:
  static constexpr std::size_t kMaxThreads = 4;
  // std::invalid_argument with more than kMaxThreads threads (start-up only).
  explicit BusWatch(std::span<hal::IoThread* const> threads);

  // True while a thread's progress counter has stood still longer than its max_silence().
  [[nodiscard]] bool stalled(hal::Timestamp now);
  // After this period's write (`queued`: it reported kOk): true when queued setpoints have
  // waited longer than the handover allows without the bus thread taking one.
  [[nodiscard]] bool undelivered(const std::optional<hal::SetpointHandover>& handover, bool queued,
                                 hal::Timestamp now);

 private:
  struct Watched {
    const hal::IoThread* thread = nullptr;
    std::uint64_t progress = 0;
    hal::Timestamp since{};  // when `progress` was first seen
  };
  std::array<Watched, kMaxThreads> threads_{};
  std::size_t count_ = 0;
  bool started_ = false;
  std::optional<std::uint64_t> taken_;           // the handover's count as last seen
  std::optional<hal::Timestamp> waiting_since_;  // the first queued write since the last take
};

}  // namespace mrd::firmware
