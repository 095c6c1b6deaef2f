#pragma once

#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

namespace mrd::hal {

// A bus back end's I/O thread and its stop request. The body polls stop_requested() between
// blocking calls (each bounded by a timeout) and sleeps through wait_until(), which a stop
// cuts short. Never used by the real-time loop itself.
class IoThread {
 public:
  IoThread() = default;
  ~IoThread() { stop(); }
  IoThread(const IoThread&) = delete;
  IoThread& operator=(const IoThread&) = delete;

  // `name` shows in top/ps (at most 15 characters).
  void start(const std::string& name, std::function<void()> body);
  // Asks the body to return and joins it. Safe to call when not started, or twice.
  void stop();

  [[nodiscard]] bool running() const { return thread_.joinable(); }
  [[nodiscard]] const std::string& name() const { return name_; }
  // Switches the running thread to SCHED_FIFO at `priority`; 0 or the errno of the refusal.
  [[nodiscard]] int make_fifo(int priority);
  [[nodiscard]] bool stop_requested() const;
  // Sleeps until `deadline`; false when a stop was requested (then returns at once).
  bool wait_until(std::chrono::steady_clock::time_point deadline);
  bool wait_for(std::chrono::steady_clock::duration d) {
    return wait_until(std::chrono::steady_clock::now() + d);
  }

 private:
  mutable std::mutex mutex_;
  std::condition_variable cv_;
  bool stop_ = false;  // guarded by mutex_
  std::string name_;
  std::thread thread_;
};

}  // namespace mrd::hal
