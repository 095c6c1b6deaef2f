#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

#include "hal/clock.hpp"
#include "hal/sample.hpp"
#include "model/observer.hpp"

namespace mrd::control {

// Step 2 of a cycle: what the newest LVDT sample is worth.
enum class SampleCheck : std::uint8_t {
  kFresh,       // new, recent, usable and in range: the loop uses its value
  kMissing,     // no sample arrived since the previous period
  kStale,       // a repeated sequence number, or older than the allowed age
  kCorrupted,   // flagged corrupted, invalid or sensor fault by the back end
  kNotFinite,   // NaN or infinite value
  kOutOfRange,  // outside the configured displacement range
  kFrozen,      // new, but its value repeated exactly for more than frozen_periods samples
  kJump,        // further from the sample before it than max_speed allows in the time between
  kFromFuture,  // stamped later than the cycle's release time by more than the allowed age
};
[[nodiscard]] std::string_view to_string(SampleCheck c);

[[nodiscard]] constexpr bool is_bad_value(SampleCheck c) {
  return c == SampleCheck::kCorrupted || c == SampleCheck::kNotFinite || c == SampleCheck::kOutOfRange ||
         c == SampleCheck::kFrozen || c == SampleCheck::kJump || c == SampleCheck::kFromFuture;
}

// What a usable sample must satisfy.
struct SampleLimits {
  double min = -0.050;          // [m]
  double max = 0.050;           // [m]
  hal::Timestamp max_age{};     // older is stale; this far ahead of the release time is from the future
  int frozen_periods = 0;       // 0: no frozen check
  double max_speed = 0.0;       // [m/s] between two received samples; 0: no jump check
};

// Freshness, range and plausibility check with memory: it remembers the last sequence number and
// holds the last good value, which the control law keeps using while samples are missing or bad.
// A frozen sensor (frames keep coming, one value) shows only as new samples that repeat the
// value exactly; with frozen_periods > 0, more than that many such repeats in a row are bad.
// Off (0) by default: a rig at rest can read one value for as long as it rests.
// A jump is judged against the previous received sample, good or not, so that a real step (a
// re-zeroed sensor) costs one bad sample and a spike two, while a sensor that keeps jumping
// stays bad.
class SampleChecker {
 public:
  explicit SampleChecker(const SampleLimits& limits) : limits_(limits) {}

  SampleCheck check(const std::optional<hal::Sample>& sample, hal::Timestamp now);  // value [m]

  [[nodiscard]] double held_value() const { return held_; }  // [m], 0 before the first good one
  // The held value's timing at `now` for the velocity tracker: fresh when `check` (this
  // period's) took it, with the interval since the good sample before it.
  [[nodiscard]] model::SampleTiming timing(SampleCheck check, hal::Timestamp now) const;
  [[nodiscard]] bool has_value() const { return has_value_; }

 private:
  [[nodiscard]] bool jumps(const hal::Sample& s);

  SampleLimits limits_;
  int repeats_ = 0;  // consecutive new samples with the value of the one before
  double held_ = 0.0;
  bool has_value_ = false;
  hal::Timestamp held_at_{};     // the held sample's own timestamp
  hal::Timestamp held_interval_{};  // from the good sample before it; 0 for the first
  std::optional<std::uint32_t> last_sequence_;
  std::optional<hal::Sample> previous_;  // the last received finite sample, for jumps
};

}  // namespace mrd::control
