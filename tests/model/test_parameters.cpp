#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

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

// Legal but outside what real dampers show (model/typical_ranges.hpp): a warning each, naming the
// field and the range; the model stays usable. On the range's own ends: quiet.
TEST(Parameters, ValuesOutsideTheTypicalRangesAreWarningsNamingTheField) {
  DamperModel m;
  m.fluid.viscosity = 6.852856e-54;  // a fit whose viscous term collapsed (Dyke's, before the bounds)
  m.fluid.flow_index = 1.8;
  m.fluid.field_exponent = 0.22;
  m.geometry.sign_velocity_scale = 0.175;
  m.jiles_atherton.c = 0.97;
  m.jiles_atherton.k = 25.0 * m.jiles_atherton.a;
  const auto report = validate(m);
  EXPECT_TRUE(report.ok()) << report.to_string();
  std::vector<std::string> warned;
  for (const auto& i : report.issues())
    if (i.severity == ValidationIssue::Severity::kWarning) warned.push_back(i.field);
  EXPECT_EQ(warned, (std::vector<std::string>{"jiles_atherton.k", "jiles_atherton.c", "fluid.viscosity",
                                              "fluid.field_exponent", "fluid.flow_index", "geometry.sign_velocity_scale"}))
      << report.to_string();
  EXPECT_NE(report.to_string().find("fluid.viscosity: 6.85286e-54 is outside what MR fluids [Pa s] show (1e-06 to 1000)"),
            std::string::npos)
      << report.to_string();
  EXPECT_NE(report.to_string().find("jiles_atherton.k: k/a = 25 is outside"), std::string::npos) << report.to_string();
  DamperModel edges;
  edges.fluid.flow_index = 1.5;
  edges.fluid.field_exponent = 0.25;
  edges.geometry.sign_velocity_scale = 0.05;
  edges.jiles_atherton.c = 0.95;
  EXPECT_TRUE(validate(edges).issues().empty()) << validate(edges).to_string();
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
