#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

namespace mrd::hal {

// A bus back end's I/O thread and its stop request. The body polls stop_requested() between
// blocking calls (each bounded by a timeout) and sleeps through wait_until(), which a stop
// cuts short. The real-time loop only reads its progress counter: the body beats once per pass
// and wait_until beats at least every kBeatSlice, so a counter that stands still longer than
// max_silence() (the back end's longest blocking call) is a hung thread.
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

  static constexpr std::chrono::milliseconds kBeatSlice{50};
  // The body's pass: lock-free, read by the loop.
  void beat() { progress_.fetch_add(1, std::memory_order_relaxed); }
  [[nodiscard]] std::uint64_t progress() const { return progress_.load(std::memory_order_relaxed); }
  // The longest the body may go without a beat and be alive; set before start().
  void set_max_silence(std::chrono::nanoseconds d) { max_silence_ = d; }
  [[nodiscard]] std::chrono::nanoseconds max_silence() const { return max_silence_; }

 private:
  mutable std::mutex mutex_;
  std::condition_variable cv_;
  bool stop_ = false;  // guarded by mutex_
  std::atomic<std::uint64_t> progress_{0};
  std::chrono::nanoseconds max_silence_{std::chrono::seconds(1)};
  std::string name_;
  std::thread thread_;
};

}  // namespace mrd::hal
