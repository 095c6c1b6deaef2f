#include "runtime/rt_setup.hpp"

#include <pthread.h>
#include <sched.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

namespace mrd::runtime {

ValidationReport RealtimeConfig::validate() const {
  ValidationReport r;
  r.check(priority >= 0 && priority <= 99, "priority",
          "must be in 0..99 (0: no SCHED_FIFO), got " + std::to_string(priority));
  r.check(io_priority >= 0 && io_priority <= 99, "io_priority",
          "must be in 0..99 (0: the bus threads stay SCHED_OTHER), got " + std::to_string(io_priority));
  r.check(priority == 0 || io_priority < priority, "io_priority",
          "must be below realtime.priority (" + std::to_string(priority) +
              "): a bus thread must not preempt the loop, got " + std::to_string(io_priority));
  r.check(cpu_dma_latency >= -1 && cpu_dma_latency <= 1000000, "cpu_dma_latency",
          "must be -1 (leave it) or 0..1000000 us, got " + std::to_string(cpu_dma_latency));
  r.check(cpu >= -1 && cpu < 1024, "cpu", "must be -1 (no affinity) or a CPU number, got " +
                                              std::to_string(cpu));
  return r;
}

void lock_memory(const RealtimeConfig& config, RtSetupResult& result) {
  if (!config.lock_memory) return;
  if (mlockall(MCL_CURRENT | MCL_FUTURE) == 0) {
    result.memory_locked = true;
    return;
  }
  const int err = errno;
  result.warnings.push_back(
      std::string("mlockall failed (") + std::strerror(err) +
      "): memory is not locked and page faults may delay the loop; grant CAP_IPC_LOCK or raise "
      "LimitMEMLOCK (the systemd unit does both)");
}

void hold_cpu_dma_latency(const RealtimeConfig& config, RtSetupResult& result, const std::string& device) {
  if (config.cpu_dma_latency < 0) return;
  if (std::string warning = result.dma_latency.hold(config.cpu_dma_latency, device); !warning.empty()) {
    result.warnings.push_back(std::move(warning));
  }
}

namespace {
// Touches a stack region so its pages are mapped (and locked) before the first cycle.
void prefault_stack() {
  constexpr std::size_t kBytes = 256 * 1024;
  unsigned char stack[kBytes];
  std::memset(stack, 0, kBytes);
  asm volatile("" : : "r"(stack) : "memory");  // keep the writes
}
}  // namespace

void make_current_thread_realtime(const RealtimeConfig& config, RtSetupResult& result) {
  if (config.cpu >= 0) {
    cpu_set_t set;
    CPU_ZERO(&set);
    CPU_SET(static_cast<std::size_t>(config.cpu), &set);
    const int err = pthread_setaffinity_np(pthread_self(), sizeof set, &set);
    if (err == 0) {
      result.pinned = true;
    } else {
      result.warnings.push_back("cannot pin the loop to CPU " + std::to_string(config.cpu) + " (" +
                                std::strerror(err) + "): it runs on any CPU");
    }
  }
  if (config.priority > 0) {
    sched_param param{};
    param.sched_priority = config.priority;
    const int err = pthread_setschedparam(pthread_self(), SCHED_FIFO, &param);
    if (err == 0) {
      result.fifo = true;
    } else {
      result.warnings.push_back(
          "cannot switch the loop to SCHED_FIFO priority " + std::to_string(config.priority) +
          " (" + std::strerror(err) +
          "): it runs under SCHED_OTHER and its latency is not bounded; grant CAP_SYS_NICE and "
          "LimitRTPRIO (the systemd unit does both)");
    }
  }
  prefault_stack();
}

void make_io_threads_realtime(const RealtimeConfig& config, std::span<hal::IoThread* const> threads,
                              RtSetupResult& result) {
  if (config.priority == 0 || config.io_priority == 0) return;
  for (hal::IoThread* thread : threads) {
    const int err = thread->make_fifo(config.io_priority);
    if (err == 0) {
      ++result.io_fifo;
      continue;
    }
    result.warnings.push_back(
        "cannot switch the bus thread " + thread->name() + " to SCHED_FIFO priority " +
        std::to_string(config.io_priority) + " (" + std::strerror(err) +
        "): it runs under SCHED_OTHER and a loaded host can delay its samples past "
        "safety.stale_periods; grant CAP_SYS_NICE and LimitRTPRIO (the systemd unit does both)");
  }
}

}  // namespace mrd::runtime
