#pragma once

#include <condition_variable>
#include <cstddef>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace mrd::tools {

// Persistent threads for batch evaluation on the host (not real-time code). run() hands out
// indices [0, count) and returns when all are done; the caller's thread works too.
class WorkerPool {
 public:
  explicit WorkerPool(unsigned threads);  // total threads including the caller; 0 = all cores
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  [[nodiscard]] unsigned size() const { return static_cast<unsigned>(workers_.size()) + 1; }
  // task(index, worker) with worker in [0, size()), so each worker may own scratch memory.
  void run(std::size_t count, const std::function<void(std::size_t, unsigned)>& task);

 private:
  void work(unsigned worker);
  void drain(unsigned worker);

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  const std::function<void(std::size_t, unsigned)>* task_ = nullptr;
  std::size_t count_ = 0;
  std::size_t next_ = 0;
  std::size_t finished_ = 0;
  std::size_t generation_ = 0;
  bool stopping_ = false;
};

}  // namespace mrd::tools
