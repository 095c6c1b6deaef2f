#pragma once

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <memory>
#include <mutex>
#include <string>

#include "tools/progress.hpp"

namespace mrd::tools {

// The progress of a long job as one status line on stderr, rewritten at most ten times a second
// with the elapsed time: round, candidate, count and total, the time the stage still needs at
// its pace so far, best error. Scripts and tests see nothing: it is
// made only when stderr is a terminal and the user did not ask for --quiet.
class TerminalProgress final : public ProgressSink {
 public:
  using Clock = std::function<std::chrono::steady_clock::time_point()>;
  explicit TerminalProgress(std::FILE* out, Clock clock = &std::chrono::steady_clock::now);
  ~TerminalProgress() override;  // ends the status line
  TerminalProgress(const TerminalProgress&) = delete;
  TerminalProgress& operator=(const TerminalProgress&) = delete;

  void report(const ProgressReport& report) override;

  // A sink on stderr when it is a terminal and !quiet; otherwise none (nullptr).
  [[nodiscard]] static std::unique_ptr<TerminalProgress> on_stderr(bool quiet);

 private:
  std::FILE* out_;
  Clock clock_;
  std::mutex mutex_;
  const std::chrono::steady_clock::time_point start_;
  // The stage (and round) in progress: when its first report came and how much was done then.
  std::string stage_;
  int stage_round_ = 0;
  std::chrono::steady_clock::time_point stage_start_{};
  std::int64_t stage_done_ = 0;
  std::chrono::steady_clock::time_point last_{};
  bool shown_ = false;
};

}  // namespace mrd::tools
