#include "common/single_writer_counter.hpp"

#include <gtest/gtest.h>

#include <thread>

namespace {

TEST(SingleWriterCounter, AddsAndKeepsTheMaximum) {
  mrd::SingleWriterCounter n;
  EXPECT_EQ(n.get(), 0u);
  n.add();
  n.add(41);
  EXPECT_EQ(n.get(), 42u);
  n.raise_to(7);
  EXPECT_EQ(n.get(), 42u);
  n.raise_to(100);
  EXPECT_EQ(n.get(), 100u);
}

// One writer, one reader: every value the reader sees is one the writer stored, never torn or
// going backwards, and the last read after the join is exact.
TEST(SingleWriterCounter, AReaderSeesAMonotonicCountFromOneWriter) {
  mrd::SingleWriterCounter n;
  constexpr std::uint64_t kAdds = 200000;
  std::thread writer([&] {
    for (std::uint64_t i = 0; i < kAdds; ++i) n.add();
  });
  std::uint64_t last = 0;
  bool monotonic = true;
  while (last < kAdds) {
    const std::uint64_t now = n.get();
    monotonic = monotonic && now >= last;
    last = now;
  }
  writer.join();
  EXPECT_TRUE(monotonic);
  EXPECT_EQ(n.get(), kAdds);
}

}  // namespace
