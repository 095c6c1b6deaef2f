#include "record/run_columns.hpp"

#include <gtest/gtest.h>

#include <string>

#include "tests/record/input_error_of.hpp"

namespace {

using mrd::record::column_unit;
using mrd::record::parse_column_mapping;
using mrd::record::RunQuantity;

std::string mapping_error(const std::string& text) {
  return mrd::record::testing::input_error_of([&] { (void)parse_column_mapping(text); });
}

TEST(RunColumns, UnitNamesConvertToSI) {
  EXPECT_DOUBLE_EQ(column_unit("displacement_cm").unit->to_internal(2.0), 0.02);
  EXPECT_DOUBLE_EQ(column_unit("force_kN").unit->to_internal(1.5), 1500.0);
  EXPECT_DOUBLE_EQ(column_unit("current_mA").unit->to_internal(250.0), 0.25);
  EXPECT_DOUBLE_EQ(column_unit("velocity_cm_s").unit->to_internal(3.0), 0.03);
  EXPECT_DOUBLE_EQ(column_unit("time_ms").unit->to_internal(5.0), 0.005);
  EXPECT_DOUBLE_EQ(column_unit("temperature_K").unit->to_internal(300.0), 300.0 - 273.15);
  EXPECT_EQ(column_unit("voltage_V").unit->quantity, RunQuantity::kVoltage);
  EXPECT_EQ(column_unit("B_mT").unit->quantity, RunQuantity::kFluxDensity);
}

TEST(RunColumns, UnknownUnitAndUnknownColumnAreDifferentMistakes) {
  EXPECT_EQ(column_unit("displacement_in").error,
            "unknown unit 'in' for displacement; expected displacement_m, displacement_mm or "
            "displacement_cm");
  EXPECT_EQ(column_unit("force").error, "no unit for force; expected force_N or force_kN");
  EXPECT_EQ(column_unit("pressure_Pa").error.rfind("unknown column; expected time_s, time_ms, ", 0),
            0u);
}

TEST(RunColumns, MappingByHeaderName) {
  const auto m = parse_column_mapping("t=time_s,D=displacement_cm,Y=voltage_V,F=force_N");
  EXPECT_FALSE(m.by_position);
  ASSERT_EQ(m.entries.size(), 4u);
  EXPECT_EQ(m.entries[1].source, "D");
  EXPECT_EQ(m.entries[1].unit.name, "displacement_cm");
}

TEST(RunColumns, MappingByPositionAndSignFlip) {
  const auto m = parse_column_mapping("1=time_s, 2=displacement_mm, 4=-force_N");
  EXPECT_TRUE(m.by_position);
  EXPECT_EQ(m.entries[2].position, 4u);
  EXPECT_DOUBLE_EQ(m.entries[2].unit.to_internal(10.0), -10.0);
}

TEST(RunColumns, MappingErrorsNameTheEntry) {
  EXPECT_EQ(mapping_error(""), "--columns: no columns mapped");
  EXPECT_EQ(mapping_error("t=time_s,D"),
            "--columns: 'D': expected SOURCE=UNIT, e.g. D=displacement_cm or 2=displacement_mm");
  EXPECT_EQ(mapping_error("D=displacement_ft"),
            "--columns: 'D=displacement_ft': unknown unit 'ft' for displacement; expected "
            "displacement_m, displacement_mm or displacement_cm");
  EXPECT_EQ(mapping_error("0=time_s"), "--columns: '0=time_s': positions count from 1");
  EXPECT_EQ(mapping_error("1=time_s,D=displacement_cm"),
            "--columns: mixes positions (1=...) and header names (t=...); use one kind");
  EXPECT_EQ(mapping_error("t=time_s,t=time_ms"), "--columns: 't=time_ms': 't' is mapped twice");
  EXPECT_EQ(mapping_error("D=displacement_cm,E=displacement_mm"),
            "--columns: 'E=displacement_mm': a second displacement column (the first is 'D')");
}

}  // namespace
