#pragma once

#include <cstdio>
#include <string>
#include <string_view>

#include "hal/clock.hpp"
#include "telemetry/supervisor_feed.hpp"

namespace mrd::telemetry {

// syslog(3) priorities, as journald reads them from a "<N>" line prefix.
enum class Priority : int { kCrit = 2, kErr = 3, kWarning = 4, kNotice = 5, kInfo = 6 };

// Log lines from the non-real-time threads. Under systemd, stderr is a stream to journald
// (JOURNAL_STREAM names its device and inode) and each line carries its priority as a "<N>"
// prefix, which journald strips and files (journalctl -p warning shows DEGRADED and worse);
// on a terminal the line reads "<program>: <text>" without the number.
class Journal {
 public:
  Journal(std::FILE* out, bool priority_prefix, std::string program)
      : out_(out), prefix_(priority_prefix), program_(std::move(program)) {}
  // stderr, with prefixes when stderr is journald's stream.
  static Journal for_stderr(std::string program);
  // True when the JOURNAL_STREAM variable ("device:inode") names the file behind `fd`.
  static bool is_journal_stream(int fd);

  void write(Priority priority, std::string_view text) const;
  [[nodiscard]] bool priority_prefix() const { return prefix_; }

 private:
  std::FILE* out_;
  bool prefix_;
  std::string program_;
};

// A transition's priority: SAFE on a fault is critical (the coil is de-energised and the damper
// passive), a SAFE the operator asked for (shutdown) a notice, DEGRADED a warning, RUN a notice.
[[nodiscard]] Priority transition_priority(const SupervisorEvent& e);
// "supervisor: RUN -> SAFE (driver_fault) at cycle 1234, 1.234 s after start"
[[nodiscard]] std::string format_transition(const SupervisorEvent& e, hal::Timestamp start);
// The statistics' table: "  INIT -> RUN (good_periods): 1" per non-zero (from, to, trigger).
[[nodiscard]] std::string format_transitions(const control::TransitionCounts& counts);

}  // namespace mrd::telemetry
