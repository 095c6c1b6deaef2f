// Bad recorded runs end to end (docs/RELIABILITY.md): a line too long to be data, a truncated
// file, a run cut mid-row. NaN cells and time going backwards are in test_run_csv.cpp and
// test_candump_log.cpp.
#include <fcntl.h>
#include <sys/resource.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "tests/record/input_error_of.hpp"
#include "record/csv.hpp"
#include "record/run_reader.hpp"

namespace {

using mrd::record::kMaxLineLength;
using mrd::record::testing::input_error_of;

std::int64_t peak_resident_kib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss;
}

// A file of `header` then `size` bytes of NULs and no end of line: sparse, so it costs no disk
// and is written at once however large it is.
std::string sparse_file(const std::string& leaf, const std::string& header, std::int64_t size) {
  const std::string path = ::testing::TempDir() + leaf;
  const int fd = open(path.c_str(), O_CREAT | O_TRUNC | O_WRONLY, 0600);
  EXPECT_GE(fd, 0);
  EXPECT_EQ(write(fd, header.data(), header.size()), static_cast<ssize_t>(header.size()));
  EXPECT_EQ(ftruncate(fd, static_cast<off_t>(header.size()) + size), 0);
  close(fd);
  return path;
}

TEST(BadRuns, ATwoGigabyteLineIsRefusedWithoutReadingItIntoMemory) {
  const std::string path = sparse_file("mrd_two_gigabyte_line.csv",
                                       "time_s,displacement_mm,current_A\n0,1,0\n",
                                       std::int64_t{2} << 30);
  const auto before = peak_resident_kib();
  EXPECT_EQ(input_error_of([&] { (void)mrd::record::read_recorded_run(path); }),
            path + ":3: line longer than 1048576 bytes: not a text file this reader takes");
  // The reader stops after the cap: far less than the line, with room for the allocator.
  EXPECT_LT(peak_resident_kib() - before, 64 * 1024);
  unlink(path.c_str());
}

TEST(BadRuns, ALineOverTheCapInMemoryIsRefusedToo) {
  std::string text = "time_s,displacement_mm,current_A\n0,1,0\n0.001,";
  text.append(kMaxLineLength, '1');
  text += ",0\n";
  EXPECT_EQ(input_error_of([&] { (void)mrd::record::parse_recorded_run(text, "long.csv"); }),
            "long.csv:3: line longer than 1048576 bytes: not a text file this reader takes");
  // At the cap exactly, the line is read (and here refused for what it holds, not its length).
  std::string at_cap = "time_s,displacement_mm,current_A\n0,1,0\n0.001,1,";
  at_cap.append(kMaxLineLength - (at_cap.size() - at_cap.rfind('\n') - 1), '0');
  EXPECT_EQ(input_error_of([&] { (void)mrd::record::parse_recorded_run(at_cap, "cap.csv"); }).find(
                "line longer"),
            std::string::npos);
}

TEST(BadRuns, TruncatedFilesNameTheLineWhereTheyBreakOff) {
  const std::string good = "time_s,displacement_mm,current_A\n0,1,0\n0.001,2,0\n0.002,3,0\n";
  const auto error_of_first = [&](std::size_t bytes) {
    return input_error_of([&] { (void)mrd::record::parse_recorded_run(good.substr(0, bytes), "cut.csv"); });
  };
  // Cut inside the last row ("0.002,"): a short row, never a silent sample.
  EXPECT_EQ(error_of_first(good.size() - 4),
            "cut.csv:4: column 'displacement_mm': ragged row: 1 fields, but the header has 3");
  // Cut inside the header: its last column is a name the reader does not know.
  EXPECT_EQ(error_of_first(25).rfind("cut.csv:1: column 'cu': unknown column; expected time_s, ", 0), 0u);
  // Cut after the header: no samples.
  EXPECT_EQ(error_of_first(33), "cut.csv:1: a run needs at least 2 samples, got 0");
}

// Found by fuzz_run_csv (docs/RELIABILITY.md): a finite cell whose unit conversion overflows
// gave an infinite force.
TEST(BadRuns, AValueThatOverflowsOnceConvertedIsAnError) {
  EXPECT_EQ(input_error_of([] {
              (void)mrd::record::parse_recorded_run(
                  "time_s,displacement_mm,current_A,force_kN\n0,1,0,1e308\n1,1,0,1\n", "big.csv");
            }),
            "big.csv:2: column 'force_kN': '1e308' overflows once converted to SI");
}

}  // namespace
