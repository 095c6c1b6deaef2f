#pragma once

#include <cstdint>
#include <string>

namespace mrd::runtime {

// Holds the kernel's power-management QoS request on /dev/cpu_dma_latency, as cyclictest does:
// open it, write the 32-bit limit in microseconds, keep the descriptor open. While it is open
// the CPUs stay out of idle states whose exit latency exceeds the limit (0: the shallowest
// only); closing it withdraws the request. Without it a 1 kHz loop pays a deep C-state's exit on
// most wake-ups (docs/PERFORMANCE.md). Move-only; the destructor closes.
class CpuDmaLatency {
 public:
  static constexpr const char* kDevice = "/dev/cpu_dma_latency";

  CpuDmaLatency() = default;
  ~CpuDmaLatency() { release(); }
  CpuDmaLatency(CpuDmaLatency&& other) noexcept : fd_(other.fd_) { other.fd_ = -1; }
  CpuDmaLatency& operator=(CpuDmaLatency&& other) noexcept;
  CpuDmaLatency(const CpuDmaLatency&) = delete;
  CpuDmaLatency& operator=(const CpuDmaLatency&) = delete;

  // Opens `device` and writes `microseconds`; an empty string on success, else a warning that
  // names the call, the error and the consequence (the request is then not held).
  [[nodiscard]] std::string hold(std::int32_t microseconds, const std::string& device = kDevice);
  void release();
  [[nodiscard]] bool held() const { return fd_ >= 0; }

 private:
  int fd_ = -1;
};

}  // namespace mrd::runtime
