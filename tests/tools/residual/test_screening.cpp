// Screening before the fit: each sensor fault, injected by the test into a clean simulated run,
// is found on its channel with its reason; clean simulated and measured runs lose nothing; and a
// run whose last half second is faulted fits like the unfaulted run only with the screening on.
#include "tools/residual/screening.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdint>
#include <numbers>
#include <string>

#include "record/run_reader.hpp"
#include "record/run_columns.hpp"
#include "tests/tools/residual/residual_test_support.hpp"
#include "tools/residual/residual_report.hpp"

namespace {

using namespace mrd::tools;

mrd::record::RecordedRun clean_run(RunProfile profile = RunProfile::kTable4, const char* damper = "1kN") {
  return residual_testing::simulated_recorded_run(profile, damper, {}, 4.0);
}

bool has_span(const Screening& s, const std::string& channel, ScreenReason reason, double from, double to) {
  return std::ranges::any_of(s.spans, [&](const ScreenedSpan& span) {
    return span.channel == channel && span.reason == reason && span.start_s <= to && span.end_s >= from;
  });
}

std::string describe(const Screening& s) {
  std::string out;
  for (const ScreenedSpan& span : s.spans)
    out += span.channel + " " + std::string(to_string(span.reason)) + " " + std::to_string(span.start_s) + "-" +
           std::to_string(span.end_s) + "\n";
  return out;
}

// The last `seconds` of the run: the load cell clipped at 90 % of its peak, the LVDT stuck where
// it was when the fault began (an end stop, or a frozen converter).
mrd::record::RecordedRun with_faulted_end(mrd::record::RecordedRun run, double seconds) {
  const auto [lo, hi] = std::minmax_element(run.force.begin(), run.force.end());
  const double clip = 0.9 * std::max(*hi, -*lo);
  const double start = run.time.back() - seconds;
  std::size_t first = run.size();
  for (std::size_t i = 0; i < run.size(); ++i) {
    if (run.time[i] < start) continue;
    if (first == run.size()) first = i;
    run.force[i] = std::clamp(run.force[i], -clip, clip);
    run.displacement[i] = run.displacement[first];
  }
  return run;
}

// A 1 kHz run whose force climbs at `slope` N per sample to a peak it holds for `plateau`
// samples, then falls at the same slope; elsewhere it steps by 1 N (its resolution q). The
// displacement moves throughout.
mrd::record::RecordedRun peaked_run(std::size_t plateau, double slope) {
  mrd::record::RecordedRun run;
  run.sample_rate = 1000.0;
  double f = 0.0;
  const auto add = [&](double step, std::size_t n) {
    for (std::size_t k = 0; k < n; ++k) {
      f += step;
      run.force.push_back(f);
    }
  };
  add(1.0, 100);
  add(slope, 20);
  add(0.0, plateau - 1);  // with the last climb's sample: `plateau` at the peak
  add(-slope, 20);
  add(-1.0, 100);
  for (std::size_t i = 0; i < run.force.size(); ++i) {
    run.time.push_back(static_cast<double>(i) * 1e-3);
    run.displacement.push_back(1e-4 * static_cast<double>(i));
  }
  return run;
}

bool clipped_force(const Screening& s) {
  return std::ranges::any_of(s.spans, [](const ScreenedSpan& span) {
    return span.channel == "force" && span.reason == ScreenReason::kClipped;
  });
}

// min_flat (8) samples at a peak cut at speed are a clip; one fewer is no flat run at all.
TEST(Screening, AClipOfExactlyTheMinimumRunLengthIsFoundAndOneShorterIsNot) {
  ASSERT_EQ(ScreeningOptions{}.min_flat, 8u);
  const Screening eight = screen_run(peaked_run(8, 5.0));
  EXPECT_TRUE(clipped_force(eight)) << describe(eight);
  ASSERT_EQ(eight.spans.size(), 1u) << describe(eight);
  // The peak's samples 119-126, and the margin either side.
  EXPECT_LE(eight.spans[0].first, 119u);
  EXPECT_GE(eight.spans[0].last, 126u);
  EXPECT_LE(eight.spans[0].last - eight.spans[0].first, 8u + 12u);
  const Screening seven = screen_run(peaked_run(7, 5.0));
  EXPECT_TRUE(seven.spans.empty()) << describe(seven);
}

// Short clips: the signal, continued at the slope it had outside, would have left the level
// by more than 8 resolution steps over the plateau's length. Exactly 8 is a natural peak's
// flattening; a little more is a cut.
TEST(Screening, AShortClipIsCutAtSpeedBeyondEightResolutionStepsOverItsLength) {
  EXPECT_TRUE(clipped_force(screen_run(peaked_run(8, 1.25))));  // 10 q
  EXPECT_TRUE(clipped_force(screen_run(peaked_run(9, 1.0))));   // 9 q
  const Screening natural = screen_run(peaked_run(8, 1.0));     // 8 q
  EXPECT_FALSE(clipped_force(natural)) << describe(natural);
}

TEST(Screening, CleanSimulatedRunsLoseNothing) {
  for (const RunProfile p : {RunProfile::kTable4, RunProfile::kTelegraph, RunProfile::kSine}) {
    for (const char* damper : {"1kN", "50kN"}) {
      const Screening s = screen_run(clean_run(p, damper));
      EXPECT_EQ(s.excluded_samples, 0u) << damper << " profile " << static_cast<int>(p) << "\n" << describe(s);
    }
  }
}

TEST(Screening, MeasuredRunsLoseNothing) {
  mrd::record::RunReadOptions dyke;
  dyke.columns = mrd::record::parse_column_mapping("t=time_s,D=displacement_cm,Y=voltage_V,F=force_N,V=velocity_cm_s");
  const auto run = mrd::record::read_recorded_run(MRD_DATA_DIR "/damper/dyke-nees-prototype/ranran_50.csv", dyke);
  EXPECT_EQ(screen_run(run).excluded_samples, 0u) << describe(screen_run(run));
  mrd::record::RunReadOptions quiroz;
  quiroz.columns = mrd::record::parse_column_mapping("1=time_s,2=displacement_mm,3=velocity_mm_s,4=force_N");
  quiroz.current_from_name = true;
  for (const char* name : {"25mm0x25Hz0A", "25mm0x5Hz1A", "2mm5Hz0x5A", "5mm3Hz0x75A", "5mm3Hz1A"}) {
    const auto q = mrd::record::read_recorded_run(std::string(MRD_DATA_DIR "/damper/quiroz-utfsm/sine/") + name + ".txt",
                                                  quiroz);
    const Screening s = screen_run(q);
    EXPECT_EQ(s.excluded_samples, 0u) << name << "\n" << describe(s);
  }
}

TEST(Screening, EachFaultIsFoundOnItsChannelWithItsReason) {
  const auto clean = clean_run();
  {
    auto run = with_faulted_end(clean, 0.5);
    const Screening s = screen_run(run);
    EXPECT_TRUE(has_span(s, "force", ScreenReason::kClipped, 3.5, 4.0)) << describe(s);
    EXPECT_TRUE(has_span(s, "displacement", ScreenReason::kStuck, 3.5, 4.0) ||
                has_span(s, "displacement", ScreenReason::kClipped, 3.5, 4.0))
        << describe(s);
    EXPECT_LT(s.excluded_samples, 900u);  // the faulted 0.5 s and the load cell's clips, not the run
  }
  {
    auto run = clean;
    run.force[1234] += 40.0 * (*std::ranges::max_element(run.force) - *std::ranges::min_element(run.force)) / 100.0;
    run.displacement[2345] -= 0.01;
    const Screening s = screen_run(run);
    EXPECT_TRUE(has_span(s, "force", ScreenReason::kSpike, run.time[1234], run.time[1234])) << describe(s);
    EXPECT_TRUE(has_span(s, "displacement", ScreenReason::kSpike, run.time[2345], run.time[2345])) << describe(s);
    EXPECT_EQ(s.spans.size(), 2u) << describe(s);
  }
  {
    auto run = clean;
    for (std::size_t i = 2000; i < run.size(); ++i) run.time[i] += 0.05;  // 50 samples lost
    const Screening s = screen_run(run);
    EXPECT_TRUE(has_span(s, "time", ScreenReason::kGap, run.time[2000], run.time[2000])) << describe(s);
    EXPECT_EQ(s.spans.size(), 1u) << describe(s);
  }
}

TEST(Screening, BridgedInputsAreLinearAcrossTheSpan) {
  auto run = clean_run();
  Screening s;
  s.excluded.assign(run.size(), 0);
  for (std::size_t i = 100; i < 110; ++i) s.excluded[i] = 1;
  const double x0 = run.displacement[99], x1 = run.displacement[110];
  bridge_excluded_inputs(run, s);
  EXPECT_NEAR(run.displacement[104], x0 + (x1 - x0) * (run.time[104] - run.time[99]) / (run.time[110] - run.time[99]),
              1e-15);
}

// Each input bridged only where a fault reaches it: across a fault of the force the recorded
// coil current (here a telegraph, switching every 7 samples) and the motion stay, so that the
// model's lag and core follow the switches through the span; a fault of the LVDT bridges the
// motion alone; a logging gap's row (or an excluded sample no span names) bridges all three.
TEST(Screening, AFaultBridgesOnlyTheInputsItReaches) {
  auto run = clean_run();
  for (std::size_t i = 0; i < run.size(); ++i) run.coil[i] = (i / 7) % 2 == 0 ? 0.0 : 1.0;
  const auto recorded = run;
  Screening s;
  s.excluded.assign(run.size(), 0);
  const auto fault = [&](std::size_t first, std::size_t last, const char* channel, ScreenReason reason) {
    s.spans.push_back({first, last, run.time[first], run.time[last], channel, reason});
    for (std::size_t i = first; i <= last; ++i) s.excluded[i] = 1;
  };
  fault(100, 140, "force", ScreenReason::kClipped);
  fault(300, 340, "force", ScreenReason::kImplausible);
  fault(500, 505, "displacement", ScreenReason::kSpike);
  fault(700, 720, "time", ScreenReason::kGap);
  for (std::size_t i = 900; i < 910; ++i) s.excluded[i] = 1;
  bridge_excluded_inputs(run, s);
  const auto linear = [&](const std::vector<double>& c, std::size_t before, std::size_t after, std::size_t k) {
    return c[before] + (c[after] - c[before]) * (run.time[k] - run.time[before]) / (run.time[after] - run.time[before]);
  };
  for (std::size_t k : {100u, 120u, 140u}) {
    EXPECT_EQ(run.coil[k], recorded.coil[k]) << k;
    EXPECT_EQ(run.displacement[k], recorded.displacement[k]) << k;
  }
  for (std::size_t k : {307u, 321u, 335u}) {
    EXPECT_EQ(run.coil[k], recorded.coil[k]) << k;
    EXPECT_NEAR(run.displacement[k], linear(recorded.displacement, 299, 341, k), 1e-15) << k;
  }
  EXPECT_EQ(run.coil[503], recorded.coil[503]);
  EXPECT_NEAR(run.displacement[503], linear(recorded.displacement, 499, 506, 503), 1e-15);
  for (std::size_t k : {705u, 714u}) {
    EXPECT_NEAR(run.coil[k], linear(recorded.coil, 699, 721, k), 1e-15) << k;
    EXPECT_NEAR(run.displacement[k], linear(recorded.displacement, 699, 721, k), 1e-15) << k;
  }
  EXPECT_NEAR(run.coil[903], linear(recorded.coil, 899, 910, 903), 1e-15);
}

// A rig at its end stop: the LVDT jitters within half a per cent of the stroke while the load
// cell rings at 25 Hz through both signs and clips. No damper reverses its force without moving;
// the same ringing with the rod dithering at 3 % of the stroke is a damper's, and is kept.
TEST(Screening, AForceRingingWhileTheRodStandsIsImplausible) {
  const auto clean = clean_run();
  const auto [x_lo, x_hi] = std::minmax_element(clean.displacement.begin(), clean.displacement.end());
  const auto [f_lo, f_hi] = std::minmax_element(clean.force.begin(), clean.force.end());
  const double stroke = *x_hi - *x_lo, peak = std::max(*f_hi, -*f_lo);
  const auto ringing = [&](double motion_share, bool jitter) {
    auto run = clean;
    std::size_t first = 0;
    std::uint32_t state = 99u;
    for (std::size_t i = 0; i < run.size(); ++i) {
      if (run.time[i] < 2.0 || run.time[i] > 2.36) continue;
      if (first == 0) first = i;
      state = state * 1664525u + 1013904223u;
      const double u = static_cast<double>(state >> 8) / 8388608.0 - 1.0;
      const double phase = 2.0 * std::numbers::pi * 25.0 * (run.time[i] - 2.0);
      run.displacement[i] = run.displacement[first] + (jitter ? 0.005 * stroke * u : motion_share * stroke * std::sin(phase));
      run.force[i] = std::clamp(1.2 * peak * std::cos(phase), -peak, peak);
    }
    return run;
  };
  const Screening stop = screen_run(ringing(0.0, true));
  EXPECT_TRUE(has_span(stop, "force", ScreenReason::kImplausible, 2.05, 2.3)) << describe(stop);
  std::size_t outside = 0;
  for (std::size_t i = 0; i < clean.size(); ++i)
    outside += stop.excluded[i] && (clean.time[i] < 1.9 || clean.time[i] > 2.46);
  EXPECT_EQ(outside, 0u) << describe(stop);
  const Screening dither = screen_run(ringing(0.03, false));
  EXPECT_FALSE(std::ranges::any_of(dither.spans, [](const ScreenedSpan& s) { return s.reason == ScreenReason::kImplausible; }))
      << describe(dither);
  EXPECT_EQ(std::string(to_string(ScreenReason::kImplausible)), "implausible");
}

// The fault takes over a fit without screening; with it, the base fit's error is the unfaulted
// run's, on the kept samples.
TEST(Screening, AFaultedEndDoesNotTakeOverTheFit) {
  const auto clean = clean_run(RunProfile::kTable4, "1kN");
  const auto faulted = with_faulted_end(clean, 0.5);
  ResidualOptions options;
  options.threads = 2;
  options.discover = false;
  const ResidualResult reference = find_missing_effects(make_fit_series({clean}, {}), options);
  const ResidualResult screened = find_missing_effects(make_fit_series({faulted}, {}), options);
  FitSeriesOptions off;
  off.screen = false;
  const ResidualResult unscreened = find_missing_effects(make_fit_series({faulted}, off), options);
  EXPECT_NEAR(screened.before.all, reference.before.all, 0.05 * reference.before.all)
      << residual_summary({faulted}, screened);
  EXPECT_GT(unscreened.before.all, 3.0 * reference.before.all) << residual_summary({faulted}, unscreened);
  EXPECT_TRUE(screened.accepted.empty()) << residual_summary({faulted}, screened);
  const auto json = nlohmann::json::parse(residual_json(screened));
  bool clipped = false;
  for (const auto& span : json["screening"]["spans"]) clipped = clipped || span["reason"] == "clipped";
  EXPECT_TRUE(clipped) << json.dump(2);
  const auto none = nlohmann::json::parse(residual_json(unscreened))["screening"];
  EXPECT_EQ(none["excluded_samples"], 0);
  EXPECT_TRUE(none["spans"].empty());
}

}  // namespace

