#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

#include "hal/clock.hpp"
#include "hal/displacement_source.hpp"

namespace mrd::firmware {

// Step 2 of a cycle: what the newest LVDT sample is worth.
enum class SampleCheck : std::uint8_t {
  kFresh,       // new, recent, usable and in range: the loop uses its value
  kMissing,     // no sample arrived since the previous period
  kStale,       // a repeated sequence number, or older than the allowed age
  kCorrupted,   // flagged corrupted, invalid or sensor fault by the back end
  kNotFinite,   // NaN or infinite value
  kOutOfRange,  // outside the configured displacement range
};
[[nodiscard]] std::string_view to_string(SampleCheck c);

[[nodiscard]] constexpr bool is_bad_value(SampleCheck c) {
  return c == SampleCheck::kCorrupted || c == SampleCheck::kNotFinite || c == SampleCheck::kOutOfRange;
}

// Freshness and range check with memory: it remembers the last sequence number and holds the
// last good value, which the control law keeps using while samples are missing or bad.
class SampleChecker {
 public:
  SampleChecker(double min, double max, hal::Timestamp max_age)
      : min_(min), max_(max), max_age_(max_age) {}

  SampleCheck check(const std::optional<hal::DisplacementSample>& sample, hal::Timestamp now);

  [[nodiscard]] double held_value() const { return held_; }  // [m], 0 before the first good one
  [[nodiscard]] bool has_value() const { return has_value_; }

 private:
  double min_;
  double max_;
  hal::Timestamp max_age_;
  double held_ = 0.0;
  bool has_value_ = false;
  std::optional<std::uint32_t> last_sequence_;
};

}  // namespace mrd::firmware
