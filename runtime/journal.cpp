#include "runtime/journal.hpp"

#include <sys/stat.h>

#include <cinttypes>
#include <cstdlib>

namespace mrd::runtime {

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

}  // namespace mrd::runtime
