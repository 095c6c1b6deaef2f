#pragma once

#include <chrono>
#include <cstddef>
#include <string_view>

namespace mrd::telemetry {

struct WriteResult {
  std::size_t written = 0;  // bytes taken by the file, from the start of the data
  int error = 0;            // 0: all written; the errno of the failure; ETIMEDOUT: the deadline came first
};

// Writes `data` to `fd` (opened O_NONBLOCK) and waits in poll(2) while the file takes nothing,
// but never past `deadline`: a FIFO whose reader stopped draining costs at most the deadline.
WriteResult write_before(int fd, std::string_view data, std::chrono::steady_clock::time_point deadline);

}  // namespace mrd::telemetry
