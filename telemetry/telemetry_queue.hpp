#pragma once

#include <boost/lockfree/spsc_queue.hpp>
#include <cstddef>
#include <cstdint>

#include "common/single_writer_counter.hpp"
#include "telemetry/telemetry_record.hpp"

namespace mrd::telemetry {

// The lock-free SPSC ring between the loop (producer) and the telemetry writer (consumer).
// Its capacity comes from the config, so the storage is allocated once, at construction; push
// and pop never allocate. A full ring drops the new record and counts it, so
// written + dropped always equals offered.
class TelemetryQueue {
 public:
  explicit TelemetryQueue(std::size_t capacity) : queue_(capacity) {}

  // Loop side.
  void offer(const TelemetryRecord& r) {
    offered_.add();
    if (!queue_.push(r)) dropped_.add();
  }

  // Writer side: hands every queued record to `sink`, returns how many.
  template <typename Sink>
  std::size_t drain(Sink&& sink) {
    return queue_.consume_all(sink);
  }

  [[nodiscard]] std::uint64_t offered() const { return offered_.get(); }
  [[nodiscard]] std::uint64_t dropped() const { return dropped_.get(); }

 private:
  boost::lockfree::spsc_queue<TelemetryRecord> queue_;
  SingleWriterCounter offered_;  // the loop is the one writer of both
  SingleWriterCounter dropped_;
};

}  // namespace mrd::telemetry
