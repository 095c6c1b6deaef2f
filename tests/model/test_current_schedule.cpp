#include "model/current_schedule.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace {

using mrd::model::CurrentSchedule;
using mrd::model::CurrentScheduleTable;

double fresh(double x) {  // a schedule with no history: the plain Table 4 lookup
  CurrentSchedule s;
  return s.update(x);
}

TEST(CurrentSchedule, Table4EdgesExactly) {
  const double above = 1e-12;
  EXPECT_EQ(fresh(0.0), 0.0);
  EXPECT_EQ(fresh(0.005), 0.0);
  EXPECT_EQ(fresh(0.005 + above), 0.2);
  EXPECT_EQ(fresh(0.010), 0.2);
  EXPECT_EQ(fresh(0.010 + above), 0.4);
  EXPECT_EQ(fresh(0.020), 0.4);
  EXPECT_EQ(fresh(0.020 + above), 0.6);
  EXPECT_EQ(fresh(0.030), 0.6);
  EXPECT_EQ(fresh(0.030 + above), 0.8);
  EXPECT_EQ(fresh(0.040), 0.8);
  EXPECT_EQ(fresh(0.040 + above), 1.2);
  EXPECT_EQ(fresh(0.100), 1.2);
}

TEST(CurrentSchedule, UsesMagnitudeOfDisplacement) {
  EXPECT_EQ(fresh(-0.005), 0.0);
  EXPECT_EQ(fresh(-0.0051), 0.2);
  EXPECT_EQ(fresh(-0.035), 0.8);
  EXPECT_EQ(fresh(-0.041), 1.2);
}

TEST(CurrentSchedule, RisesAtExactEdgesAndFallsOnlyPastTheBand) {
  CurrentSchedule s;  // band 0.2 mm
  EXPECT_EQ(s.update(0.0049), 0.0);
  EXPECT_EQ(s.update(0.0051), 0.2);
  EXPECT_EQ(s.update(0.0049), 0.2);    // inside the band: hold
  EXPECT_EQ(s.update(0.00481), 0.2);   // still inside
  EXPECT_EQ(s.update(0.0048), 0.0);    // at threshold - band: release
  EXPECT_EQ(s.update(0.0455), 1.2);    // rises several levels at once
  EXPECT_EQ(s.update(0.0150), 0.4);    // a big fall drops straight to its level
}

TEST(CurrentSchedule, NoisyLvdtOnAThresholdTogglesOnceNotEverySample) {
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 30e-6);  // 30 um RMS, band is 200 um
  CurrentSchedule banded;
  CurrentScheduleTable no_band_table;
  no_band_table.band = 0.0;
  CurrentSchedule unbanded(no_band_table);
  int banded_toggles = 0, unbanded_toggles = 0;
  double last_banded = banded.update(0.010), last_unbanded = unbanded.update(0.010);
  for (int i = 0; i < 10000; ++i) {
    const double x = 0.010 + noise(rng);
    const double b = banded.update(x), u = unbanded.update(x);
    banded_toggles += b != last_banded;
    unbanded_toggles += u != last_unbanded;
    last_banded = b;
    last_unbanded = u;
  }
  EXPECT_LE(banded_toggles, 1);
  EXPECT_GT(unbanded_toggles, 1000);  // what the band prevents
}

TEST(CurrentSchedule, NonFiniteDisplacementHoldsTheLevel) {
  CurrentSchedule s;
  s.update(0.025);
  EXPECT_EQ(s.update(std::numeric_limits<double>::quiet_NaN()), 0.6);
  EXPECT_EQ(s.update(std::numeric_limits<double>::infinity()), 0.6);
}

TEST(CurrentSchedule, ThresholdsAreConfigurable) {
  CurrentScheduleTable t;
  t.thresholds = {0.001, 0.002, 0.003, 0.004, 0.005};
  t.currents = {0.1, 0.2, 0.3, 0.4, 0.5, 0.6};
  t.band = 0.0;
  CurrentSchedule s(t);
  EXPECT_EQ(s.update(0.001), 0.1);
  EXPECT_EQ(s.update(0.0045), 0.5);
  EXPECT_EQ(s.update(0.006), 0.6);
}

}  // namespace
