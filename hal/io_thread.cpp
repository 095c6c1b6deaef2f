#include "hal/io_thread.hpp"

#include <pthread.h>

namespace mrd::hal {

void IoThread::start(const std::string& name, std::function<void()> body) {
  stop();
  {
    const std::lock_guard lock(mutex_);
    stop_ = false;
  }
  thread_ = std::thread(std::move(body));
  pthread_setname_np(thread_.native_handle(), name.substr(0, 15).c_str());
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
  return !cv_.wait_until(lock, deadline, [this] { return stop_; });
}

}  // namespace mrd::hal
