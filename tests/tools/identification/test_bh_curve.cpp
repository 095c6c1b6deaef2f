#include "tools/identification/bh_curve.hpp"

#include <gtest/gtest.h>

#include <string>

namespace {

using mrd::tools::BHCurveOptions;
using mrd::record::InputError;
using mrd::tools::parse_bh_curve;

// The error message, or "" when the text parses.
std::string error_of(const std::string& text, const BHCurveOptions& options = {}) {
  try {
    parse_bh_curve(text, "loops.csv", options);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

const std::string kTwoLoops =
    "H1_A_per_m,B1_T,H2_kA_per_m,B2_mT\n"
    "10,0.5,0.02,800\n"
    "0,0.2,0,300\n"
    "-10,-0.5,-0.02,-800\n"
    "0,-0.2,0,-300\n";

TEST(BHCurveReader, PairsColumnsIntoLoopsAndConvertsUnits) {
  const auto curve = parse_bh_curve(kTwoLoops, "loops.csv");
  ASSERT_EQ(curve.loops.size(), 2u);
  EXPECT_EQ(curve.points(), 8u);
  EXPECT_DOUBLE_EQ(curve.loops[1].H[0], 20.0);  // 0.02 kA/m
  EXPECT_DOUBLE_EQ(curve.loops[1].B[0], 0.8);   // 800 mT
  EXPECT_DOUBLE_EQ(curve.max_abs_H(), 20.0);
}

TEST(BHCurveReader, LoopColumnSplitsOnePair) {
  const auto curve = parse_bh_curve(
      "loop,H_A_per_m,B_T\n1,1,0.1\n1,0,0\n1,-1,-0.1\n1,0,0\n2,2,0.2\n2,0,0\n2,-2,-0.2\n2,0,0\n",
      "x.csv");
  ASSERT_EQ(curve.loops.size(), 2u);
  EXPECT_DOUBLE_EQ(curve.loops[1].H[0], 2.0);
}

TEST(BHCurveReader, ShorterLoopEndsWithEmptyCellsAndTrailingCommas) {
  const auto curve = parse_bh_curve(
      "H1_A_per_m,B1_T,H2_A_per_m,B2_T,\n1,1,1,1,\n2,2,2,2,\n3,3,3,3,\n4,4,4,4,\n5,5,,,\n", "x.csv");
  EXPECT_EQ(curve.loops[0].H.size(), 5u);
  EXPECT_EQ(curve.loops[1].H.size(), 4u);
}

TEST(BHCurveReader, BICurveNeedsTheCircuitAndUsesEquation9) {
  const std::string text = "I_A,B_T\n1,0.1\n0,0\n-1,-0.1\n0,0\n";
  EXPECT_NE(error_of(text).find("needs the magnetic circuit"), std::string::npos);
  BHCurveOptions options;
  options.has_circuit = true;
  options.circuit = {600.0, 0.06};
  const auto curve = parse_bh_curve(text, "bi.csv", options);
  EXPECT_DOUBLE_EQ(curve.loops[0].H[0], 10000.0);  // 600 * 1 A / 0.06 m
}

TEST(BHCurveReader, BadNumberNamesFileLineAndColumn) {
  std::string text = kTwoLoops;
  text.replace(text.find("-0.5"), 4, "abc");
  EXPECT_EQ(error_of(text), "loops.csv:4: column 'B1_T': 'abc' is not a finite number");
}

TEST(BHCurveReader, NonFiniteValuesAreErrors) {
  std::string text = kTwoLoops;
  text.replace(text.find("0.2,0,300"), 3, "nan");
  EXPECT_EQ(error_of(text), "loops.csv:3: column 'B1_T': 'nan' is not a finite number");
}

// Found by fuzz_bh_curve (docs/RELIABILITY.md): a loop index past the range of long was
// undefined behaviour, and finite values could become infinite fields once converted.
TEST(BHCurveReader, HugeLoopIndicesAndValuesOutsidePhysicsAreErrors) {
  EXPECT_EQ(error_of("loop,H_A_per_m,B_T\n1e300,1,1\n"),
            "loops.csv:2: column 'loop': loop index must be an integer of at most 9 digits");
  EXPECT_EQ(error_of("H_kA_per_m,B_T\n1e308,1\n"),
            "loops.csv:2: column 'H_kA_per_m': '1e308' is inf A/m, outside physics (at most 1e+09 A/m)");
  EXPECT_EQ(error_of("H_A_per_m,B_mT\n1,2e5\n"),
            "loops.csv:2: column 'B_mT': '2e5' is 200 T, outside physics (at most 100 T)");
  BHCurveOptions circuit;
  circuit.has_circuit = true;
  EXPECT_NE(error_of("I_A,B_T\n1e300,1\n", circuit).find("outside physics"), std::string::npos);
}

TEST(BHCurveReader, ALineOverTheLengthCapIsAnError) {
  std::string text = "H_A_per_m,B_T\n1,";
  text.append(mrd::record::kMaxLineLength, '1');
  EXPECT_EQ(error_of(text),
            "loops.csv:2: line longer than 1048576 bytes: not a text file this reader takes");
}

TEST(BHCurveReader, MalformedFilesGetOneClearError) {
  EXPECT_EQ(error_of(""), "loops.csv:0: empty file: expected a header with H and B columns");
  EXPECT_NE(error_of("H_A_per_m,X\n1,2\n").find("column 'X': unknown column"), std::string::npos);
  EXPECT_NE(error_of("H1_A_per_m,B1_T,H2_A_per_m\n1,2,3\n").find("must come in pairs"),
            std::string::npos);
  EXPECT_NE(error_of("B_T\n1\n").find("no field column"), std::string::npos);
  EXPECT_NE(error_of("H_A_per_m,B_T\n1,2,3\n").find("loops.csv:2: 3 fields, but the header has 2"),
            std::string::npos);
  EXPECT_NE(error_of("H_A_per_m,B_T\n1,\n").find("column 'B_T': empty cell"), std::string::npos);
  EXPECT_NE(error_of("H_A_per_m,B_T\n1,1\n2,2\n").find("at least 4"), std::string::npos);
  EXPECT_NE(error_of("H1_A_per_m,B1_T,H2_A_per_m,B2_T\n1,1,,\n2,2,2,2\n")
                .find("value after the loop ended"),
            std::string::npos);
}

TEST(BHCurveReader, MissingFileIsAnErrorNotACrash) {
  EXPECT_THROW(mrd::tools::read_bh_curve("/nonexistent/loops.csv"), InputError);
}

TEST(BHCurveReader, ReadsTheMeasuredFerriteLoops) {
  const auto curve =
      mrd::tools::read_bh_curve(MRD_DATA_DIR "/bh-loops/szewczyk-jamodel/MnZn_ferrite_loops.csv");
  ASSERT_EQ(curve.loops.size(), 4u);
  EXPECT_EQ(curve.points(), 4u * 129u);
  EXPECT_NEAR(curve.max_abs_H(), 80.0, 0.5);
}

}  // namespace
