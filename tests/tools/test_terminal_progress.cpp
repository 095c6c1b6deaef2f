// The progress line: what it shows, that it rewrites itself in place, that it holds back reports
// closer than 100 ms but never a stage's last, and that there is none off a terminal.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <string>

#include "tools/terminal_progress.hpp"

namespace {

std::string read_back(std::FILE* file) {
  std::fflush(file);
  std::rewind(file);
  std::string text;
  for (int c; (c = std::fgetc(file)) != EOF;) text.push_back(static_cast<char>(c));
  return text;
}

}  // namespace

TEST(TerminalProgress, ShowsRoundCandidateCountAndBestErrorThenEndsTheLine) {
  std::FILE* file = std::tmpfile();
  ASSERT_NE(file, nullptr);
  {
    mrd::tools::TerminalProgress progress(file);
    progress.report({.stage = "round", .round = 2, .candidate = "coil_lag", .done = 3, .total = 3,
                     .best_error = 123.456, .unit = "N RMS"});
  }
  const std::string text = read_back(file);
  std::fclose(file);
  EXPECT_NE(text.find("\r\033[K["), std::string::npos) << text;
  EXPECT_NE(text.find(" s] round 2: coil_lag (3/3), best 123.5 N RMS"), std::string::npos) << text;
  EXPECT_EQ(text.back(), '\n');  // the destructor ends the status line
}

TEST(TerminalProgress, HoldsBackReportsWithin100MsButNotTheLastOfAStage) {
  std::FILE* file = std::tmpfile();
  ASSERT_NE(file, nullptr);
  {
    mrd::tools::TerminalProgress progress(file);
    for (int done = 1; done <= 50; ++done) {
      progress.report({.stage = "round", .round = 1, .done = done, .total = 50});
    }
  }
  const std::string text = read_back(file);
  std::fclose(file);
  EXPECT_NE(text.find("(1/50)"), std::string::npos) << text;   // the first shows
  EXPECT_NE(text.find("(50/50)"), std::string::npos) << text;  // the last of the stage shows
  // The 50 reports come within microseconds of each other: all but a few are held back.
  std::size_t lines = 0;
  for (std::size_t at = 0; (at = text.find('\r', at)) != std::string::npos; ++at) ++lines;
  EXPECT_LT(lines, 10u) << text;
}

// The time left in a stage at its pace so far, on an injected clock: 2 of 10 candidates in the 8 s
// after the stage's first report leave 6 to go at 4 s each.
TEST(TerminalProgress, EstimatesTheStagesTimeLeftFromItsPace) {
  std::FILE* file = std::tmpfile();
  ASSERT_NE(file, nullptr);
  std::chrono::steady_clock::time_point now{};
  {
    mrd::tools::TerminalProgress progress(file, [&] { return now; });
    progress.report({.stage = "round", .round = 1, .done = 2, .total = 10});
    now += std::chrono::seconds(8);
    progress.report({.stage = "round", .round = 1, .done = 4, .total = 10});
    now += std::chrono::seconds(1);
    progress.report({.stage = "round", .round = 2, .done = 1, .total = 10});  // a new stage: no pace yet
  }
  const std::string text = read_back(file);
  std::fclose(file);
  EXPECT_NE(text.find("[    8.0 s] round 1 (4/10), about 24 s left"), std::string::npos) << text;
  EXPECT_EQ(text.find("(2/10), about"), std::string::npos) << text;
  EXPECT_NE(text.find("round 2 (1/10)\n"), std::string::npos) << text;
}

TEST(TerminalProgress, NoneWhenQuietOrStderrIsNotATerminal) {
  EXPECT_EQ(mrd::tools::TerminalProgress::on_stderr(true), nullptr);
  if (isatty(2) != 1) EXPECT_EQ(mrd::tools::TerminalProgress::on_stderr(false), nullptr);
}
