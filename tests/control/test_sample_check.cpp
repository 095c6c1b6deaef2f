// The sample check alone: samples and the cycle's release time in, a verdict out. Each verdict at
// its boundary (a sample is judged by its own timestamp against the release time, whatever its
// sequence number says), and the held value and its timing that the control law goes on with.
#include "control/sample_check.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <optional>

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

Sample valued(double value, Timestamp at, std::uint32_t sequence, std::uint8_t flags = mrd::hal::kSampleValid) {
  return {value, at, sequence, flags};
}

TEST(SampleCheck, NoSampleIsMissingAndKeepsTheHeldValue) {
  SampleChecker c = checker();
  EXPECT_FALSE(c.has_value());
  EXPECT_EQ(c.check(std::nullopt, kNow), SampleCheck::kMissing);
  ASSERT_EQ(c.check(valued(0.004, kNow, 1), kNow), SampleCheck::kFresh);
  EXPECT_EQ(c.check(std::nullopt, kNow + 1ms), SampleCheck::kMissing);
  EXPECT_TRUE(c.has_value());
  EXPECT_DOUBLE_EQ(c.held_value(), 0.004);
}

TEST(SampleCheck, TheSameSequenceNumberAgainIsStaleEvenWhenRecent) {
  SampleChecker c = checker();
  ASSERT_EQ(c.check(valued(0.001, kNow, 7), kNow), SampleCheck::kFresh);
  EXPECT_EQ(c.check(valued(0.002, kNow + 1ms, 7), kNow + 1ms), SampleCheck::kStale);
  EXPECT_DOUBLE_EQ(c.held_value(), 0.001);
  EXPECT_EQ(c.check(valued(0.002, kNow + 2ms, 8), kNow + 2ms), SampleCheck::kFresh);
}

TEST(SampleCheck, AFlaggedSampleIsCorruptedAndItsValueIsNotHeld) {
  using mrd::hal::kSampleCorrupted;
  using mrd::hal::kSampleSensorFault;
  using mrd::hal::kSampleSequenceGap;
  using mrd::hal::kSampleValid;
  SampleChecker c = checker();
  ASSERT_EQ(c.check(valued(0.001, kNow, 1), kNow), SampleCheck::kFresh);
  EXPECT_EQ(c.check(valued(0.009, kNow, 2, 0), kNow), SampleCheck::kCorrupted);  // not valid
  EXPECT_EQ(c.check(valued(0.009, kNow, 3, kSampleValid | kSampleCorrupted), kNow), SampleCheck::kCorrupted);
  EXPECT_EQ(c.check(valued(0.009, kNow, 4, kSampleValid | kSampleSensorFault), kNow), SampleCheck::kCorrupted);
  EXPECT_DOUBLE_EQ(c.held_value(), 0.001);
  // A gap before it does not make a sample unusable.
  EXPECT_EQ(c.check(valued(0.002, kNow, 5, kSampleValid | kSampleSequenceGap), kNow), SampleCheck::kFresh);
  EXPECT_DOUBLE_EQ(c.held_value(), 0.002);
}

TEST(SampleCheck, NaNAndInfinityAreNotFinite) {
  SampleChecker c = checker();
  EXPECT_EQ(c.check(valued(std::numeric_limits<double>::quiet_NaN(), kNow, 1), kNow), SampleCheck::kNotFinite);
  EXPECT_EQ(c.check(valued(std::numeric_limits<double>::infinity(), kNow, 2), kNow), SampleCheck::kNotFinite);
  EXPECT_EQ(c.check(valued(-std::numeric_limits<double>::infinity(), kNow, 3), kNow), SampleCheck::kNotFinite);
  EXPECT_FALSE(c.has_value());
}

TEST(SampleCheck, TheRangeEndsAreInAndTheNextDoubleBeyondIsOut) {
  SampleChecker c({.min = -0.02, .max = 0.03, .max_age = kMaxAge});
  EXPECT_EQ(c.check(valued(-0.02, kNow, 1), kNow), SampleCheck::kFresh);
  EXPECT_EQ(c.check(valued(0.03, kNow, 2), kNow), SampleCheck::kFresh);
  EXPECT_EQ(c.check(valued(std::nextafter(0.03, 1.0), kNow, 3), kNow), SampleCheck::kOutOfRange);
  EXPECT_EQ(c.check(valued(std::nextafter(-0.02, -1.0), kNow, 4), kNow), SampleCheck::kOutOfRange);
  EXPECT_DOUBLE_EQ(c.held_value(), 0.03);
}

// frozen_periods repeats of one value are allowed; the next is frozen, and a changed value is fresh.
TEST(SampleCheck, AValueRepeatedMoreThanTheFrozenPeriodsIsFrozen) {
  SampleChecker c({.max_age = kMaxAge, .frozen_periods = 3});
  std::uint32_t sequence = 1;
  Timestamp now = kNow;
  auto next = [&](double value) {
    now += 1ms;
    return c.check(valued(value, now, sequence++), now);
  };
  EXPECT_EQ(next(0.005), SampleCheck::kFresh);
  for (int repeat = 1; repeat <= 3; ++repeat) EXPECT_EQ(next(0.005), SampleCheck::kFresh) << repeat;
  EXPECT_EQ(next(0.005), SampleCheck::kFrozen);
  EXPECT_EQ(next(0.005), SampleCheck::kFrozen);
  EXPECT_EQ(next(0.0051), SampleCheck::kFresh);
  EXPECT_DOUBLE_EQ(c.held_value(), 0.0051);
}