namespace {

// The rows the reader set aside are the screening's spans too, with reason, column and line, and
// cost no sample beyond themselves.
TEST(Screening, RowsTheReaderSetAsideAreListedWithTheirLine) {
  std::string text = "time_s,displacement_mm,current_A,force_N\n";
  for (int i = 0; i < 200; ++i) {
    const std::string row = std::to_string(i * 0.001) + "," + std::to_string(i % 7) + ",0.5," + std::to_string(i % 5) + "\n";
    text += row;
    if (i == 50) text += row;  // a repeated row (line 53)
  }
  text.insert(text.find("\n0.100000,"), "\n0.100000,,0.5,1");  // an empty cell before t = 0.1 s
  const mrd::record::RecordedRun run = mrd::record::parse_recorded_run(text, "logger.csv");
  ASSERT_EQ(run.size(), 200u);
  const mrd::tools::Screening s = mrd::tools::screen_run(run);
  std::vector<const mrd::tools::ScreenedSpan*> rows;
  for (const auto& span : s.spans)
    if (span.line > 0) rows.push_back(&span);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0]->reason, mrd::tools::ScreenReason::kDuplicate);
  EXPECT_EQ(rows[0]->line, 53u);
  EXPECT_EQ(rows[0]->channel, "row");
  EXPECT_EQ(rows[1]->reason, mrd::tools::ScreenReason::kNonFinite);
  EXPECT_EQ(rows[1]->channel, "displacement_mm");
  EXPECT_DOUBLE_EQ(rows[1]->start_s, 0.1);
  EXPECT_EQ(std::string(mrd::tools::to_string(rows[1]->reason)), "non_finite");
}

}  // namespace
