#pragma once

#include <cstdint>

#include "hal/clock.hpp"

namespace mrd::hal {

// Bit flags a back end sets on a sample. A sample without kSampleValid must not be used.
enum SampleFlag : std::uint8_t {
  kSampleValid = 1u << 0,
  kSampleCorrupted = 1u << 1,    // checksum, decode or sensor-status failure; value is unusable
  kSampleSequenceGap = 1u << 2,  // one or more frames were lost before this one (value is usable)
  kSampleSensorFault = 1u << 3,  // the sensor itself reports the value unusable
};

// One value a back end received for the loop on one channel (hal/sample_source.hpp): the LVDT's
// displacement [m], the outer controller's force demand [N] or the load cell's force [N], SI
// inside, converted at the bus.
struct Sample {
  double value = 0.0;         // SI
  Timestamp timestamp{};      // when the back end received it, on the loop's clock
  std::uint32_t sequence = 0; // +1 per sample the back end produced; repeats mean a stale sample
  std::uint8_t flags = 0;     // SampleFlag bits

  [[nodiscard]] bool usable() const {
    return (flags & kSampleValid) != 0 && (flags & (kSampleCorrupted | kSampleSensorFault)) == 0;
  }
};

}  // namespace mrd::hal
