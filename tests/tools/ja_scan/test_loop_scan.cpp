#include "tools/ja_scan/loop_scan.hpp"

#include <gtest/gtest.h>

namespace {

using mrd::model::JilesAthertonParams;
using mrd::tools::scan_loop;

// The paper's Table 1 read with a = 25.3 A/m and alpha = 8.43e-5 (docs/MODEL.md).
const JilesAthertonParams kTable1{1.3e6, 25.3, 8.43e-5, 66.6, 0.2};

TEST(Table1Finding, PhysicalBelowAbout70AmpsPerMetre) {
  for (const double H_max : {5.0, 20.0, 50.0, 68.0}) {
    EXPECT_TRUE(scan_loop(kTable1, H_max).physical()) << H_max;
  }
}

TEST(Table1Finding, RunsAwayFromAbout100AmpsPerMetreUp) {
  for (const double H_max : {100.0, 300.0, 1e3, 1e4, 1e5}) {
    EXPECT_FALSE(scan_loop(kTable1, H_max).physical()) << H_max;
  }
}

TEST(Table1Finding, LabelsAsPrintedGiveAlmostNoMagnetisation) {
  // alpha = 25.3 and beta (a) = 8.43e-5 A/m: Man saturates at any field, so the loop is a
  // step of height mu0*Ms; the literal reading is not a material, it is a switch.
  const JilesAthertonParams literal{1.3e6, 8.43e-5, 25.3, 66.6, 0.2};
  const auto report = mrd::model::validate(literal);
  EXPECT_FALSE(report.issues().empty());  // mean-field gain ~1e11: a warning at least
}

TEST(LoopScan, WellConditionedDefaultIsPhysicalAtEveryAmplitude) {
  for (const double H_max : {100.0, 1e3, 1e4, 1e5}) {
    const auto row = scan_loop(JilesAthertonParams{}, H_max);
    EXPECT_TRUE(row.physical()) << H_max;
  }
  const auto major = scan_loop(JilesAthertonParams{}, 3e4);
  EXPECT_LT(major.closure_error, 1e-6);
  EXPECT_LT(major.symmetry_error, 1e-4);
}

}  // namespace
