// The readers on damaged input. The fuzzers (fuzz/) look for crashes; these tests assert what
// the readers do with the damage. One line at a time is damaged: the reader either refuses the
// file with an InputError naming that line (or the next, where the damage shows only against
// it), or reads it, and then every other line reads exactly as undamaged, none is lost and
// none is invented. A candump log's bad frames are dropped and each counted once, and the good
// frames after them still decode; a line that is not candump syntax is never read as a frame.
#include <gtest/gtest.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <random>
#include <regex>
#include <string>
#include <string_view>
#include <vector>

#include "hal/can/can_codec.hpp"
#include "record/candump_log.hpp"
#include "record/csv.hpp"
#include "record/run_reader.hpp"

namespace {

using mrd::record::InputError;
using mrd::record::RecordedRun;
namespace can = mrd::hal::can;

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  for (std::size_t start = 0; start < text.size();) {
    const std::size_t end = text.find('\n', start);
    out.push_back(text.substr(start, end - start));
    start = end == std::string::npos ? text.size() : end + 1;
  }
  return out;
}

std::string text_of(const std::vector<std::string>& lines) {
  std::string out;
  for (const auto& l : lines) out += l + "\n";
  return out;
}

bool blank(const std::string& line) {
  return line.find_first_not_of(" \t\r") == std::string::npos;
}

// Edits inside one line with characters of `alphabet`, never a newline, so every line keeps
// its number.
std::string damage(std::string line, std::string_view alphabet, std::mt19937& rng) {
  std::uniform_int_distribution<int> edits(1, 4);
  std::uniform_int_distribution<std::size_t> pick(0, alphabet.size() - 1);
  for (int e = edits(rng); e > 0 && !line.empty(); --e) {
    std::uniform_int_distribution<std::size_t> at(0, line.size() - 1);
    switch (rng() % 3) {
      case 0: line[at(rng)] = alphabet[pick(rng)]; break;
      case 1: line.insert(at(rng), 1, alphabet[pick(rng)]); break;
      default: line.erase(at(rng), 1 + rng() % 4); break;
    }
  }
  return line;
}

// What delimited files are made of. Without '(': a first line starting with it is a candump log
// (record/run_reader.hpp), judged by the candump tests.
constexpr std::string_view kDelimitedAlphabet = "0123456789.,-+eE \t\"xAnaif_";
constexpr std::string_view kCandumpAlphabet = "0123456789ABCDEFabcdef.#() R";

// The line an InputError names, "fuzz:12: column ..." -> 12; 0 when it names none.
std::size_t error_line(const std::string& message) {
  constexpr std::string_view kPrefix = "fuzz:";
  std::size_t line = 0;
  if (message.starts_with(kPrefix)) {
    std::from_chars(message.data() + kPrefix.size(), message.data() + message.size(), line);
  }
  return line;
}

void expect_finite_and_time_increasing(const RecordedRun& run) {
  for (std::size_t i = 0; i < run.size(); ++i) {
    ASSERT_TRUE(std::isfinite(run.time[i]) && std::isfinite(run.displacement[i]) && std::isfinite(run.coil[i]));
    if (i > 0) {
      ASSERT_GT(run.time[i], run.time[i - 1]);
    }
  }
}

struct Tally {
  int runs = 0;
  int errors = 0;
};

// Damages one line of `text` at a time, 3000 times, and checks the answer against the undamaged
// reading. `check_run(run, clean, damaged_index, damaged_lines)` judges a run that was read.
template <typename CheckRun>
Tally damage_line_by_line(const std::string& text, std::string_view alphabet,
                          const mrd::record::RunReadOptions& options, CheckRun check_run) {
  const RecordedRun clean = mrd::record::parse_recorded_run(text, "fuzz", options);
  const auto lines = lines_of(text);
  std::mt19937 rng(7);
  Tally tally;
  for (int i = 0; i < 3000; ++i) {
    const std::size_t index = rng() % lines.size();
    auto damaged = lines;
    damaged[index] = damage(lines[index], alphabet, rng);
    try {
      const RecordedRun run = mrd::record::parse_recorded_run(text_of(damaged), "fuzz", options);
      ++tally.runs;
      expect_finite_and_time_increasing(run);
      check_run(run, clean, index, damaged);
    } catch (const InputError& e) {
      ++tally.errors;
      const std::size_t named = error_line(e.what());
      // Or too few rows left once the damaged ones were set aside (named at the header).
      const bool too_few = std::string_view(e.what()).find("rows set aside") != std::string_view::npos;
      EXPECT_TRUE(named == index + 1 || named == index + 2 || too_few)
          << "line " << index + 1 << " damaged: '" << damaged[index] << "'\n" << e.what();
    }
    if (testing::Test::HasFailure()) break;  // one damaged text is enough to read
  }
  // Both outcomes are exercised.
  EXPECT_GT(tally.runs, 100);
  EXPECT_GT(tally.errors, 100);
  return tally;
}

