#pragma once

#include <boost/lockfree/spsc_queue.hpp>
#include <cstddef>
#include <optional>
#include <type_traits>

namespace mrd::hal {

// Lock-free single-producer/single-consumer FIFO with a compile-time capacity, used between a
// bus I/O thread and the real-time loop. It wraps boost::lockfree::spsc_queue (Debian's
// libboost-dev) rather than a home-made ring: its acquire/release protocol is long reviewed,
// and capacity<N> keeps the storage inline, so neither side ever allocates.
template <typename T, std::size_t Capacity>
class SpscRing {
  static_assert(std::is_trivially_copyable_v<T>, "items cross threads by copy");
  static_assert(Capacity >= 2);

 public:
  // Producer side. False when full: the item is dropped and the caller counts it.
  bool try_push(const T& item) { return queue_.push(item); }

  // Consumer side.
  std::optional<T> try_pop() {
    T item;
    if (queue_.pop(item)) return item;
    return std::nullopt;
  }
  // Drains everything and keeps the newest: the loop wants the latest sample, not a backlog.
  std::optional<T> pop_latest() {
    std::optional<T> newest;
    queue_.consume_all([&newest](const T& item) { newest = item; });
    return newest;
  }
  [[nodiscard]] std::size_t size_approx() const { return queue_.read_available(); }

  static constexpr std::size_t capacity() { return Capacity; }

 private:
  boost::lockfree::spsc_queue<T, boost::lockfree::capacity<Capacity>> queue_;
};

}  // namespace mrd::hal
