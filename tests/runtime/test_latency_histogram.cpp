#include "runtime/latency_histogram.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <random>

#include "runtime/loop_report.hpp"

namespace {

using mrd::runtime::LatencyHistogram;

TEST(LatencyHistogram, BucketsAreContiguousAndNarrow) {
  for (std::uint64_t v = 0; v < 200000; v += 7) {
    const auto i = LatencyHistogram::index(v);
    EXPECT_LE(v, LatencyHistogram::upper_edge(i)) << v;
    if (i > 0) {
      EXPECT_GT(v, LatencyHistogram::upper_edge(i - 1)) << v;
    }
    // Bucket width under 1/64 of the value: percentiles within 1.6 %.
    EXPECT_LE(LatencyHistogram::upper_edge(i) - v, v / 64 + 1) << v;
  }
  EXPECT_EQ(LatencyHistogram::index(~0ull), LatencyHistogram::kBuckets - 1);
}

TEST(LatencyHistogram, PercentilesOfAKnownDistribution) {
  auto h = std::make_unique<LatencyHistogram>();
  // 1..100000 ns, each once: p50 = 50000, p99 = 99000, p99.9 = 99900, max 100000.
  for (int v = 1; v <= 100000; ++v) h->record(v);
  EXPECT_EQ(h->count(), 100000u);
  EXPECT_EQ(h->max(), 100000u);
  EXPECT_NEAR(static_cast<double>(h->percentile(0.5)), 50000.0, 50000.0 / 64);
  EXPECT_NEAR(static_cast<double>(h->percentile(0.99)), 99000.0, 99000.0 / 64);
  EXPECT_NEAR(static_cast<double>(h->percentile(0.999)), 99900.0, 99900.0 / 64);
  EXPECT_EQ(h->percentile(1.0), 100000u);
  EXPECT_GE(h->percentile(0.5), 50000u);  // never optimistic: the bucket's upper edge
}

TEST(LatencyHistogram, RareOutlierShowsInP999AndMaxOnly) {
  auto h = std::make_unique<LatencyHistogram>();
  for (int i = 0; i < 9990; ++i) h->record(5000);
  for (int i = 0; i < 10; ++i) h->record(800000);  // 0.1 % at 800 us
  EXPECT_LE(h->percentile(0.99), 5100u);
  EXPECT_LE(h->percentile(0.999), 5100u);  // exactly the 99.9th value is still 5 us
  h->record(800000);
  EXPECT_GE(h->percentile(0.999), 790000u);
  EXPECT_EQ(h->max(), 800000u);
  EXPECT_EQ(h->percentile(0.0), h->percentile(0.5));
  const std::string text = mrd::runtime::format_histogram("t", *h);
  EXPECT_NE(text.find("5 ..      10 us: 9990"), std::string::npos) << text;
  EXPECT_NE(text.find("500 ..    1000 us: 11"), std::string::npos) << text;
}

TEST(LatencyHistogram, NegativeDurationsCountAsZero) {
  LatencyHistogram h;
  h.record(-5);
  EXPECT_EQ(h.bucket_count(0), 1u);
  EXPECT_EQ(LatencyHistogram{}.percentile(0.5), 0u);
}

}  // namespace
