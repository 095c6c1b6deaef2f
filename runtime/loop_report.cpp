#include "runtime/loop_report.hpp"

#include <array>
#include <cstdio>

namespace mrd::runtime {

namespace {
double us(std::uint64_t ns) { return static_cast<double>(ns) * 1e-3; }
}  // namespace

std::string format_percentiles(const char* name, const LatencyHistogram& h) {
  char line[256];
  std::snprintf(line, sizeof line,
                "%-22s p50 %8.1f  p99 %8.1f  p99.9 %8.1f  max %8.1f  (n = %llu)\n", name,
                us(h.percentile(0.50)), us(h.percentile(0.99)), us(h.percentile(0.999)), us(h.max()),
                static_cast<unsigned long long>(h.count()));
  return line;
}

std::string format_histogram(const char* name, const LatencyHistogram& h) {
  // Bin edges in ns; a value goes in the first bin whose edge it is below.
  static constexpr std::array<std::uint64_t, 14> kEdges{1'000,   2'000,   5'000,   10'000,  20'000,
                                                        50'000,  100'000, 200'000, 500'000, 1'000'000,
                                                        2'000'000, 5'000'000, 10'000'000, ~0ull};
  std::array<std::uint64_t, kEdges.size()> bins{};
  for (std::size_t i = 0; i < LatencyHistogram::kBuckets; ++i) {
    const std::uint64_t n = h.bucket_count(i);
    if (n == 0) continue;
    std::size_t b = 0;
    while (LatencyHistogram::upper_edge(i) >= kEdges[b]) ++b;
    bins[b] += n;
  }
  std::string out = std::string(name) + " histogram:\n";
  std::uint64_t lo = 0;
  for (std::size_t b = 0; b < kEdges.size(); ++b) {
    if (bins[b] > 0) {
      char line[128];
      if (kEdges[b] == ~0ull) {
        std::snprintf(line, sizeof line, "  >= %7.0f us: %llu\n", us(lo),
                      static_cast<unsigned long long>(bins[b]));
      } else {
        std::snprintf(line, sizeof line, "  %7.0f .. %7.0f us: %llu\n", us(lo), us(kEdges[b]),
                      static_cast<unsigned long long>(bins[b]));
      }
      out += line;
    }
    lo = kEdges[b];
  }
  return out;
}

std::string format_loop_statistics(const LoopStatistics& stats) {
  std::string out = "cycles " + std::to_string(stats.cycles.get()) + ", overruns " +
                    std::to_string(stats.overruns.get()) + "\n";
  out += format_percentiles("wake-up latency [us]", stats.wake_latency);
  out += format_percentiles("execution time [us]", stats.execution);
  return out;
}

}  // namespace mrd::runtime
