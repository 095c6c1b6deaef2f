#pragma once

#include <cstdint>
#include <optional>

#include "hal/sample.hpp"
#include "hal/sample_source.hpp"
#include "hal/spsc_ring.hpp"

namespace mrd::hal {

// One sample channel from a bus thread to the loop: the bus thread numbers and pushes samples,
// the loop takes the newest through SampleSource. An SPSC ring rather than a latest-value
// mailbox, so that a loop which stops draining shows as dropped samples the back end counts.
// Wait-free on both sides, no allocation.
class SampleChannel final : public SampleSource {
 public:
  // Loop side: the newest sample pushed since the previous call; the backlog is dropped.
  [[nodiscard]] std::optional<Sample> latest() override { return ring_.pop_latest(); }

  // Bus thread: the sequence number of the channel's next sample (+1 per sample produced).
  [[nodiscard]] std::uint32_t next_sequence() { return ++sequence_; }
  // Bus thread: hands `sample` to the loop; false when the ring is full and it was dropped.
  [[nodiscard]] bool push(const Sample& sample) { return ring_.try_push(sample); }

 private:
  SpscRing<Sample, 64> ring_;
  std::uint32_t sequence_ = 0;  // bus thread only
};

}  // namespace mrd::hal
