// The controller writes telemetry only below telemetry.directory (docs/RELIABILITY.md, least
// privilege): the config check resolves the path with its symbolic links, and the writer does
// not follow a link planted at the file itself after the check.
#include <unistd.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "config/config_loader.hpp"
#include "telemetry/csv_telemetry_writer.hpp"
#include "telemetry/telemetry_queue.hpp"

namespace {

namespace fs = std::filesystem;
using mrd::config::LoadedConfig;

class TelemetryDirectory : public ::testing::Test {
 protected:
  void SetUp() override {
    // One directory per process: ctest runs these tests side by side.
    root_ = fs::temp_directory_path() / ("mrd_telemetry_directory_" + std::to_string(getpid()));
    fs::remove_all(root_);
    fs::create_directories(logs_ = root_ / "logs");
    fs::create_directories(outside_ = root_ / "outside");
  }
  void TearDown() override { fs::remove_all(root_); }

  // The config with telemetry at `path` below logs_, checked as --check-config would.
  LoadedConfig with_path(const std::string& path) const {
    return mrd::config::load_config_text(
        "[telemetry]\npath = \"" + path + "\"\ndirectory = \"" + logs_.string() + "\"\n", "t.toml");
  }
  static bool refused(const LoadedConfig& c) {
    for (const auto& e : c.errors) {
      if (e.to_string().starts_with("t.toml:2: telemetry.path: ") &&
          e.to_string().find("not a file below telemetry.directory") != std::string::npos) {
        return true;
      }
    }
    return false;
  }

  fs::path root_, logs_, outside_;
};

TEST_F(TelemetryDirectory, PathsBelowTheDirectoryAreAccepted) {
  for (const char* path : {"run.csv", "runs/2026/run.csv", "./a/../run.csv"}) {
    EXPECT_TRUE(with_path(path).ok()) << path << "\n" << with_path(path).report();
  }
  EXPECT_TRUE(with_path((logs_ / "abs.csv").string()).ok());
  auto config = with_path("runs/run.csv").config;
  EXPECT_EQ(config.telemetry.resolved_path(), (logs_ / "runs/run.csv").string());
}

TEST_F(TelemetryDirectory, PathsThatLeaveItAreRefused) {
  EXPECT_TRUE(refused(with_path("../outside/run.csv"))) << with_path("../outside/run.csv").report();
  EXPECT_TRUE(refused(with_path("runs/../../run.csv")));
  EXPECT_TRUE(refused(with_path("/etc/mrd/mrd.toml")));
  EXPECT_TRUE(refused(with_path(".")));  // the directory itself is not a file
  EXPECT_EQ(with_path("../x.csv").errors[0].to_string(),
            "t.toml:2: telemetry.path: '../x.csv' resolves to " + (root_ / "x.csv").string() +
                ", not a file below telemetry.directory '" + logs_.string() + "'");
}

TEST_F(TelemetryDirectory, ASymbolicLinkOutOfItIsFollowedAndRefused) {
  fs::create_directory_symlink(outside_, logs_ / "escape");
  EXPECT_TRUE(refused(with_path("escape/run.csv")));
  fs::create_directory_symlink(logs_, outside_ / "back");  // a link that stays inside is fine
  EXPECT_TRUE(with_path((outside_ / "back" / "run.csv").string()).ok());
}

TEST_F(TelemetryDirectory, ACommandLineOverrideIsCheckedToo) {
  auto config = with_path("run.csv").config;
  config.telemetry.path = (outside_ / "run.csv").string();  // mrd-controller --telemetry
  const auto checked = mrd::config::revalidate(config, "command line");
  ASSERT_FALSE(checked.ok());
  EXPECT_NE(checked.report().find("command line: telemetry.path: "), std::string::npos) << checked.report();
}

TEST_F(TelemetryDirectory, TheWriterDoesNotFollowALinkPlantedAtTheFile) {
  const fs::path victim = outside_ / "victim.txt";
  std::ofstream(victim) << "keep\n";
  fs::create_symlink(victim, logs_ / "run.csv");
  mrd::telemetry::TelemetryQueue queue(16);
  mrd::telemetry::CsvTelemetryWriter writer(queue, 0.05);
  const auto started = writer.start((logs_ / "run.csv").string());
  EXPECT_FALSE(started.ok);
  EXPECT_NE(started.error.find("cannot open telemetry file"), std::string::npos) << started.error;
  std::ifstream in(victim);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "keep");
}

}  // namespace
