// Telemetry's losses in the journal: a new condition at once, more of the same at most once per
// interval, never a line per record; and in systemd's STATUS=. Time is scripted.
#include "telemetry/telemetry_alarm.hpp"

#include <gtest/gtest.h>

#include <cerrno>
#include <chrono>

#include "telemetry/service_notifier.hpp"

namespace {

using mrd::telemetry::Priority;
using mrd::telemetry::TelemetryAlarm;
using mrd::telemetry::TelemetryLosses;
using std::chrono::seconds;

TEST(TelemetryAlarm, NothingLostNothingSaid) {
  TelemetryAlarm alarm(seconds(5));
  EXPECT_FALSE(alarm.check({}, seconds(0)));
  EXPECT_FALSE(alarm.check({}, seconds(100)));
}

TEST(TelemetryAlarm, TheFirstDropAtOnceThenAtMostOncePerInterval) {
  TelemetryAlarm alarm(seconds(5));
  const auto first = alarm.check({.dropped = 3}, seconds(1));
  ASSERT_TRUE(first);
  EXPECT_EQ(first->priority, Priority::kWarning);
  EXPECT_EQ(first->text, "telemetry: 3 records dropped (the ring was full) so far");
  EXPECT_FALSE(alarm.check({.dropped = 50}, seconds(2)));
  EXPECT_FALSE(alarm.check({.dropped = 90}, seconds(6) - std::chrono::nanoseconds(1)));
  const auto later = alarm.check({.dropped = 120}, seconds(6));
  ASSERT_TRUE(later);
  EXPECT_EQ(later->text, "telemetry: 120 records dropped (the ring was full) so far");
  EXPECT_FALSE(alarm.check({.dropped = 120}, seconds(60)));  // no new losses: silence
}

TEST(TelemetryAlarm, AnIoFailureIsAnErrorAndANewErrnoIsSaidAtOnce) {
  TelemetryAlarm alarm(seconds(5));
  ASSERT_TRUE(alarm.check({.dropped = 1}, seconds(0)));
  const auto io = alarm.check({.dropped = 1, .lost = 40, .error = ENOSPC}, seconds(1));
  ASSERT_TRUE(io);
  EXPECT_EQ(io->priority, Priority::kErr);
  EXPECT_EQ(io->text, "telemetry: 1 records dropped (the ring was full), 40 lost to I/O (No space left on device) so far");
  EXPECT_FALSE(alarm.check({.dropped = 1, .lost = 400, .error = ENOSPC}, seconds(2)));
  const auto other = alarm.check({.dropped = 1, .lost = 401, .error = EPIPE}, seconds(3));
  ASSERT_TRUE(other);
  EXPECT_NE(other->text.find("401 lost to I/O (Broken pipe)"), std::string::npos) << other->text;
}

TEST(TelemetryAlarm, AFailedHeaderWithNoRecordLostYetIsSaid) {
  TelemetryAlarm alarm(seconds(5));
  const auto line = alarm.check({.error = ENOSPC}, seconds(0));
  ASSERT_TRUE(line);
  EXPECT_EQ(line->priority, Priority::kErr);
  EXPECT_EQ(line->text, "telemetry: 0 lost to I/O (No space left on device) so far");
}

TEST(TelemetryAlarm, TheStatusLineCarriesTheLosses) {
  mrd::telemetry::ServiceStatus s{.rate = 1000.0, .cycles = 10};
  EXPECT_EQ(format_status(s), "INIT, 1000 Hz, wake-up p99 0.0 us, overruns 0, cycles 10");
  s.telemetry = {.dropped = 2, .lost = 7, .error = EPIPE};
  EXPECT_EQ(format_status(s), "INIT, 1000 Hz, wake-up p99 0.0 us, overruns 0, cycles 10; telemetry: 2 records dropped "
                              "(the ring was full), 7 lost to I/O (Broken pipe)");
}

}  // namespace

namespace {

TEST(TelemetryAlarm, TheWritersTimeoutIsSaidAsWhatHappened) {
  EXPECT_EQ(mrd::telemetry::describe_losses({.lost = 5, .error = ETIMEDOUT}),
            "5 lost to I/O (the file took nothing within the write timeout)");
}

}  // namespace
