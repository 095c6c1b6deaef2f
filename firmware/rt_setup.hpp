#pragma once

#include <string>
#include <vector>

#include "hal/config_check.hpp"

namespace mrd::firmware {

struct RealtimeConfig {
  int priority = 80;        // SCHED_FIFO priority 1..99 for the loop thread; 0: stay SCHED_OTHER
  int cpu = -1;             // pin the loop thread to this CPU; -1: no affinity
  bool lock_memory = true;  // mlockall(MCL_CURRENT | MCL_FUTURE)

  [[nodiscard]] hal::ConfigReport validate() const;  // field paths relative to [realtime]
};

// What the set-up achieved. Each step that could not be done leaves a warning saying what was
// asked, why it failed and what runs instead; the controller runs on regardless.
struct RtSetupResult {
  bool memory_locked = false;
  bool fifo = false;
  bool pinned = false;
  std::vector<std::string> warnings;
};

// Process-wide, before the threads start: mlockall and a pre-faulted heap.
void lock_memory(const RealtimeConfig& config, RtSetupResult& result);
// On the loop thread itself: SCHED_FIFO, affinity, and a pre-faulted stack.
void make_current_thread_realtime(const RealtimeConfig& config, RtSetupResult& result);

}  // namespace mrd::firmware