// A delimited file: one sample a data line, whatever the damage. Every sample of an undamaged
// line is as before; a header's damage may change units, so only the count is judged then.
void check_delimited(const std::string& text, const mrd::record::RunReadOptions& options, std::size_t header_lines) {
  damage_line_by_line(text, kDelimitedAlphabet, options, [&](const RecordedRun& run, const RecordedRun& clean, std::size_t index,
                                         const std::vector<std::string>& damaged) {
    // A row the reader set aside (an emptied or nan cell, a time that now repeats or goes back) is
    // lost like a blank one, and only the damaged row may be.
    for (const RecordedRun::SetAsideRow& r : run.set_aside_rows)
      EXPECT_TRUE(r.line == index + 1 || r.line == index + 2) << r.line << ": " << damaged[index];
    const bool lost_line = blank(damaged[index]) || !run.set_aside_rows.empty();
    if (index < header_lines) {
      if (!lost_line) {
        EXPECT_EQ(run.size(), clean.size()) << damaged[index];
      }
      return;
    }
    const std::size_t row = index - header_lines;
    ASSERT_EQ(run.size(), clean.size() - (lost_line ? 1 : 0)) << damaged[index];
    // A time made to stray ahead near the end leaves it open which of two rows strayed: the reader
    // may set aside the row after the damaged one instead, and only those two are then unjudged.
    const bool either = !run.set_aside_rows.empty() && run.set_aside_rows.front().line == index + 2;
    for (std::size_t i = 0, j = 0; i < clean.size(); ++i) {
      if (either && (i == row || i == row + 1)) {
        if (i == row) ++j;
        continue;
      }
      if (i == row && lost_line) continue;
      if (i != row) {
        EXPECT_EQ(run.time[j], clean.time[i]) << damaged[index];
        EXPECT_EQ(run.displacement[j], clean.displacement[i]);
        EXPECT_EQ(run.coil[j], clean.coil[i]);
        if (clean.has_force()) {
          EXPECT_EQ(run.force[j], clean.force[i]);
        }
      }
      ++j;
    }
  });
}

TEST(RunReaders, DamagedOwnCsvIsRefusedAtTheDamagedLineOrReadWithNoRowLost) {
  check_delimited(
      "time_s,displacement_mm,current_A,force_kN,velocity_mm_s\n0,1,0.5,1,2\n0.001,2,0.5,1.1,3\n"
      "0.002,3,0.5,1.2,4\n0.003,4,0.6,1.3,5\n",
      {}, 1);
}

TEST(RunReaders, DamagedForeignFilesAreRefusedAtTheDamagedLineOrReadWithNoRowLost) {
  mrd::record::RunReadOptions dyke;
  dyke.columns =
      mrd::record::parse_column_mapping("t=time_s,D=displacement_cm,Y=voltage_V,F=force_N");
  check_delimited(
      "\"t\",\"A\",\"D\",\"Y\",\"fs\",\"V\",\"F\",\n0,-32.3,0.021,2.25,3004.8,7.8,946.9,\n"
      "0.0003328,-31.0,0.023,2.25,,7.5,945.2,\n0.0006656,-29.5,0.026,2.25,,7.3,943.2,\n",
      dyke, 1);
  mrd::record::RunReadOptions quiroz;
  quiroz.columns =
      mrd::record::parse_column_mapping("1=time_s,2=displacement_mm,3=velocity_mm_s,4=force_N");
  quiroz.current = 0.5;
  check_delimited(
      "  0.0e+00 -1.02e-01 1.08e+00 -1.46e+01\n  5.0e-03 -9.67e-02 1.16e+00 -1.11e+01\n"
      "  1.0e-02 -9.11e-02 1.21e+00 -0.98e+01\n",
      quiroz, 0);
}

