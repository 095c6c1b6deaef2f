#include "telemetry/journal.hpp"

#include <sys/stat.h>

#include <cinttypes>
#include <cstdlib>

namespace mrd::telemetry {

bool Journal::is_journal_stream(int fd) {
  const char* stream = std::getenv("JOURNAL_STREAM");
  if (stream == nullptr) return false;
  unsigned long long device = 0;
  unsigned long long inode = 0;
  if (std::sscanf(stream, "%llu:%llu", &device, &inode) != 2) return false;
  struct stat st{};
  if (fstat(fd, &st) != 0) return false;
  return static_cast<unsigned long long>(st.st_dev) == device && static_cast<unsigned long long>(st.st_ino) == inode;
}

Journal Journal::for_stderr(std::string program) {
  return Journal(stderr, is_journal_stream(2), std::move(program));
}

void Journal::write(Priority priority, std::string_view text) const {
  if (prefix_) {
    std::fprintf(out_, "<%d>%.*s\n", static_cast<int>(priority), static_cast<int>(text.size()), text.data());
  } else {
    std::fprintf(out_, "%s: %.*s\n", program_.c_str(), static_cast<int>(text.size()), text.data());
  }
  std::fflush(out_);
}

Priority transition_priority(const SupervisorEvent& e) {
  using control::SupervisorState;
  switch (e.to) {
    case SupervisorState::kSafe:
      return e.trigger == control::Trigger::kShutdown ? Priority::kNotice : Priority::kCrit;
    case SupervisorState::kDegraded: return Priority::kWarning;
    default: return Priority::kNotice;
  }
}

std::string format_transition(const SupervisorEvent& e, hal::Timestamp start) {
  char line[192];
  std::snprintf(line, sizeof line, "supervisor: %s -> %s (%s) at cycle %" PRIu64 ", %.3f s after start",
                std::string(to_string(e.from)).c_str(), std::string(to_string(e.to)).c_str(),
                std::string(to_string(e.trigger)).c_str(), e.cycle,
                std::chrono::duration<double>(e.time - start).count());
  return line;
}

std::string format_transitions(const control::TransitionCounts& counts) {
  std::string out;
  constexpr auto kStates = static_cast<std::size_t>(control::SupervisorState::kCount);
  constexpr auto kTriggers = static_cast<std::size_t>(control::Trigger::kCount);
  for (std::size_t from = 0; from < kStates; ++from) {
    for (std::size_t to = 0; to < kStates; ++to) {
      for (std::size_t why = 0; why < kTriggers; ++why) {
        const auto f = static_cast<control::SupervisorState>(from);
        const auto t = static_cast<control::SupervisorState>(to);
        const auto w = static_cast<control::Trigger>(why);
        if (const std::uint64_t n = counts.get(f, t, w); n > 0) {
          out += "  " + std::string(to_string(f)) + " -> " + std::string(to_string(t)) + " (" +
                 std::string(to_string(w)) + "): " + std::to_string(n) + "\n";
        }
      }
    }
  }
  return out.empty() ? "  (none)\n" : out;
}

}  // namespace mrd::telemetry
