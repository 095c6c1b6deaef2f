// SIGHUP's check of the config file: a bad file is reported with its problems, a changed good one
// is named for the next start, the running config stays either way. No process, no signal.
#include "firmware/config_reload.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "tests/support/test_files.hpp"

namespace {

using mrd::firmware::ConfigReload;
using mrd::telemetry::Priority;

const std::string kGood = "[backends]\nlvdt = \"mock\"\ndriver = \"mock\"\nlines = \"mock\"\n";

class Reload : public ::testing::Test {
 protected:
  void write(const std::string& text) const { std::ofstream(path_) << text; }

  mrd::test::TestDirectory dir_{"mrd_config_reload"};
  std::string path_ = (dir_ / "mrd.toml").string();
};

TEST_F(Reload, TheSameFileIsValidAndUnchanged) {
  write(kGood);
  const auto outcome = ConfigReload(path_, kGood).check();
  EXPECT_EQ(outcome.priority, Priority::kNotice);
  EXPECT_EQ(outcome.text, "SIGHUP: " + path_ + " is valid and unchanged, the running config stays");
}

TEST_F(Reload, AValidChangeWaitsForTheNextStartAndSaysSo) {
  write(kGood + "[safety]\nstale_periods = 5\n");
  const auto outcome = ConfigReload(path_, kGood).check();
  EXPECT_EQ(outcome.priority, Priority::kWarning);
  EXPECT_EQ(outcome.text, "SIGHUP: " + path_ +
                              " is valid and differs from the running config; it takes effect at the next start "
                              "(systemctl restart mrd-controller: SAFE, then a fresh start), the running config stays");
}

TEST_F(Reload, ABadFileIsAnErrorWithEveryProblemAndTheRunningConfigStays) {
  write(kGood + "[safety]\nstale_periods = 0\n[loop]\nrate = 1e9\n");
  const auto outcome = ConfigReload(path_, kGood).check();
  EXPECT_EQ(outcome.priority, Priority::kErr);
  EXPECT_EQ(outcome.text, "SIGHUP: " + path_ + " is not valid (2 error(s)), the running config stays:\n" + path_ +
                              ":6: safety.stale_periods: must be >= 1, got 0\n" + path_ +
                              ":8: loop.rate: must be in 10..20000 Hz, got 1e+09");
  write("");  // truncated by an editor: no back ends
  EXPECT_EQ(ConfigReload(path_, kGood).check().priority, Priority::kErr);
}

TEST_F(Reload, TheEmbeddedConfigHasNothingToReRead) {
  const auto outcome = ConfigReload("", "").check();
  EXPECT_EQ(outcome.priority, Priority::kNotice);
  EXPECT_EQ(outcome.text, "SIGHUP: the embedded config runs (no --config): nothing to re-read, the running config stays");
}

}  // namespace
