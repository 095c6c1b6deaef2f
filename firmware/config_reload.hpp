#pragma once

#include <string>

#include "telemetry/journal.hpp"

namespace mrd::firmware {

// SIGHUP's answer (a logrotate `kill -HUP` among the senders): the config file read and checked
// again, never a stop. Nothing is swapped under a running damper: a file that differs from the
// one the run started with, however valid, takes effect at the next start (systemctl restart),
// and the journal says so; an invalid one is reported with every problem.
class ConfigReload {
 public:
  // `path`: the --config file (empty: the embedded config runs); `running_text`: its text at start.
  ConfigReload(std::string path, std::string running_text)
      : path_(std::move(path)), running_text_(std::move(running_text)) {}

  struct Outcome {
    telemetry::Priority priority;
    std::string text;  // the journal's line(s)
  };
  // Reads and validates the file now (main thread; allocates, reads a file).
  [[nodiscard]] Outcome check() const;

 private:
  std::string path_;
  std::string running_text_;
};

}  // namespace mrd::firmware
