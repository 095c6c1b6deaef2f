// mrd-plant's log as a CSV reader wants it: the time origin, a '#' comment, before the column
// line (pandas.read_csv(f, comment='#')), and the column line even for a run with no row.
#include "sim/plant/run_log.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace {

std::string slurp(const std::filesystem::path& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(RunLog, TheOriginCommentComesBeforeTheColumnLine) {
  const auto path = std::filesystem::temp_directory_path() / "mrd_run_log_origin.csv";
  mrd::plant::RunLog log;
  ASSERT_TRUE(log.open(path.string()).ok);
  log.write_time_origin(12.5);
  mrd::plant::RigSample sample{};
  log.write(sample);
  log.close();
  const std::string text = slurp(path);
  const std::string origin = "# time_s 0 is CLOCK_MONOTONIC 12.500000000 s\n";
  const std::string columns = "time_s,displacement_mm,current_A,force_N,B_T,temperature_C\n";
  EXPECT_EQ(text.substr(0, origin.size() + columns.size()), origin + columns) << text;
  EXPECT_EQ(log.rows(), 1u);
  std::filesystem::remove(path);
}

TEST(RunLog, ARunWithNoRowStillHasItsColumnLine) {
  const auto path = std::filesystem::temp_directory_path() / "mrd_run_log_empty.csv";
  mrd::plant::RunLog log;
  ASSERT_TRUE(log.open(path.string()).ok);
  log.close();
  EXPECT_EQ(slurp(path), "time_s,displacement_mm,current_A,force_N,B_T,temperature_C\n");
  std::filesystem::remove(path);
}

}  // namespace
