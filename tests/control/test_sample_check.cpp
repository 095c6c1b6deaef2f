// The sample check alone, at the boundaries of its age limits: a sample is judged by its own
// timestamp against the cycle's release time, whatever its sequence number says.
#include "control/sample_check.hpp"

#include <gtest/gtest.h>

#include <chrono>

namespace {

using namespace std::chrono_literals;
using mrd::control::SampleCheck;
using mrd::control::SampleChecker;
using mrd::hal::Sample;
using mrd::hal::Timestamp;

constexpr Timestamp kMaxAge = 5ms;
constexpr Timestamp kNow = 1s;

SampleChecker checker() { return SampleChecker({.max_age = kMaxAge}); }

Sample stamped(Timestamp at, std::uint32_t sequence) {
  return {0.001, at, sequence, mrd::hal::kSampleValid};
}

TEST(SampleCheck, ASampleExactlyTheAllowedAgeOldIsFreshAndOneNanosecondOlderIsStale) {
  SampleChecker c = checker();
  EXPECT_EQ(c.check(stamped(kNow - kMaxAge, 1), kNow), SampleCheck::kFresh);
  EXPECT_EQ(c.check(stamped(kNow + 1ms - kMaxAge - 1ns, 2), kNow + 1ms), SampleCheck::kStale);
}

// A bus that delivers late: every sample new, each stamped before the allowed age.
TEST(SampleCheck, AnOldSampleWithANewSequenceNumberIsStale) {
  SampleChecker c = checker();
  ASSERT_EQ(c.check(stamped(kNow, 1), kNow), SampleCheck::kFresh);
  for (std::uint32_t i = 2; i < 6; ++i) {
    const Timestamp now = kNow + i * 1ms;
    EXPECT_EQ(c.check(stamped(now - 2 * kMaxAge, i), now), SampleCheck::kStale) << i;
  }
  // The held value is the last fresh one's, and a timely sample is fresh again.
  EXPECT_EQ(c.check(stamped(kNow + 6ms, 6), kNow + 6ms), SampleCheck::kFresh);
}

TEST(SampleCheck, ASampleExactlyTheAllowedAgeAheadIsFreshAndOneNanosecondMoreIsFromTheFuture) {
  SampleChecker c = checker();
  EXPECT_EQ(c.check(stamped(kNow + kMaxAge, 1), kNow), SampleCheck::kFresh);
  EXPECT_EQ(c.check(stamped(kNow + 1ms + kMaxAge + 1ns, 2), kNow + 1ms), SampleCheck::kFromFuture);
}

}  // namespace
