// The TOML reader on its own: a parsed table in, values and messages (file, line, key) out.
// An absent key keeps the caller's default and is listed as defaulted; a wrong type is an error
// that keeps the default; a key nobody asked for is reported, so a typo is never silent.
#include "config/toml_reader.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <string>

namespace {

using mrd::config::ConfigMessages;
using mrd::config::TomlReader;

struct Read {
  toml::table root;
  ConfigMessages messages;
  TomlReader in;
  explicit Read(std::string_view text) : root(toml::parse(text)), in(root, "r.toml", messages) {}
};

TEST(TomlReader, ValuesAreReadAbsentOnesKeepTheirDefaultAndAreListed) {
  Read r("[loop]\nrate = 2500\n[safety]\nenable_in_safe = true\nlink_timeout = 0.25\n");
  double rate = 1000.0, missing = 7.0;
  bool enable = false;
  std::chrono::milliseconds timeout{0};
  r.in.get("loop.rate", rate);  // an integer where a double is asked for: taken
  r.in.get("loop.missing", missing);
  r.in.get("safety.enable_in_safe", enable);
  r.in.get_seconds("safety.link_timeout", timeout);
  EXPECT_EQ(rate, 2500.0);
  EXPECT_EQ(missing, 7.0);
  EXPECT_TRUE(enable);
  EXPECT_EQ(timeout, std::chrono::milliseconds{250});
  EXPECT_EQ(r.in.defaulted(), std::vector<std::string>{"loop.missing"});
  EXPECT_EQ(r.in.keys(), (std::vector<std::string>{"loop.rate", "loop.missing", "safety.enable_in_safe", "safety.link_timeout"}));
  EXPECT_TRUE(r.messages.empty());
}

TEST(TomlReader, AWrongTypeIsAnErrorWithItsLineAndKeepsTheDefault) {
  Read r("# a comment\n[loop]\nrate = \"fast\"\n");
  double rate = 1000.0;
  r.in.get("loop.rate", rate);
  EXPECT_EQ(rate, 1000.0);
  ASSERT_EQ(r.messages.size(), 1u);
  EXPECT_EQ(r.messages[0].file, "r.toml");
  EXPECT_EQ(r.messages[0].line, 3);
  EXPECT_EQ(r.messages[0].key, "loop.rate");
  EXPECT_FALSE(r.messages[0].warning);
}

TEST(TomlReader, AKeyNobodyAskedForIsReportedWithItsLine) {
  Read r("[loop]\nrate = 2500\nrtae = 3\n");
  double rate = 0.0;
  r.in.get("loop.rate", rate);
  r.in.report_unknown_keys();
  ASSERT_EQ(r.messages.size(), 1u);
  EXPECT_EQ(r.messages[0].key, "loop.rtae");
  EXPECT_EQ(r.messages[0].line, 3);
}

TEST(TomlReader, AnEnumIsOneOfItsChoicesAndAnArrayHasExactlyItsLength) {
  enum class Mode { kA, kB };
  Read r("mode = \"b\"\nother = \"c\"\npair = [1.5, 2.5]\nshort = [1.0]\n");
  Mode mode = Mode::kA, other = Mode::kA;
  r.in.get_enum("mode", mode, {{"a", Mode::kA}, {"b", Mode::kB}});
  r.in.get_enum("other", other, {{"a", Mode::kA}, {"b", Mode::kB}});
  std::array<double, 2> pair{}, short_one{9.0, 9.0};
  r.in.get("pair", pair);
  r.in.get("short", short_one);
  EXPECT_EQ(mode, Mode::kB);
  EXPECT_EQ(other, Mode::kA);
  EXPECT_EQ(pair, (std::array<double, 2>{1.5, 2.5}));
  EXPECT_EQ(short_one, (std::array<double, 2>{9.0, 9.0}));
  ASSERT_EQ(r.messages.size(), 2u);
  EXPECT_EQ(r.messages[0].key, "other");
  EXPECT_EQ(r.messages[0].line, 2);
  EXPECT_EQ(r.messages[1].key, "short");
  EXPECT_EQ(r.messages[1].line, 4);
}

}  // namespace
