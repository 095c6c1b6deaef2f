#include "hal/spsc_ring.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <thread>

#include "hal/latest_mailbox.hpp"

namespace {

using mrd::hal::LatestMailbox;
using mrd::hal::SpscRing;

TEST(SpscRing, KeepsFifoOrderAndRefusesWhenFull) {
  SpscRing<int, 4> ring;
  EXPECT_FALSE(ring.try_pop().has_value());
  int pushed = 0;
  while (ring.try_push(pushed)) ++pushed;
  EXPECT_GE(pushed, 3);  // boost keeps one slot free to tell full from empty
  for (int i = 0; i < pushed; ++i) EXPECT_EQ(ring.try_pop(), i);
  EXPECT_FALSE(ring.try_pop().has_value());
}

TEST(SpscRing, PopLatestDrainsAndKeepsNewest) {
  SpscRing<int, 8> ring;
  EXPECT_FALSE(ring.pop_latest().has_value());
  for (int i = 1; i <= 5; ++i) ASSERT_TRUE(ring.try_push(i));
  EXPECT_EQ(ring.pop_latest(), 5);
  EXPECT_EQ(ring.size_approx(), 0u);
}

TEST(SpscRing, TwoThreadsSeeEveryItemInOrder) {
  SpscRing<std::uint32_t, 64> ring;
  constexpr std::uint32_t kCount = 200000;
  std::thread producer([&ring] {
    for (std::uint32_t i = 0; i < kCount;) {
      if (ring.try_push(i)) ++i;
      else std::this_thread::yield();
    }
  });
  std::uint32_t expected = 0;
  while (expected < kCount) {
    if (auto v = ring.try_pop()) {
      ASSERT_EQ(*v, expected);
      ++expected;
    } else {
      std::this_thread::yield();
    }
  }
  producer.join();
}

TEST(LatestMailbox, ReaderGetsOnlyTheNewestAndOnlyOnce) {
  LatestMailbox<double> box;
  EXPECT_FALSE(box.take().has_value());
  box.publish(1.0);
  box.publish(2.0);
  EXPECT_EQ(box.take(), 2.0);
  EXPECT_FALSE(box.take().has_value());
  box.publish(3.0);
  EXPECT_EQ(box.take(), 3.0);
}

struct Pair {
  std::uint64_t a;
  std::uint64_t b;
};

TEST(LatestMailbox, ConcurrentValuesAreNeverTornAndNeverGoBack) {
  LatestMailbox<Pair> box;
  constexpr std::uint64_t kLast = 200000;
  std::thread writer([&box] {
    for (std::uint64_t i = 1; i <= kLast; ++i) box.publish({i, ~i});
  });
  std::uint64_t seen = 0;
  while (seen < kLast) {
    if (auto p = box.take()) {
      ASSERT_EQ(p->b, ~p->a) << "torn value";
      ASSERT_GT(p->a, seen) << "went back in time";
      seen = p->a;
    } else {
      std::this_thread::yield();
    }
  }
  writer.join();
}

}  // namespace
