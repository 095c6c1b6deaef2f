// What mrd-residual writes: JSON with exactly the documented keys, and a config that the
// controller loads, with the accepted effect on and the fitted damper in it.
#include "tools/residual/residual_report.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <regex>
#include <set>
#include <sstream>

#include "config/config_loader.hpp"
#include "tests/tools/residual/residual_test_support.hpp"
#include "tools/text_format.hpp"

namespace {

using namespace mrd::tools;

const ResidualResult& gas_spring_result() {
  static const ResidualResult r = residual_testing::analyse(
      residual_testing::simulated_recorded_run(RunProfile::kTable4, "1kN", {{"gas_spring", 1.0}}, 4.0));
  return r;
}

TEST(ResidualReport, JsonHasExactlyTheDocumentedKeys) {
  const ResidualResult& r = gas_spring_result();
  const auto json = nlohmann::json::parse(residual_json(r));
  std::set<std::string> top;
  for (const auto& [key, value] : json.items()) top.insert(key);
  EXPECT_EQ(top, (std::set<std::string>{"samples", "rms_before_N", "noise_floor_N", "fit_before_percent", "fit_after_percent", "parameters",
                                        "max_before_N", "effects", "effect", "rms_after_N", "max_after_N", "effect_params",
                                        "candidates", "ambiguous", "ambiguity_tests", "discovered", "screening",
                                        "robust", "switch_timing", "set_revisions", "unexplained", "unphysical"}));
  for (const char* key : {"steps", "estimated", "applied", "median_phase", "rms_before_N", "rms_after_N"})
    EXPECT_TRUE(json["switch_timing"].contains(key)) << key;
  EXPECT_EQ(json["switch_timing"]["steps"].get<std::size_t>(), r.switch_timing.steps);
  EXPECT_EQ(json["unphysical"].size(), r.unphysical.size());
  EXPECT_EQ(json["parameters"][0]["determined"].get<bool>(), determined(r.parameters[0]));
  EXPECT_EQ(json["effect"], "gas_spring");
  EXPECT_TRUE(json["effect_params"]["gas_spring"].contains("preload_N")) << json.dump(2);
  // Doubles round-trip: the JSON holds the very bits of the result.
  EXPECT_EQ(json["rms_before_N"].get<double>(), r.before.all);
  EXPECT_EQ(json["rms_after_N"].get<double>(), r.after.all);
  EXPECT_EQ(json["noise_floor_N"].get<double>(), r.noise_floor);
  EXPECT_EQ(json["fit_after_percent"].get<double>(), r.fit_after_percent);
  bool coil_lag = false;
  for (const auto& c : json["candidates"]) {
    EXPECT_TRUE(c.contains("rms_after_N") && c.contains("validation_rms_N") && c["accepted"].is_boolean()) << c;
    const auto& e = c["evidence"];
    EXPECT_EQ(e["pieces"].get<int>(), 72) << c;  // 12 blocks of 166 samples held out, 6 pieces each
    for (const char* key : {"mean_square_fall_N2", "fall_required_N2", "standard_error_N2", "t", "t_required", "z", "z_required"})
      EXPECT_TRUE(e[key].is_number()) << key << c;
    // Accepted only with the evidence (the set revision may still drop one that had it).
    if (c["accepted"].get<bool>()) {
      EXPECT_TRUE(e["significant"].get<bool>() && e["material"].get<bool>()) << c;
    }
    coil_lag = coil_lag || c["effect"] == "coil_lag";
  }
  EXPECT_TRUE(coil_lag) << json.dump(2);
  ASSERT_EQ(json["parameters"].size(), r.parameters.size());
  EXPECT_EQ(json["parameters"][0]["name"], "geometry.pole_length");
  EXPECT_EQ(json["parameters"][0]["sd"].get<double>(), r.parameters[0].standard_deviation);
}

// Where the time went: every step of the pipeline in order, its passes adding up to the total,
// the base fit and the rounds doing the fitting, and the summary's last line saying so.
TEST(ResidualReport, TheTimeAndThePassesAreSplitByStep) {
  const ResidualResult& r = gas_spring_result();
  std::vector<std::string> steps;
  std::int64_t passes = 0;
  double seconds = 0.0;
  for (const ResidualResult::StepCost& c : r.steps) {
    steps.push_back(c.step);
    passes += c.evaluations;
    seconds += c.seconds;
    EXPECT_GE(c.seconds, 0.0) << c.step;
  }
  EXPECT_EQ(steps, (std::vector<std::string>{"base fit", "greedy rounds", "set revision", "effects against terms",
                                             "discovery", "uncertainty"}));
  EXPECT_EQ(passes, r.evaluations);
  EXPECT_LE(seconds, r.seconds);
  EXPECT_GT(r.steps[0].evaluations, 0);
  EXPECT_GT(r.steps[1].evaluations, 0);
  const std::string summary = residual_summary({}, r);
  EXPECT_NE(summary.find(format("  by step: base fit %.1f s (%lld passes), greedy rounds", r.steps[0].seconds,
                                static_cast<long long>(r.steps[0].evaluations))),
            std::string::npos)
      << summary;
}

TEST(ResidualReport, UpdatedConfigLoadsWithTheEffectOnAndTheFittedDamper) {
  const ResidualResult& r = gas_spring_result();
  const std::string text = updated_config(mrd::config::default_config_text(), r);
  const auto loaded = mrd::config::load_config_text(text, "updated.toml");
  ASSERT_TRUE(loaded.ok()) << loaded.report() << text;
  const auto& d = loaded.config.law.damper;
  EXPECT_TRUE(d.effects.get<mrd::model::GasSpringEffect>().enabled);
  EXPECT_FALSE(d.effects.get<mrd::model::CoilLagEffect>().enabled);
  // Written at 7 significant digits: within half a unit of the 7th.
  const auto seven_digits = [](double written, double fitted) { EXPECT_NEAR(written, fitted, 5e-7 * std::fabs(fitted)); };
  seven_digits(d.effects.get<mrd::model::GasSpringEffect>().stiffness, r.final_model.effects.get<mrd::model::GasSpringEffect>().stiffness);
  seven_digits(d.geometry.pole_length, r.final_model.geometry.pole_length);
  seven_digits(d.fluid.viscosity, r.final_model.fluid.viscosity);
  // No fitted value has more than 7 significant digits in the file.
  const std::regex value(R"(^\s*(pole_length|viscosity|stiffness) = -?([0-9.]+))");
  int checked = 0;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    std::smatch m;
    if (!std::regex_search(line, m, value)) continue;
    std::string digits = m[2];
    std::erase(digits, '.');
    digits.erase(0, digits.find_first_not_of('0'));
    EXPECT_LE(digits.size(), 7u) << line;
    ++checked;
  }
  EXPECT_GE(checked, 3);
  // The 1 kN class: 70 N preload and 500 N/m at size 1. On the Table 4 schedule the current
  // follows |x|, so with the material free part of k x goes into the field (docs/CLOSING-THE-
  // LOOP.md, "Limits"); the preload and the fit to the noise (2 N) are what the run fixes.
  EXPECT_NEAR(d.effects.get<mrd::model::GasSpringEffect>().preload, 70.0, 5.0);
  EXPECT_GT(d.effects.get<mrd::model::GasSpringEffect>().stiffness, 0.0);
  EXPECT_LT(r.after.all, 1.5 * 2.0);
  // Patched in place: the default's order (a sorted writer puts [backends] first) and comments stay.
  EXPECT_LT(text.find("[loop]"), text.find("[backends]"));
  EXPECT_NE(text.find("[damper.effects.gas_spring]   # accumulator: F0 + k x\n"), std::string::npos) << text;
  EXPECT_NE(text.find("[damper.circuit]              # Eq. 9: H = N I / Le\n"), std::string::npos) << text;
  // Written again over its own output, only the values it changes change.
  EXPECT_EQ(updated_config(text, r), text);
}

}  // namespace
