// mrd-simulate-run's generator: deterministic per seed, clean runs hold only the sensors' noise,
// and every effect, undeclared in the CSV, leaves a residual against the base model.
#include "tools/simulation/run_generator.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstring>
#include <numbers>
#include <set>
#include <sstream>
#include <string>
#include <tuple>

#include "tools/simulation/run_csv.hpp"

namespace {

using mrd::tools::RunOptions;
using mrd::tools::RunProfile;
using mrd::tools::SimulatedRun;

RunOptions short_run(RunProfile profile, const char* damper_class) {
  RunOptions o;
  o.profile = profile;
  o.damper = *mrd::tools::find_damper_class(damper_class);
  o.frequency = 1.0;
  o.duration = 3.0;
  o.seed = 5;
  return o;
}

using mrd::tools::model_residual;

TEST(RunGenerator, SameOptionsGiveTheSameRunBitForBitAndTheSeedMatters) {
  auto o = short_run(RunProfile::kTelegraph, "1kN");
  o.effects = {{"thermal_drift", 1.0}, {"sensor_delay", 0.5}};
  const SimulatedRun a = mrd::tools::simulate_run(o);
  const SimulatedRun b = mrd::tools::simulate_run(o);
  ASSERT_EQ(a.samples.size(), 3000u);
  ASSERT_EQ(a.samples.size(), b.samples.size());
  EXPECT_EQ(std::memcmp(a.samples.data(), b.samples.data(), a.samples.size() * sizeof a.samples[0]), 0);
  std::ostringstream csv_a, csv_b;
  mrd::tools::write_run_csv(csv_a, a, {});
  mrd::tools::write_run_csv(csv_b, b, {});
  EXPECT_EQ(csv_a.str(), csv_b.str());
  o.seed = 6;
  const SimulatedRun c = mrd::tools::simulate_run(o);
  EXPECT_NE(a.samples[1000].displacement, c.samples[1000].displacement);
}

TEST(RunGenerator, ACleanRunHoldsOnlyTheLoadCellNoise) {
  for (const char* damper : {"50kN", "1kN"}) {
    for (const auto profile : {RunProfile::kTable4, RunProfile::kTelegraph}) {
      const SimulatedRun run = mrd::tools::simulate_run(short_run(profile, damper));
      const double noise = run.options.force_noise;
      EXPECT_NEAR(model_residual(run), noise, 0.1 * noise) << damper << " " << to_string(profile);
    }
  }
}

// Each effect at two sizes, on a profile where it acts: the base model's residual is many
// times the noise, and the larger size leaves a larger residual. coil_lag needs a current
// that changes quickly (telegraph); the others show on the paper's Table 4 sine.
TEST(RunGenerator, EveryEffectVisiblyChangesTheRunAndGrowsWithItsSize) {
  for (const char* damper : {"50kN", "1kN"}) {
    for (const mrd::model::EffectInfo& effect : mrd::model::effect_infos()) {
      if (!effect.named_candidate) continue;  // learned terms are discovered, not simulated
      const std::string_view name = effect.name;
      const auto profile = name == "coil_lag" ? RunProfile::kTelegraph : RunProfile::kTable4;
      auto o = short_run(profile, damper);
      const double clean = model_residual(mrd::tools::simulate_run(o));
      o.effects = {{std::string(name), 0.5}};
      const double small = model_residual(mrd::tools::simulate_run(o));
      o.effects = {{std::string(name), 2.0}};
      const double large = model_residual(mrd::tools::simulate_run(o));
      EXPECT_GT(small, 5.0 * clean) << damper << " " << name;
      EXPECT_GT(large, 1.2 * small) << damper << " " << name;  // coil_lag saturates first
    }
  }
}

// The observer with sensor_delay on, replayed on a run whose LVDT is late, predicts across the
// delay: the error falls far on the sine; on 5 Hz random motion the tracker's acceleration lags,
// and less is recovered.
TEST(RunGenerator, ObserverCompensatesTheSensorDelayOfARun) {
  for (const auto& [damper, profile, gain] : {std::tuple{"50kN", RunProfile::kTable4, 10.0},
                                              std::tuple{"1kN", RunProfile::kRandom, 2.0}}) {
    auto o = short_run(profile, damper);
    o.effects = {{"sensor_delay", 0.5}};
    const SimulatedRun run = mrd::tools::simulate_run(o);
    EXPECT_GT(model_residual(run, {}), gain * model_residual(run, run.effects)) << damper;
  }
}

TEST(RunGenerator, EffectsAreSizedForTheDamperClass) {
  auto o = short_run(RunProfile::kTable4, "1kN");
  o.effects = {{"coil_lag", 2.0}, {"gas_spring", 0.5}, {"stroke_end_air", 4.0}};
  const SimulatedRun run = mrd::tools::simulate_run(o);
  EXPECT_DOUBLE_EQ(run.effects.get<mrd::model::CoilLagEffect>().time_constant, 2.0 / 190.0);
  EXPECT_DOUBLE_EQ(run.effects.get<mrd::model::GasSpringEffect>().preload, 35.0);
  EXPECT_DOUBLE_EQ(run.effects.get<mrd::model::StrokeEndAirEffect>().depth, 0.95);  // capped
  EXPECT_DOUBLE_EQ(run.effects.get<mrd::model::StrokeEndAirEffect>().threshold, 0.015);
  EXPECT_FALSE(run.effects.get<mrd::model::ThermalDriftEffect>().enabled);
}

TEST(RunGenerator, ThermalDriftHeatsTheFluidByItsSize) {
  auto o = short_run(RunProfile::kTable4, "50kN");
  o.effects = {{"thermal_drift", 1.0}};
  const SimulatedRun run = mrd::tools::simulate_run(o);
  const double rise = run.samples.back().temperature - run.samples.front().temperature;
  EXPECT_GT(rise, 0.9 * 20.0);  // the cooling over 3 s of a 600 s time constant is small
  EXPECT_LT(rise, 20.0 + 1e-9);
}

TEST(RunGenerator, ProfilesMoveAndCommandAsDocumented) {
  // Random motion uses the whole stroke and no more.
  const SimulatedRun random = mrd::tools::simulate_run(short_run(RunProfile::kRandom, "50kN"));
  double peak = 0.0;
  for (const auto& s : random.samples) peak = std::max(peak, std::fabs(s.true_displacement));
  EXPECT_NEAR(peak, 0.040, 1e-12);
  // The telegraph holds two levels and switches every 20 ms on average.
  const SimulatedRun telegraph = mrd::tools::simulate_run(short_run(RunProfile::kTelegraph, "1kN"));
  int switches = 0;
  for (std::size_t k = 1; k < telegraph.samples.size(); ++k) {
    const double i = telegraph.samples[k].current;
    EXPECT_TRUE(i == 0.0 || i == 1.0) << i;
    if (i != telegraph.samples[k - 1].current) ++switches;
  }
  EXPECT_GT(switches, 100);  // 150 expected in 3 s
  EXPECT_LT(switches, 200);
  // Table 4 on the 50 kN class: 1 Hz, +-40 mm, the published currents (1.2 A only when the
  // LVDT's noise lifts a peak above 40 mm).
  const SimulatedRun table4 = mrd::tools::simulate_run(short_run(RunProfile::kTable4, "50kN"));
  std::set<double> levels;
  for (const auto& s : table4.samples) levels.insert(s.current);
  for (const double level : {0.0, 0.2, 0.4, 0.6, 0.8}) EXPECT_EQ(levels.count(level), 1u) << level;
  EXPECT_LE(levels.size(), 6u);
  // The paper's five sine tests, two cycles each by default.
  RunOptions sines;
  sines.profile = RunProfile::kPaperSines;
  EXPECT_NEAR(mrd::tools::resolve(sines).duration, 2.0 * (20.0 + 10.0 + 5.0 + 2.0 + 1.0), 1e-9);
}

TEST(RunGenerator, CsvHasTheRecordedRunHeaderAndUnits) {
  const SimulatedRun run = mrd::tools::simulate_run(short_run(RunProfile::kTable4, "50kN"));
  std::ostringstream out;
  mrd::tools::write_run_csv(out, run, {true, true, true});
  std::istringstream in(out.str());
  std::string header, first, second;
  std::getline(in, header);
  std::getline(in, first);
  std::getline(in, second);
  EXPECT_EQ(header, "time_s,displacement_mm,current_A,force_N,velocity_mm_s,B_T,temperature_C");
  double t = 0, x_mm = 0, i = 0, f_N = 0, v_mm_s = 0, B = 0, temperature = 0;
  ASSERT_EQ(std::sscanf(second.c_str(), "%lf,%lf,%lf,%lf,%lf,%lf,%lf", &t, &x_mm, &i, &f_N, &v_mm_s, &B,
                        &temperature),
            7);
  EXPECT_DOUBLE_EQ(t, 1e-3);
  EXPECT_NEAR(x_mm, run.samples[1].displacement * 1e3, 1e-6);
  EXPECT_NEAR(f_N, run.samples[1].force, 1e-8 * std::fabs(run.samples[1].force));  // nine significant digits
  EXPECT_NEAR(v_mm_s, 40.0 * 2.0 * std::numbers::pi * std::cos(2.0 * std::numbers::pi * 1e-3), 1e-5);
  EXPECT_EQ(temperature, 20.0);
  std::ostringstream plain;
  mrd::tools::write_run_csv(plain, run, {false, false, false});
  EXPECT_EQ(plain.str().substr(0, plain.str().find('\n')), "time_s,displacement_mm,current_A,force_N");
}

TEST(RunGenerator, ManifestNamesTheCarriedEffects) {
  auto o = short_run(RunProfile::kTable4, "1kN");
  o.effects = {{"stroke_end_air", 2.0}};
  const auto json = nlohmann::json::parse(mrd::tools::run_manifest_json(mrd::tools::simulate_run(o)));
  EXPECT_EQ(json["damper_class"], "1kN");
  EXPECT_EQ(json["effects"], nlohmann::json::parse(R"([{"name": "stroke_end_air", "size": 2.0}])")) << json.dump(2);
  // The TOML travels as a string with its newlines, escaped by JSON and unescaped by the parse.
  EXPECT_NE(json["effects_toml"].get<std::string>().find("[damper.effects.stroke_end_air]\nenabled = true\n"),
            std::string::npos)
      << json.dump(2);
}

TEST(RunGenerator, EffectRequestsParseNamesAndSizes) {
  std::string error;
  EXPECT_EQ(mrd::tools::parse_effect_request("coil_lag", error)->size, 1.0);
  EXPECT_EQ(mrd::tools::parse_effect_request("coil_lag:large", error)->size, 2.0);
  EXPECT_EQ(mrd::tools::parse_effect_request("gas_spring:small", error)->size, 0.5);
  EXPECT_EQ(mrd::tools::parse_effect_request("sensor_delay:1.5", error)->size, 1.5);
  EXPECT_FALSE(mrd::tools::parse_effect_request("coil_lag:-1", error));
  EXPECT_NE(error.find("must be small, medium, large or a number > 0"), std::string::npos);
  EXPECT_FALSE(mrd::tools::parse_effect_request("air_spring", error));
  EXPECT_NE(error.find("unknown effect 'air_spring'"), std::string::npos);
  RunOptions twice;
  twice.effects = {{"coil_lag", 1.0}, {"coil_lag", 2.0}};
  EXPECT_NE(mrd::tools::check(twice).find("effect coil_lag is given twice"), std::string::npos);
}

}  // namespace

// Each candidate's descriptor sizes it for each damper class (its nominal()), off until a run
// asks; only an effect sized by the run's energy may read the same on both. An effect added
// without its class sizes fails here.
TEST(DamperClasses, EveryCandidateCarriesItsOwnSizeOnEachClass) {
  const auto large = *mrd::tools::find_damper_class("50kN");
  const auto small = *mrd::tools::find_damper_class("1kN");
  for (const mrd::model::EffectInfo& e : mrd::model::effect_infos()) {
    if (!e.named_candidate) continue;
    EXPECT_FALSE(e.enabled(large.nominal_effects)) << e.name;
    EXPECT_FALSE(e.enabled(small.nominal_effects)) << e.name;
    if (e.sized_by_dissipated_energy) continue;
    EXPECT_NE(e.size_summary(large.nominal_effects), e.size_summary(small.nominal_effects)) << e.name;
  }
}
