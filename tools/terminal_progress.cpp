#include "tools/terminal_progress.hpp"

#include <unistd.h>

#include <cmath>
#include <string>

namespace mrd::tools {

TerminalProgress::TerminalProgress(std::FILE* out, Clock clock)
    : out_(out), clock_(std::move(clock)), start_(clock_()) {}

TerminalProgress::~TerminalProgress() {
  if (shown_) std::fputs("\n", out_);
}

void TerminalProgress::report(const ProgressReport& r) {
  const std::lock_guard lock(mutex_);
  const auto now = clock_();
  if (r.stage != stage_ || r.round != stage_round_) {
    stage_ = std::string(r.stage);
    stage_round_ = r.round;
    stage_start_ = now;
    stage_done_ = r.done;
  }
  const bool last_of_stage = r.total > 0 && r.done >= r.total;
  if (shown_ && !last_of_stage && now - last_ < std::chrono::milliseconds(100)) return;
  last_ = now;
  std::string line(r.stage);
  char part[128];
  if (r.round > 0) {
    std::snprintf(part, sizeof part, " %d", r.round);
    line += part;
  }
  if (!r.candidate.empty()) line.append(": ").append(r.candidate);
  if (r.total > 0) {
    std::snprintf(part, sizeof part, " (%lld/%lld)", static_cast<long long>(r.done), static_cast<long long>(r.total));
    line += part;
    // The rest of the stage at the pace since its first report.
    if (r.done > stage_done_ && r.done < r.total) {
      const double pace = std::chrono::duration<double>(now - stage_start_).count() / static_cast<double>(r.done - stage_done_);
      std::snprintf(part, sizeof part, ", about %.0f s left", pace * static_cast<double>(r.total - r.done));
      line += part;
    }
  }
  if (std::isfinite(r.best_error)) {
    std::snprintf(part, sizeof part, ", best %.4g %.*s", r.best_error, static_cast<int>(r.unit.size()),
                  r.unit.data());
    line += part;
  }
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  // \r and clear to the end of the line: the status rewrites itself in place.
  std::fprintf(out_, "\r\033[K[%7.1f s] %s", elapsed, line.c_str());
  std::fflush(out_);
  shown_ = true;
}

std::unique_ptr<TerminalProgress> TerminalProgress::on_stderr(bool quiet) {
  if (quiet || ::isatty(STDERR_FILENO) != 1) return nullptr;
  return std::make_unique<TerminalProgress>(stderr);
}

}  // namespace mrd::tools
