// mrd-hil-report on telemetry as loggers write it (issue 27, item 5): a repeated row counts once,
// conflicts and empty or nan cells are set aside with their line, a gap is found and dated, and
// no figure is drawn across a gap of either file.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "record/csv.hpp"
#include "record/recorded_run.hpp"
#include "telemetry/csv_telemetry_writer.hpp"
#include "tools/hil/force_join.hpp"
#include "tools/hil/telemetry_csv.hpp"

namespace {

using mrd::tools::parse_telemetry_csv;

// One row as the controller writes it: cycle, time, displacement, force and state; the rest 0.
std::string row(std::uint64_t cycle, double t, double x_mm = 1.0, double force_N = 0.5,
                const char* state = "RUN") {
  char line[200];
  std::snprintf(line, sizeof line, "%llu,%.6f,%.4f,fresh,nan,0,0,0,0,0,0,%.5g,%s,none,0,1,0,0\n",
                static_cast<unsigned long long>(cycle), t, x_mm, force_N, state);
  return line;
}

// Rows of cycles [from, to) at 1 kHz.
std::string rows(std::uint64_t from, std::uint64_t to, const char* state = "RUN") {
  std::string out;
  for (std::uint64_t c = from; c < to; ++c) out += row(c, 1e-3 * static_cast<double>(c), 1.0, 0.5, state);
  return out;
}

const std::string kHeader = mrd::telemetry::CsvTelemetryWriter::header();

TEST(TelemetryFaults, ARepeatedRowIsKeptOnceAndCounted) {
  // Rows at lines 2..11; cycle 5 (line 7) written again at line 8.
  const auto log = parse_telemetry_csv(kHeader + rows(0, 6) + row(5, 0.005) + rows(6, 10), "t.csv");
  ASSERT_EQ(log.rows.size(), 10u);
  ASSERT_EQ(log.set_aside_rows.size(), 1u);
  EXPECT_EQ(log.set_aside_rows[0].reason, "duplicate");
  EXPECT_EQ(log.set_aside_rows[0].line, 8u);
  EXPECT_TRUE(log.gaps.empty());
  EXPECT_NEAR(log.record_rate, 1000.0, 1e-6);
}

TEST(TelemetryFaults, ConflictsAndEmptyOrNanCellsAreSetAsideWithTheirLineAndColumn) {
  const std::string text = kHeader + rows(0, 4) +                    // lines 2-5
                           row(3, 0.003, 2.0) +                      // 6: time and cycle of line 5, other values
                           row(4, 0.001) +                           // 7: time goes back
                           rows(4, 6) +                              // 8-9
                           "6,0.006000,1.0000,fresh,nan,0,0,0,0,0,0,,RUN,none,0,1,0,0\n"      // 10: empty force
                           "7,0.007000,nan,fresh,nan,0,0,0,0,0,0,0.5,RUN,none,0,1,0,0\n"      // 11: nan displacement
                           "8,0.008000,1.0000,fresh,nan,0,0,0,0,0,0,0.5,RUN,none,nan,1,0,0\n" // 12: nan count
                           + row(9, 0.009) +                         // 13
                           row(9, 0.010);                            // 14: a cycle that does not advance
  const auto log = parse_telemetry_csv(text, "t.csv");
  ASSERT_EQ(log.rows.size(), 7u);  // cycles 0-5 and 9; measured_current's nan is the writer's own
  EXPECT_TRUE(std::isnan(log.rows[0].measured_current));
  const std::vector<std::tuple<std::string, std::size_t, std::string>> expected = {
      {"time_conflict", 6, "time_s"}, {"time_conflict", 7, "time_s"}, {"non_finite", 10, "force_N"},
      {"non_finite", 11, "displacement_mm"}, {"non_finite", 12, "overruns"}, {"time_conflict", 14, "cycle"}};
  ASSERT_EQ(log.set_aside_rows.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(log.set_aside_rows[i].reason, std::get<0>(expected[i])) << i;
    EXPECT_EQ(log.set_aside_rows[i].line, std::get<1>(expected[i])) << i;
    EXPECT_EQ(log.set_aside_rows[i].column, std::get<2>(expected[i])) << i;
  }
}

TEST(TelemetryFaults, NothingUsableLeftOrAnUnknownHeaderIsAnErrorNamingFileAndLine) {
  const std::string empty_times = "0,,1.0000,fresh,nan,0,0,0,0,0,0,0.5,RUN,none,0,1,0,0\n";
  try {
    (void)parse_telemetry_csv(kHeader + empty_times + empty_times, "t.csv");
    ADD_FAILURE() << "a file without a usable row was read";
  } catch (const mrd::record::InputError& e) {
    EXPECT_STREQ(e.what(), "t.csv:1: no telemetry row left (set aside: 2 non_finite (first at line 2))");
  }
  EXPECT_THROW((void)parse_telemetry_csv("cycle,time_s,force_N\n" + rows(0, 3), "t.csv"), mrd::record::InputError);
}

TEST(TelemetryFaults, AGapIsFoundByItsMissingCyclesAndATransitionInItIsDatedByIt) {
  // Cycles 340-399 after 0-39: 300 records lost; the supervisor went INIT -> RUN in between.
  const auto log = parse_telemetry_csv(kHeader + rows(0, 40, "INIT") + rows(340, 400), "t.csv");
  ASSERT_EQ(log.gaps.size(), 1u);
  EXPECT_EQ(log.gaps[0].missing, 300u);
  EXPECT_NEAR(log.gaps[0].start, 0.039, 1e-9);
  EXPECT_NEAR(log.gaps[0].duration(), 0.301, 1e-9);
  EXPECT_EQ(to_string(log.gaps[0], log.rows), "0.301 s from 0.039 s (lines 41-42): 300 records missing");
  EXPECT_NEAR(log.record_rate, 1000.0, 1e-6);  // the gap is no slower logger
  const auto changes = mrd::tools::state_changes(log.rows, log.gaps);
  ASSERT_EQ(changes.size(), 1u);
  ASSERT_TRUE(changes[0].within.has_value());
  EXPECT_EQ(to_string(changes[0]), "INIT -> RUN (none) within a gap: after 0.039 s, by cycle 340 (0.340 s)");
  // Decimated telemetry (every 10th cycle) has no gap, and a late loop (a long step with no
  // cycle missing) is one that says so; a transition on the late cycle is dated by its row.
  std::string decimated = kHeader;
  for (std::uint64_t c = 0; c < 200; c += 10)
    decimated += row(c, 1e-3 * static_cast<double>(c) + (c >= 100 ? 0.02 : 0.0), 1.0, 0.5, c >= 100 ? "SAFE" : "RUN");
  const auto late = parse_telemetry_csv(decimated, "d.csv");
  ASSERT_EQ(late.gaps.size(), 1u);
  EXPECT_EQ(late.gaps[0].missing, 0u);
  EXPECT_NE(to_string(late.gaps[0], late.rows).find("no record missing"), std::string::npos);
  const auto trip = mrd::tools::state_changes(late.rows, late.gaps);
  ASSERT_EQ(trip.size(), 2u);  // INIT -> RUN at the first row, RUN -> SAFE on the late cycle
  EXPECT_FALSE(trip[1].within.has_value());
}

// A plant log of 2 s at 1 kHz, its force a 2 Hz sine, and the controller's telemetry at the
// same times with an observer that got the force exactly: the error is 0 wherever both are.
mrd::record::RecordedRun plant_log(double lost_from, double lost_to) {
  mrd::record::RecordedRun run;
  run.name = "plant.csv";
  for (int i = 0; i <= 2000; ++i) {
    const double t = 1e-3 * i;
    if (t >= lost_from && t < lost_to) continue;
    run.time.push_back(t);
    run.displacement.push_back(0.01 * std::sin(2.0 * std::numbers::pi * t));
    run.coil.push_back(0.0);
    run.force.push_back(1000.0 * std::sin(4.0 * std::numbers::pi * t));
  }
  run.sample_rate = mrd::record::nominal_sample_rate(run.time);
  return run;
}

TEST(TelemetryFaults, NoForceErrorIsTakenAcrossAGapInThePlantLog) {
  std::vector<mrd::tools::TelemetryRow> telemetry;
  for (int i = 0; i <= 2000; ++i) {
    mrd::tools::TelemetryRow r;
    r.cycle = static_cast<std::uint64_t>(i);
    r.time = 1e-3 * i;
    r.displacement = 0.01 * std::sin(2.0 * std::numbers::pi * r.time);
    r.force = 1000.0 * std::sin(4.0 * std::numbers::pi * r.time);
    r.state = mrd::control::SupervisorState::kRun;
    telemetry.push_back(r);
  }
  const auto whole = mrd::tools::join_force(telemetry, plant_log(9.0, 9.0), 0.0);
  EXPECT_EQ(whole.rows, 2001u);
  EXPECT_LT(whole.rms_error, 1e-9);
  // 0.3 s lost from 0.8 s: a straight line across it is off the sine by up to 1.5 kN (hundreds
  // of newtons RMS over the joined rows); the rows in the gap are left out instead.
  const auto broken = mrd::tools::join_force(telemetry, plant_log(0.8, 1.1), 0.0);
  EXPECT_NEAR(static_cast<double>(broken.in_plant_gaps), 300.0, 1.0);  // 0.800-1.099 s, the edges by the lag's rounding
  EXPECT_EQ(broken.rows + broken.in_plant_gaps, 2001u);
  EXPECT_LT(broken.rms_error, 1e-9);
  EXPECT_NEAR(broken.lag, 0.0, 1e-12);
  ASSERT_EQ(broken.plant_gaps.size(), 1u);
  EXPECT_NEAR(broken.plant_gaps[0].first, 0.799, 1e-9);
  EXPECT_NEAR(broken.plant_gaps[0].second, 1.1, 1e-9);
}

}  // namespace
