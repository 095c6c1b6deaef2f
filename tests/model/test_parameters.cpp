#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "model/current_schedule.hpp"
#include "model/damper_model.hpp"

namespace {

using mrd::model::DamperModel;
using mrd::model::JilesAthertonParams;
using mrd::ValidationIssue;

bool has_error(const mrd::ValidationReport& r, const std::string& field) {
  for (const auto& i : r.issues()) {
    if (i.field == field && i.severity == ValidationIssue::Severity::kError) return true;
  }
  return false;
}

TEST(Parameters, DefaultsAreValidAndQuiet) {
  const auto report = validate(DamperModel{});
  EXPECT_TRUE(report.ok());
  EXPECT_TRUE(report.issues().empty()) << report.to_string();
}

TEST(Parameters, ValuesOutsidePhysicsAreErrorsNamingTheField) {
  DamperModel m;
  m.jiles_atherton.Ms = -1.0;
  m.jiles_atherton.c = 1.0;
  m.geometry.gap = 0.0;
  m.fluid.volume_fraction = 0.9;
  const auto report = validate(m);
  EXPECT_FALSE(report.ok());
  EXPECT_TRUE(has_error(report, "jiles_atherton.Ms"));
  EXPECT_TRUE(has_error(report, "jiles_atherton.c"));
  EXPECT_TRUE(has_error(report, "geometry.gap"));
  EXPECT_TRUE(has_error(report, "fluid.volume_fraction"));
  EXPECT_NE(report.to_string().find("jiles_atherton.c: must lie in [0, 1)"), std::string::npos)
      << report.to_string();
}

TEST(Parameters, NanIsAnError) {
  JilesAthertonParams p;
  p.k = std::nan("");
  EXPECT_TRUE(has_error(validate(p), "k"));
}

TEST(Parameters, StrongMeanFieldCouplingIsAWarningNotAnError) {
  const JilesAthertonParams table1{1.3e6, 25.3, 8.43e-5, 66.6, 0.2};
  const auto report = validate(table1);
  EXPECT_TRUE(report.ok());
  ASSERT_EQ(report.issues().size(), 1u);
  EXPECT_EQ(report.issues()[0].severity, ValidationIssue::Severity::kWarning);
  EXPECT_EQ(report.issues()[0].field, "alpha");
}

TEST(Parameters, ScheduleThresholdsMustIncreaseAndBandFitBetweenThem) {
  mrd::model::CurrentScheduleTable t;
  t.thresholds[2] = t.thresholds[1];
  EXPECT_TRUE(has_error(validate(t), "thresholds[2]"));
  mrd::model::CurrentScheduleTable wide;
  wide.band = 0.006;
  EXPECT_TRUE(has_error(validate(wide), "band"));
}

}  // namespace
