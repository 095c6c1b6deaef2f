#include "runtime/cpu_dma_latency.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace mrd::runtime {

CpuDmaLatency& CpuDmaLatency::operator=(CpuDmaLatency&& other) noexcept {
  if (this != &other) {
    release();
    fd_ = other.fd_;
    other.fd_ = -1;
  }
  return *this;
}

std::string CpuDmaLatency::hold(std::int32_t microseconds, const std::string& device) {
  release();
  const std::string what = "cannot hold " + device + " at " + std::to_string(microseconds) + " us (";
  const std::string consequence =
      "): the CPUs may enter deep idle states and the loop's wake-up latency grows; the systemd "
      "unit and the package's udev rule grant it to the user mrd";
  const int fd = open(device.c_str(), O_WRONLY | O_CLOEXEC);
  if (fd < 0) return what + "open: " + std::strerror(errno) + consequence;
  // The kernel takes the raw 32-bit value (a decimal string works too, but cyclictest and the
  // kernel's documentation use the binary form).
  const std::int32_t value = microseconds;
  const ssize_t n = write(fd, &value, sizeof value);
  if (n != static_cast<ssize_t>(sizeof value)) {
    const int err = n < 0 ? errno : EIO;
    close(fd);
    return what + "write: " + std::strerror(err) + consequence;
  }
  fd_ = fd;
  return {};
}

void CpuDmaLatency::release() {
  if (fd_ >= 0) close(fd_);
  fd_ = -1;
}

}  // namespace mrd::runtime
