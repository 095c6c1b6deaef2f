// The soak (docs/RELIABILITY.md): the loop, the simulated plant and random faults for many
// cycles faster than real time. Soak.Short runs in the normal suite; Soak.TenMillionCycles
// carries the `slow` label (ctest -L slow).
#include <gtest/gtest.h>

#include <cstdio>

#include "tests/firmware/soak.hpp"

namespace {

void print(const mrd::test::SoakFigures& f) {
  std::printf(
      "soak: %llu cycles in %.1f s (%.0f cycles/s), %llu faults, %llu SAFE entries, %llu "
      "recoveries, longest recovery %llu cycles, stuck in SAFE %llu cycles, %llu latches cleared\n"
      "soak: max |M| observer %.4g A/m, max |B| observer %.4g T, plant %.4g T, non-finite %llu\n"
      "soak: resident %ld KiB after warm-up, at most %ld KiB after (+%ld KiB)\n"
      "soak: telemetry %llu offered = %llu written + %llu dropped\n",
      static_cast<unsigned long long>(f.cycles), f.seconds, static_cast<double>(f.cycles) / f.seconds,
      static_cast<unsigned long long>(f.faults), static_cast<unsigned long long>(f.safe_entries),
      static_cast<unsigned long long>(f.recoveries), static_cast<unsigned long long>(f.longest_recovery),
      static_cast<unsigned long long>(f.stuck_in_safe), static_cast<unsigned long long>(f.latches),
      f.max_abs_M_observer, f.max_abs_B_observer,
      f.max_abs_B_plant, static_cast<unsigned long long>(f.non_finite), f.rss_after_warmup_kib,
      f.rss_max_kib, f.rss_max_kib - f.rss_after_warmup_kib,
      static_cast<unsigned long long>(f.telemetry_offered),
      static_cast<unsigned long long>(f.telemetry_written),
      static_cast<unsigned long long>(f.telemetry_dropped));
}

void check(const mrd::test::SoakFigures& f, std::uint64_t cycles) {
  print(f);
  EXPECT_EQ(f.cycles, cycles);
  EXPECT_GT(f.faults, 0u);
  EXPECT_GT(f.safe_entries, 0u);  // the faults did bite
  // Every SAFE spell ended in RUN, but perhaps the last one, if a fault came near the end.
  EXPECT_LE(f.recoveries, f.safe_entries);
  EXPECT_GE(f.recoveries + 1, f.safe_entries);
  EXPECT_EQ(f.stuck_in_safe, 0u);
  EXPECT_EQ(f.non_finite, 0u);
  // Bounded: |M| within Ms, B below a few tesla.
  EXPECT_LE(f.max_abs_M_observer, f.Ms);
  EXPECT_LT(f.max_abs_B_observer, 3.0);
  EXPECT_LT(f.max_abs_B_plant, 3.0);
  // No growth after warm-up beyond allocator noise.
  EXPECT_GT(f.rss_after_warmup_kib, 0);
  EXPECT_LT(f.rss_max_kib - f.rss_after_warmup_kib, 2048);
  EXPECT_EQ(f.telemetry_offered, f.cycles);
  EXPECT_EQ(f.telemetry_written + f.telemetry_dropped, f.cycles);
}

TEST(Soak, TwoHundredThousandCycles) { check(mrd::test::run_soak(200'000, 1), 200'000); }

TEST(Soak, TenMillionCycles) { check(mrd::test::run_soak(10'000'000, 2), 10'000'000); }

}  // namespace
