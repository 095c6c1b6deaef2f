#include "hal/io_thread.hpp"

#include <pthread.h>
#include <sched.h>

#include <algorithm>
#include <cerrno>

namespace mrd::hal {

void IoThread::start(const std::string& name, std::function<void()> body) {
  stop();
  {
    const std::lock_guard lock(mutex_);
    stop_ = false;
  }
  name_ = name.substr(0, 15);
  thread_ = std::thread(std::move(body));
  pthread_setname_np(thread_.native_handle(), name_.c_str());
}

int IoThread::make_fifo(int priority) {
  if (!thread_.joinable()) return ESRCH;
  sched_param param{};
  param.sched_priority = priority;
  return pthread_setschedparam(thread_.native_handle(), SCHED_FIFO, &param);
}

void IoThread::stop() {
  {
    const std::lock_guard lock(mutex_);
    stop_ = true;
  }
  cv_.notify_all();
  if (thread_.joinable()) thread_.join();
}

bool IoThread::stop_requested() const {
  const std::lock_guard lock(mutex_);
  return stop_;
}

bool IoThread::wait_until(std::chrono::steady_clock::time_point deadline) {
  std::unique_lock lock(mutex_);
  // In slices: a long back-off is a live thread, and says so.
  for (;;) {
    beat();
    const auto slice = std::min(deadline, std::chrono::steady_clock::now() + kBeatSlice);
    if (cv_.wait_until(lock, slice, [this] { return stop_; })) return false;
    if (slice == deadline) return true;
  }
}

}  // namespace mrd::hal
