#pragma once

#include <chrono>
#include <thread>

namespace mrd::test {

// Polls `condition` until it holds or `limit` passes; returns whether it held. A bounded wait
// for an event, never a fixed sleep standing in for one.
template <typename Condition>
bool wait_for(Condition&& condition, std::chrono::milliseconds limit = std::chrono::seconds{5}) {
  const auto deadline = std::chrono::steady_clock::now() + limit;
  while (!condition()) {
    if (std::chrono::steady_clock::now() > deadline) return false;
    std::this_thread::sleep_for(std::chrono::microseconds{200});
  }
  return true;
}

}  // namespace mrd::test
