// What mrd-residual writes: JSON with exactly the documented keys, and a config that the
// controller loads, with the accepted effect on and the fitted damper in it.
#include "tools/residual/residual_report.hpp"

#include <gtest/gtest.h>

#include <regex>
#include <set>

#include "config/config_loader.hpp"
#include "tests/tools/residual/residual_test_support.hpp"

namespace {

using namespace mrd::tools;

const ResidualResult& gas_spring_result() {
  static const ResidualResult r = residual_testing::analyse(
      residual_testing::simulated_recorded_run(RunProfile::kTable4, "1kN", {{"gas_spring", 1.0}}, 4.0));
  return r;
}

TEST(ResidualReport, JsonHasExactlyTheDocumentedKeys) {
  const std::string json = residual_json(gas_spring_result());
  std::set<std::string> top;
  int depth = 0;
  const std::regex key("\"([a-zA-Z_]+)\":");
  for (std::size_t i = 0; i < json.size(); ++i) {
    const char c = json[i];
    if (c == '{' || c == '[') ++depth;
    if (c == '}' || c == ']') --depth;
    std::smatch m;
    const std::string rest = json.substr(i, 40);
    if (depth == 1 && c == '"' && std::regex_search(rest, m, key) && m.position(0) == 0) top.insert(m[1]);
  }
  EXPECT_EQ(top, (std::set<std::string>{"samples", "rms_before_N", "max_before_N", "effects", "effect", "rms_after_N",
                                        "max_after_N", "effect_params", "candidates", "ambiguous", "ambiguity_tests", "discovered", "screening",
                                        "set_revisions", "unexplained"}));
  EXPECT_NE(json.find("\"effect\": \"gas_spring\""), std::string::npos) << json;
  EXPECT_NE(json.find("\"gas_spring\": {\"preload_N\": "), std::string::npos) << json;
  EXPECT_NE(json.find("{\"effect\": \"coil_lag\", \"rms_after_N\": "), std::string::npos) << json;
}

TEST(ResidualReport, UpdatedConfigLoadsWithTheEffectOnAndTheFittedDamper) {
  const ResidualResult& r = gas_spring_result();
  const std::string text = updated_config(mrd::config::default_config_text(), r);
  const auto loaded = mrd::config::load_config_text(text, "updated.toml");
  ASSERT_TRUE(loaded.ok()) << loaded.report() << text;
  const auto& d = loaded.config.law.damper;
  EXPECT_TRUE(d.effects.get<mrd::model::GasSpringEffect>().enabled);
  EXPECT_FALSE(d.effects.get<mrd::model::CoilLagEffect>().enabled);
  EXPECT_DOUBLE_EQ(d.effects.get<mrd::model::GasSpringEffect>().stiffness, r.final_model.effects.get<mrd::model::GasSpringEffect>().stiffness);
  EXPECT_DOUBLE_EQ(d.geometry.pole_length, r.final_model.geometry.pole_length);
  EXPECT_DOUBLE_EQ(d.fluid.viscosity, r.final_model.fluid.viscosity);
  // The 1 kN class: 70 N preload and 500 N/m at size 1.
  EXPECT_NEAR(d.effects.get<mrd::model::GasSpringEffect>().preload, 70.0, 5.0);
  EXPECT_NEAR(d.effects.get<mrd::model::GasSpringEffect>().stiffness, 500.0, 100.0);
}

}  // namespace