// The text of a frame's id, "110" in "(...) vcan0 110#...": the checksum covers the payload
// only (mrd.dbc), so damage that turns one of our ids into another is the one corruption no
// reader can see, and is left out of the "nothing invented" check.
std::string id_of(const std::string& line) {
  const std::size_t hash = line.find('#');
  const std::size_t space = line.rfind(' ', hash);
  return hash == std::string::npos || space == std::string::npos ? "" : line.substr(space + 1, hash - space - 1);
}

// candump -l's line, "(seconds.fraction) interface id#data [R|T]", written from its format
// rather than from the reader: a line it does not match must be refused.
bool candump_syntax(const std::string& line) {
  static const std::regex kLine(
      R"([ \t\r]*\(\d+(\.\d{1,9})?\)[ \t]+[^ \t]+[ \t]+([0-9A-Fa-f]{3}|[0-9A-Fa-f]{8}))"
      R"(#(([0-9A-Fa-f]{2}){0,8}|[Rr][0-9A-Fa-f]?|#[0-9A-Fa-f]([0-9A-Fa-f]{2}){0,64})([ \t]+[RT])?[ \t\r]*)");
  return std::regex_match(line, kLine);
}

TEST(RunReaders, DamagedCandumpLineIsRefusedThereOrCountedWithNoGoodFrameLost) {
  std::string log;
  for (std::uint8_t i = 0; i < 6; ++i) {
    const auto t = 100000 + 1000 * i;
    log += mrd::record::candump_line(
               1700000000, t, "vcan0",
               can::encode_command(can::kDefaultCommandId, {0.1 * i, true, i}).frame) +
           "\n";
    log += mrd::record::candump_line(
               1700000000, t + 500, "vcan0",
               can::encode_lvdt(can::kDefaultLvdtId, {0.001 * (i + 1), false, i}).frame) +
           "\n";
  }
  const auto original = lines_of(log);
  const Tally tally = damage_line_by_line(log, kCandumpAlphabet, {}, [&](const RecordedRun& run, const RecordedRun& clean,
                                                       std::size_t index, const std::vector<std::string>& damaged) {
    EXPECT_TRUE(blank(damaged[index]) || candump_syntax(damaged[index]))
        << "read a line that is not candump syntax: '" << damaged[index] << "'";
    const auto stats = mrd::record::parse_candump(text_of(damaged), "fuzz").stats;
    // Every frame line lands in exactly one count.
    const auto frame_lines = static_cast<std::size_t>(std::count_if(
        damaged.begin(), damaged.end(), [](const std::string& l) { return !blank(l); }));
    EXPECT_EQ(stats.lvdt_frames + stats.command_frames + stats.feedback_frames + stats.other_frames +
                  stats.dropped(),
              frame_lines)
        << damaged[index];
    EXPECT_EQ(run.size() + stats.samples_before_current, stats.lvdt_frames);
    if (id_of(damaged[index]) != id_of(original[index])) return;
    // Nothing invented: the run's displacements are the undamaged log's, in order, with at
    // most the damaged frame's (or the sample that lost its current) missing.
    EXPECT_GE(run.size() + 1, clean.size()) << damaged[index];
    std::size_t j = 0;
    for (std::size_t i = 0; i < clean.size() && j < run.size(); ++i) j += run.displacement[j] == clean.displacement[i];
    EXPECT_EQ(j, run.size()) << "a displacement the log never carried: " << damaged[index];
  });
  EXPECT_GT(tally.runs, 200) << "damage to a frame's payload is dropped, not refused";
}

