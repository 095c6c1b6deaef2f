// The TOML patcher (tools/toml_patch): values written in place, the rest byte for byte.
#include "tools/toml_patch.hpp"

#include <gtest/gtest.h>

#include "config/config_loader.hpp"

namespace {

using mrd::tools::patch_toml;

constexpr const char* kAnnotated = R"(# The damper.
[damper.jiles_atherton]
Ms = 1.3e6      # saturation [A/m]
a = 2000.0      # shape [A/m]

# The fluid, second on purpose (a sorted writer would move it).
[damper.fluid]
viscosity = 0.8  # [Pa s]
list = [1, 2,
        3]  # spans lines

[control]
rate = 1000
)";

toml::table patch_values(std::string_view text) { return toml::parse(text); }

TEST(TomlPatch, NoChangeIsByteIdentical) {
  // Every key set to the value it has (written in another form where TOML allows one).
  const auto same = patch_values("[damper.jiles_atherton]\nMs = 1300000.0\na = 2e3\n[damper.fluid]\nviscosity = 0.8\n"
                                 "list = [1, 2, 3]\n[control]\nrate = 1000\n");
  EXPECT_EQ(patch_toml(kAnnotated, same), kAnnotated);
  // And the compiled-in default config, with everything it holds.
  const std::string default_text(mrd::config::default_config_text());
  EXPECT_EQ(patch_toml(default_text, toml::parse(default_text)), default_text);
}

TEST(TomlPatch, AChangedValueKeepsItsCommentAndPlace) {
  const std::string out = patch_toml(kAnnotated, patch_values("[damper.jiles_atherton]\nMs = 1.25e6\n"));
  std::string expected = kAnnotated;
  expected.replace(expected.find("1.3e6      #"), 12, "1250000.0  #");  // the comment keeps its column
  EXPECT_EQ(out, expected);
  // A value longer than its room pushes the comment one space behind it.
  const std::string longer = patch_toml(kAnnotated, patch_values("[damper.jiles_atherton]\nMs = 1234567.891\n"));
  EXPECT_NE(longer.find("Ms = 1234567.891 # saturation [A/m]\n"), std::string::npos) << longer;
}

TEST(TomlPatch, AMultiLineArrayIsReplacedWhole) {
  const std::string out = patch_toml(kAnnotated, patch_values("[damper.fluid]\nlist = [4]\n"));
  EXPECT_EQ(out.find("3]"), std::string::npos) << out;
  EXPECT_NE(out.find("]  # spans lines\n\n[control]"), std::string::npos) << out;
  EXPECT_EQ(toml::parse(out)["damper"]["fluid"]["list"].as_array()->size(), 1u);
}

TEST(TomlPatch, NewKeysAndTablesGoWhereTheyBelong) {
  const std::string out = patch_toml(
      kAnnotated, patch_values("[damper.jiles_atherton]\nk = 1500.0\n[damper.effects.gas_spring]\nenabled = true\n"
                               "preload_N = 120.5\n[logging]\nlevel = \"info\"\n"));
  // k after a, before the fluid's comment; the effect table among the damper's tables, before
  // [control]; an unrelated new table at the end.
  EXPECT_LT(out.find("a = 2000.0"), out.find("k = 1500.0"));
  EXPECT_LT(out.find("k = 1500.0"), out.find("# The fluid"));
  EXPECT_LT(out.find("[damper.effects.gas_spring]"), out.find("[control]"));
  EXPECT_GT(out.find("[logging]"), out.find("rate = 1000"));
  const toml::table back = toml::parse(out);
  EXPECT_EQ(back["damper"]["jiles_atherton"]["k"].value<double>(), 1500.0);
  EXPECT_EQ(back["damper"]["effects"]["gas_spring"]["enabled"].value<bool>(), true);
  EXPECT_EQ(back["damper"]["effects"]["gas_spring"]["preload_N"].value<double>(), 120.5);
  EXPECT_EQ(back["logging"]["level"].value<std::string>(), "info");
  EXPECT_EQ(back["damper"]["jiles_atherton"]["Ms"].value<double>(), 1.3e6);  // untouched
}

TEST(TomlPatch, DoublesReadBackToTheSameBits) {
  const double x = 0.1 + 0.2;  // 0.30000000000000004
  toml::table values;
  values.insert("x", x);
  values.insert("whole", 3.0);
  const std::string out = patch_toml("", values);
  EXPECT_EQ(toml::parse(out)["x"].value<double>(), x);
  EXPECT_TRUE(toml::parse(out)["whole"].is_floating_point()) << out;  // 3.0, not 3
}

// Fitted values go out at 7 significant digits wherever they sit; integers, booleans and
// exact zeros stay as they are.
TEST(TomlPatch, FloatsRoundToSevenSignificantDigitsAtEveryDepth) {
  toml::table values = toml::parse(
      "v = 6.852856037433653e-54\nn = 3\nz = 0.0\n[t]\nw = 1234567.891\nlist = [0.1234567891, true]\n");
  mrd::tools::round_floats(values);
  EXPECT_EQ(values["v"].value<double>(), 6.852856e-54);
  EXPECT_EQ(values["n"].value<std::int64_t>(), 3);
  EXPECT_EQ(values["z"].value<double>(), 0.0);
  EXPECT_EQ(values["t"]["w"].value<double>(), 1234568.0);
  EXPECT_EQ(values["t"]["list"][0].value<double>(), 0.1234568);
  EXPECT_EQ(values["t"]["list"][1].value<bool>(), true);
  EXPECT_EQ(mrd::tools::patch_toml("v = 1.0\n", values).find("v = 6.852856e-54\n"), 0u);
}

TEST(TomlPatch, AStringWithAHashIsNotACommentAndAnArrayOfTablesIsLeftAlone) {
  const std::string text = "name = \"a # b\" # note\n[[runs]]\nx = 1\n";
  const std::string out = patch_toml(text, patch_values("name = \"c\"\n"));
  EXPECT_EQ(out, "name = 'c'     # note\n[[runs]]\nx = 1\n");
}

}  // namespace
