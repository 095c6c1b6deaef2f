#include "firmware/bus_watch.hpp"

#include <stdexcept>
#include <string>

namespace mrd::firmware {

BusWatch::BusWatch(std::span<hal::IoThread* const> threads) {
  if (threads.size() > kMaxThreads) {
    throw std::invalid_argument("at most " + std::to_string(kMaxThreads) + " bus I/O threads can be watched");
  }
  for (hal::IoThread* t : threads) threads_[count_++].thread = t;
}

bool BusWatch::stalled(hal::Timestamp now) {
  bool any = false;
  for (std::size_t i = 0; i < count_; ++i) {
    Watched& w = threads_[i];
    const std::uint64_t p = w.thread->progress();
    if (!started_ || p != w.progress) {
      w.progress = p;
      w.since = now;
    } else if (now - w.since > w.thread->max_silence()) {
      any = true;
    }
  }
  started_ = true;
  return any;
}

bool BusWatch::undelivered(const std::optional<hal::SetpointHandover>& handover, bool queued, hal::Timestamp now) {
  if (!handover) return false;
  if (handover->taken != taken_) {
    taken_ = handover->taken;
    waiting_since_.reset();
  }
  // Unlinked, the thread takes nothing and the write says so itself.
  if (!queued) {
    waiting_since_.reset();
    return false;
  }
  if (!waiting_since_) waiting_since_ = now;
  return now - *waiting_since_ > handover->within;
}

}  // namespace mrd::firmware
