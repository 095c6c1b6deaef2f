#pragma once

#include <sys/types.h>

#include <chrono>
#include <optional>
#include <regex>
#include <string>
#include <vector>

namespace mrd::test {

// A program the test starts, with its stdout and stderr read through one pipe. Every wait is
// for an event (a line of output, the exit) and bounded by a limit; none sleeps a fixed time.
class ChildProcess {
 public:
  explicit ChildProcess(const std::vector<std::string>& argv);
  ~ChildProcess();  // SIGKILL if still running
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  [[nodiscard]] bool started() const { return pid_ > 0; }
  // Reads output until a line matches `pattern`; the match and its groups ([0] is the whole
  // match), or nullopt at the limit or at the end of the output.
  std::optional<std::vector<std::string>> wait_for_line(const std::regex& pattern, std::chrono::milliseconds limit);
  // Reads output for up to `limit`; false once it has ended (the process is exiting).
  bool read_for(std::chrono::milliseconds limit) { return read_some(limit); }
  // Reads all output and reaps the process; its exit code (128 + signal when killed), or
  // nullopt at the limit.
  std::optional<int> wait_exit(std::chrono::milliseconds limit);
  void signal(int sig);
  [[nodiscard]] const std::string& output() const { return output_; }

 private:
  bool read_some(std::chrono::milliseconds limit);  // false at the end of the output

  pid_t pid_ = -1;
  int fd_ = -1;
  std::string output_;
  std::size_t scanned_ = 0;  // lines before this offset were matched against already
  std::optional<int> status_;
};

// The first match of `pattern` in `text`, as a number (group 1).
std::optional<double> find_number(const std::string& text, const std::string& pattern);

}  // namespace mrd::test
