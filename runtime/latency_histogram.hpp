#pragma once

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>

#include "common/single_writer_counter.hpp"

namespace mrd::runtime {

// A fixed-bucket histogram of durations in nanoseconds, log-linear like HdrHistogram: exact
// below 64 ns, then 64 buckets per power of two (under 1.6 % relative width) up to 2^40 ns
// (18 min). Recording is a bucket index and single-writer counts: no allocation, no lock. One
// thread records; any thread may read (each count is exact, a read is not one instant).
class LatencyHistogram {
 public:
  static constexpr int kSubBits = 6;
  static constexpr std::uint64_t kSub = 1u << kSubBits;
  static constexpr int kMaxBits = 40;
  static constexpr std::size_t kBuckets = (kMaxBits - kSubBits + 1) * kSub;

  void record(std::int64_t ns) {
    const std::uint64_t v = ns < 0 ? 0u : static_cast<std::uint64_t>(ns);
    counts_[index(v)].add();
    total_.add();
    max_.raise_to(v);
  }

  [[nodiscard]] std::uint64_t count() const { return total_.get(); }
  [[nodiscard]] std::uint64_t max() const { return max_.get(); }
  // The smallest bucket upper edge below which a fraction q of the values lie (never above max).
  [[nodiscard]] std::uint64_t percentile(double q) const;
  [[nodiscard]] std::uint64_t bucket_count(std::size_t i) const { return counts_[i].get(); }

  static constexpr std::size_t index(std::uint64_t v) {
    if (v >= (std::uint64_t{1} << kMaxBits)) return kBuckets - 1;
    if (v < kSub) return static_cast<std::size_t>(v);
    const int shift = static_cast<int>(std::bit_width(v)) - 1 - kSubBits;
    return static_cast<std::size_t>(shift + 1) * kSub + static_cast<std::size_t>((v >> shift) - kSub);
  }
  // Largest value that falls in bucket i.
  static constexpr std::uint64_t upper_edge(std::size_t i) {
    if (i < kSub) return i;
    const std::size_t shift = i / kSub - 1;
    return ((kSub + i % kSub) << shift) + ((std::uint64_t{1} << shift) - 1);
  }

 private:
  std::array<SingleWriterCounter, kBuckets> counts_{};
  SingleWriterCounter total_;
  SingleWriterCounter max_;
};

inline std::uint64_t LatencyHistogram::percentile(double q) const {
  const std::uint64_t n = count();
  if (n == 0) return 0;
  // The rank of the q-quantile, 1-based, rounded up.
  auto rank = static_cast<std::uint64_t>(q * static_cast<double>(n));
  if (static_cast<double>(rank) < q * static_cast<double>(n)) ++rank;
  if (rank == 0) rank = 1;
  std::uint64_t seen = 0;
  for (std::size_t i = 0; i < kBuckets; ++i) {
    seen += bucket_count(i);
    if (seen >= rank) {
      const std::uint64_t edge = upper_edge(i);
      return edge < max() ? edge : max();
    }
  }
  return max();
}

}  // namespace mrd::runtime
