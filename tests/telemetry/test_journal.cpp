// Transitions reach the journal with syslog priorities: "<N>" prefixes when stderr is
// journald's stream (JOURNAL_STREAM names it), the program's name on a terminal.
#include "telemetry/journal.hpp"

#include <gtest/gtest.h>

#include "tests/support/test_files.hpp"
#include <stdlib.h>
#include <sys/stat.h>

#include <cstdio>
#include <string>

namespace {

using mrd::control::SupervisorState;
using mrd::control::Trigger;
using mrd::telemetry::Journal;
using mrd::telemetry::Priority;
using mrd::telemetry::SupervisorEvent;

SupervisorEvent event(SupervisorState from, SupervisorState to, Trigger why) {
  return {.cycle = 1234, .time = std::chrono::milliseconds(1734), .from = from, .to = to, .trigger = why};
}

TEST(Journal, PrioritiesFollowTheStateEntered) {
  EXPECT_EQ(transition_priority(event(SupervisorState::kRun, SupervisorState::kSafe, Trigger::kDriverFault)),
            Priority::kCrit);
  EXPECT_EQ(transition_priority(event(SupervisorState::kRun, SupervisorState::kSafe, Trigger::kShutdown)),
            Priority::kNotice);
  EXPECT_EQ(transition_priority(event(SupervisorState::kRun, SupervisorState::kDegraded, Trigger::kOverrun)),
            Priority::kWarning);
  EXPECT_EQ(transition_priority(event(SupervisorState::kSafe, SupervisorState::kRun, Trigger::kGoodPeriods)),
            Priority::kNotice);
}

TEST(Journal, TransitionLineNamesStatesTriggerCycleAndTime) {
  EXPECT_EQ(format_transition(event(SupervisorState::kRun, SupervisorState::kSafe, Trigger::kDriverFault),
                              std::chrono::milliseconds(500)),
            "supervisor: RUN -> SAFE (driver_fault) at cycle 1234, 1.234 s after start");
}

TEST(Journal, PrefixForJournaldPlainNameForATerminal) {
  std::FILE* f = std::tmpfile();
  Journal(f, true, "mrd-controller").write(Priority::kCrit, "supervisor: RUN -> SAFE");
  Journal(f, false, "mrd-controller").write(Priority::kWarning, "supervisor: RUN -> DEGRADED");
  EXPECT_EQ(mrd::test::read_and_close(f), "<2>supervisor: RUN -> SAFE\nmrd-controller: supervisor: RUN -> DEGRADED\n");
}

TEST(Journal, JournalStreamIsRecognisedByDeviceAndInode) {
  std::FILE* f = std::tmpfile();
  struct stat st{};
  ASSERT_EQ(fstat(fileno(f), &st), 0);
  const std::string mine = std::to_string(st.st_dev) + ":" + std::to_string(st.st_ino);
  const char* saved = std::getenv("JOURNAL_STREAM");
  const std::string kept = saved != nullptr ? saved : "";
  setenv("JOURNAL_STREAM", mine.c_str(), 1);
  EXPECT_TRUE(Journal::is_journal_stream(fileno(f)));
  setenv("JOURNAL_STREAM", (std::to_string(st.st_dev) + ":" + std::to_string(st.st_ino + 1)).c_str(), 1);
  EXPECT_FALSE(Journal::is_journal_stream(fileno(f)));
  unsetenv("JOURNAL_STREAM");
  EXPECT_FALSE(Journal::is_journal_stream(fileno(f)));
  if (saved != nullptr) setenv("JOURNAL_STREAM", kept.c_str(), 1);
  std::fclose(f);
}

}  // namespace
