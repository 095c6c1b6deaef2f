#include "telemetry/bounded_write.hpp"

#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>

namespace mrd::telemetry {

WriteResult write_before(int fd, std::string_view data, std::chrono::steady_clock::time_point deadline) {
  WriteResult result;
  while (result.written < data.size()) {
    const ssize_t n = ::write(fd, data.data() + result.written, data.size() - result.written);
    if (n > 0) {
      result.written += static_cast<std::size_t>(n);
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK) {
      result.error = errno;
      return result;
    }
    const auto left = std::chrono::ceil<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) {
      result.error = ETIMEDOUT;
      return result;
    }
    pollfd p{.fd = fd, .events = POLLOUT, .revents = 0};
    const int timeout = static_cast<int>(std::min<std::chrono::milliseconds::rep>(left.count(), 1000));
    if (::poll(&p, 1, timeout) < 0 && errno != EINTR) {
      result.error = errno;
      return result;
    }
  }
  return result;
}

}  // namespace mrd::telemetry
