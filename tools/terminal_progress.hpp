#pragma once

#include <chrono>
#include <cstdio>
#include <memory>
#include <mutex>

#include "tools/progress.hpp"

namespace mrd::tools {

// The progress of a long job as one status line on stderr, rewritten at most ten times a second
// with the elapsed time: round, candidate, best error. Scripts and tests see nothing: it is
// made only when stderr is a terminal and the user did not ask for --quiet.
class TerminalProgress final : public ProgressSink {
 public:
  explicit TerminalProgress(std::FILE* out);
  ~TerminalProgress() override;  // ends the status line
  TerminalProgress(const TerminalProgress&) = delete;
  TerminalProgress& operator=(const TerminalProgress&) = delete;

  void report(const ProgressReport& report) override;

  // A sink on stderr when it is a terminal and !quiet; otherwise none (nullptr).
  [[nodiscard]] static std::unique_ptr<TerminalProgress> on_stderr(bool quiet);

 private:
  std::FILE* out_;
  std::mutex mutex_;
  const std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_{};
  bool shown_ = false;
};

}  // namespace mrd::tools