TEST(SampleCheck, WithoutAFrozenLimitARestingSensorStaysFresh) {
  SampleChecker c = checker();
  for (std::uint32_t i = 1; i <= 1000; ++i) {
    const Timestamp now = kNow + i * 1ms;
    ASSERT_EQ(c.check(valued(0.005, now, i), now), SampleCheck::kFresh) << i;
  }
}

// max_speed 1 m/s over 1 ms allows 1 mm: a step of 1.1 mm is a jump, and so is the step back
// (judged against the bad sample), after which the value is fresh again.
TEST(SampleCheck, AStepFasterThanTheMaximumSpeedIsAJumpAndASpikeCostsTwoSamples) {
  SampleChecker c({.max_age = kMaxAge, .max_speed = 1.0});
  ASSERT_EQ(c.check(valued(0.0, kNow, 1), kNow), SampleCheck::kFresh);
  EXPECT_EQ(c.check(valued(0.0009, kNow + 1ms, 2), kNow + 1ms), SampleCheck::kFresh);
  EXPECT_EQ(c.check(valued(0.0020, kNow + 2ms, 3), kNow + 2ms), SampleCheck::kJump);
  EXPECT_EQ(c.check(valued(0.0009, kNow + 3ms, 4), kNow + 3ms), SampleCheck::kJump);
  EXPECT_EQ(c.check(valued(0.0010, kNow + 4ms, 5), kNow + 4ms), SampleCheck::kFresh);
  EXPECT_DOUBLE_EQ(c.held_value(), 0.0010);
}

// At the limit exactly: 1 mm in 1 ms at 1 m/s is motion, not a jump.
TEST(SampleCheck, AStepOfExactlyTheMaximumSpeedIsNoJump) {
  SampleChecker c({.max_age = kMaxAge, .max_speed = 1.0});
  ASSERT_EQ(c.check(valued(0.0, kNow, 1), kNow), SampleCheck::kFresh);
  EXPECT_EQ(c.check(valued(0.001, kNow + 1ms, 2), kNow + 1ms), SampleCheck::kFresh);
}

// Two samples with one timestamp are judged over a microsecond: noise passes, a step does not.
TEST(SampleCheck, TwoSamplesAtOneTimeAreJudgedOverAMicrosecond) {
  SampleChecker c({.max_age = kMaxAge, .max_speed = 1.0});
  ASSERT_EQ(c.check(valued(0.0, kNow, 1), kNow), SampleCheck::kFresh);
  EXPECT_EQ(c.check(valued(0.5e-6, kNow, 2), kNow), SampleCheck::kFresh);
  EXPECT_EQ(c.check(valued(2.0e-6, kNow, 3), kNow), SampleCheck::kJump);
}

TEST(SampleCheck, TheTimingIsFreshOnlyInThePeriodThatTookTheSampleWithItsIntervalAndAge) {
  SampleChecker c = checker();
  const SampleCheck first = c.check(valued(0.001, kNow, 1), kNow);
  EXPECT_TRUE(c.timing(first, kNow).fresh);
  EXPECT_DOUBLE_EQ(c.timing(first, kNow).interval, 0.0);
  const SampleCheck second = c.check(valued(0.002, kNow + 2ms, 2), kNow + 3ms);
  ASSERT_EQ(second, SampleCheck::kFresh);
  EXPECT_NEAR(c.timing(second, kNow + 3ms).interval, 0.002, 1e-12);
  EXPECT_NEAR(c.timing(second, kNow + 3ms).age, 0.001, 1e-12);
  const SampleCheck missing = c.check(std::nullopt, kNow + 4ms);
  EXPECT_FALSE(c.timing(missing, kNow + 4ms).fresh);
  EXPECT_NEAR(c.timing(missing, kNow + 4ms).age, 0.002, 1e-12);
}

TEST(SampleCheck, EveryVerdictHasItsOwnNameAndOnlyFreshMissingAndStaleAreNotBadValues) {
  using mrd::control::is_bad_value;
  using mrd::control::to_string;
  // The telemetry's `sample` column spells these.
  EXPECT_EQ(to_string(SampleCheck::kFresh), "fresh");
  EXPECT_EQ(to_string(SampleCheck::kMissing), "missing");
  EXPECT_EQ(to_string(SampleCheck::kStale), "stale");
  EXPECT_EQ(to_string(SampleCheck::kCorrupted), "corrupted");
  EXPECT_EQ(to_string(SampleCheck::kNotFinite), "not_finite");
  EXPECT_EQ(to_string(SampleCheck::kOutOfRange), "out_of_range");
  EXPECT_EQ(to_string(SampleCheck::kFrozen), "frozen");
  EXPECT_EQ(to_string(SampleCheck::kJump), "jump");
  EXPECT_EQ(to_string(SampleCheck::kFromFuture), "from_future");
  EXPECT_FALSE(is_bad_value(SampleCheck::kFresh));
  EXPECT_FALSE(is_bad_value(SampleCheck::kMissing));
  EXPECT_FALSE(is_bad_value(SampleCheck::kStale));
  for (SampleCheck bad : {SampleCheck::kCorrupted, SampleCheck::kNotFinite, SampleCheck::kOutOfRange,
                          SampleCheck::kFrozen, SampleCheck::kJump, SampleCheck::kFromFuture}) {
    EXPECT_TRUE(is_bad_value(bad)) << to_string(bad);
  }
}

}  // namespace