// 500 good LVDT frames, each followed by one bad frame of a random kind: every good frame is
// in the run, in order, and nothing else; each bad frame is counted once, under its kind.
TEST(RunReaders, GoodFramesAmongGarbageAllDecodeAndEachBadFrameIsCountedOnce) {
  std::mt19937 rng(11);
  std::string log;
  std::size_t line = 0;
  std::int64_t us = 0;
  const auto add = [&](const std::string& frame) {
    us += 100;  // 1,500 lines stay within the second's six digits
    log += "(1700000000." + std::to_string(100000 + us) + ") vcan0 " + frame + "\n";
    ++line;
  };
  const auto hex = [](const can::Frame& f, std::size_t length) {
    std::string out;
    for (std::size_t i = 0; i < length; ++i) {
      out += "0123456789ABCDEF"[f.data[i] >> 4];
      out += "0123456789ABCDEF"[f.data[i] & 0x0F];
    }
    return out;
  };
  const auto lvdt = [](std::int32_t um, bool fault, int counter) {
    return can::encode_lvdt(can::kDefaultLvdtId, {um * 1e-6, fault, static_cast<std::uint8_t>(counter)}).frame;
  };
  add("210#" + hex(can::encode_command(can::kDefaultCommandId, {0.4, true, 0}).frame, 8));

  mrd::record::CandumpStats expected;
  std::vector<double> displacement;
  std::size_t first_dropped = 0;
  int counter = 0;
  for (int i = 0; i < 500; ++i) {
    const auto um = static_cast<std::int32_t>(37 * i - 9000);
    const can::Frame good = lvdt(um, false, counter);
    add("110#" + hex(good, 8));
    displacement.push_back(static_cast<double>(um) * 1e-6);
    expected.lvdt_frames++;
    counter = (counter + 1) & 0x0F;
    const auto dropped = [&](std::size_t& count) {
      ++count;
      if (first_dropped == 0) first_dropped = line;
    };
    switch (rng() % 8) {
      case 0: {  // the next frame with a burst of up to 8 flipped bits, in the CRC's bit order
        can::Frame bad = lvdt(um + 1, false, counter);
        const auto at = rng() % 57;
        const auto burst = (rng() % 256) | 1;
        for (std::size_t b = 0; b < 8; ++b) {
          if ((burst >> b) & 1) bad.data[(at + b) / 8] ^= static_cast<std::uint8_t>(0x80u >> ((at + b) % 8));
        }
        add("110#" + hex(bad, 8));
        dropped(expected.bad_checksum);
        break;
      }
      case 1:  // the next frame cut short
        add("110#" + hex(lvdt(um + 1, false, counter), rng() % 8));
        dropped(expected.wrong_dlc);
        break;
      case 2:  // the good frame again
        add("110#" + hex(good, 8));
        dropped(expected.repeated_counter);
        break;
      case 3:  // the conditioner flags its sensor: in sequence, its value not used
        add("110#" + hex(lvdt(um + 1, true, counter), 8));
        dropped(expected.sensor_fault);
        counter = (counter + 1) & 0x0F;
        break;
      case 4:  // a neighbour's frame
        add("123#" + hex(lvdt(um + 1, false, counter), rng() % 9));
        expected.other_frames++;
        break;
      case 5:  // a remote request on our id
        add("110#R");
        expected.other_frames++;
        break;
      case 6:  // CAN FD on our id
        add("110##0" + hex(lvdt(um + 1, false, counter), 8));
        expected.other_frames++;
        break;
      default:  // our id as a 29-bit one
        add("00000110#" + hex(lvdt(um + 1, false, counter), 8));
        expected.other_frames++;
        break;
    }
  }
  const auto log_read = mrd::record::parse_candump(log, "fuzz");
  const auto& s = log_read.stats;
  EXPECT_EQ(log_read.run.displacement, displacement);
  EXPECT_EQ(s.lvdt_frames, expected.lvdt_frames);
  EXPECT_EQ(s.command_frames, 1u);
  EXPECT_EQ(s.bad_checksum, expected.bad_checksum);
  EXPECT_EQ(s.wrong_dlc, expected.wrong_dlc);
  EXPECT_EQ(s.repeated_counter, expected.repeated_counter);
  EXPECT_EQ(s.sensor_fault, expected.sensor_fault);
  EXPECT_EQ(s.other_frames, expected.other_frames);
  EXPECT_EQ(s.sequence_gaps, 0u) << "a bad frame moved a rolling counter";
  EXPECT_EQ(s.first_dropped_line, first_dropped);
  EXPECT_EQ(s.samples_before_current, 0u);
  // Every kind came up.
  for (const std::size_t n : {s.bad_checksum, s.wrong_dlc, s.repeated_counter, s.sensor_fault}) EXPECT_GT(n, 30u);
}

}  // namespace
