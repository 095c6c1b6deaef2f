#include "record/candump_log.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "tests/record/input_error_of.hpp"
#include "record/run_reader.hpp"
#include "tests/support/simulated_rig_run.hpp"

namespace {

namespace can = mrd::hal::can;
using mrd::record::candump_line;
using mrd::record::parse_candump;
using mrd::record::RunReadOptions;

// Writes a candump -l log the way the bus would carry the frames: each sender's counter
// goes up by one per frame.
class LogWriter {
 public:
  void lvdt(double t, double metres, bool fault = false) {
    add(t, can::encode_lvdt(can::kDefaultLvdtId, {metres, fault, lvdt_counter_++}).frame);
  }
  void command(double t, double amps) {
    add(t, can::encode_command(can::kDefaultCommandId, {amps, true, command_counter_++}).frame);
  }
  void feedback(double t, double amps) {
    add(t, can::encode_feedback(can::kDefaultFeedbackId, {amps, false, feedback_counter_++}).frame);
  }
  void add(double t, const can::Frame& f, bool extended = false) {
    text += line(t, f, extended) + "\n";
  }
  static std::string line(double t, const can::Frame& f, bool extended = false) {
    const auto us = std::llround(t * 1e6);
    return candump_line(1700000000 + us / 1000000, us % 1000000, "vcan0", f, extended);
  }
  void raw(const std::string& l) { text += l + "\n"; }

  std::string text;

 private:
  std::uint8_t lvdt_counter_ = 0, command_counter_ = 0, feedback_counter_ = 0;
};

std::string candump_error_of(const std::string& text, const RunReadOptions& options = {}) {
  return mrd::record::testing::input_error_of(
      [&] { (void)parse_candump(text, "bus.log", options); });
}

TEST(CandumpLog, LineFormatIsCandumps) {
  const auto f = can::encode_lvdt(0x110, {0.001, false, 3}).frame;
  EXPECT_EQ(candump_line(1700000000, 123456, "vcan0", f),
            "(1700000000.123456) vcan0 110#E803000000000325");  // CRC-8 J1850 of E8 03 00 00 00 00
                                                                // 03, by hand: 0x25
}

TEST(CandumpLog, SamplesAreLvdtFramesWithTheNewestMeasuredCurrent) {
  LogWriter w;
  w.command(0.0000, 0.30);
  w.feedback(0.0002, 0.29);
  w.lvdt(0.0005, 0.001);
  w.command(0.0010, 0.40);
  w.feedback(0.0012, 0.39);
  w.lvdt(0.0015, 0.002);
  w.lvdt(0.0025, -0.003);
  const auto log = parse_candump(w.text, "bus.log");
  const auto& run = log.run;
  ASSERT_EQ(run.size(), 3u);
  EXPECT_NEAR(run.time[0], 0.0005, 1e-12);
  EXPECT_NEAR(run.time[2], 0.0025, 1e-12);
  EXPECT_DOUBLE_EQ(run.displacement[2], -0.003);
  EXPECT_DOUBLE_EQ(run.coil[0], 0.29);
  EXPECT_DOUBLE_EQ(run.coil[1], 0.39);
  EXPECT_DOUBLE_EQ(run.coil[2], 0.39);
  EXPECT_EQ(run.coil_source, "Coil_CurrentFeedback (measured current)");
  EXPECT_FALSE(run.has_force());
  EXPECT_NEAR(run.sample_rate, 1000.0, 1e-6);
  EXPECT_EQ(log.stats.lvdt_frames, 3u);
  EXPECT_EQ(log.stats.command_frames, 2u);
  EXPECT_EQ(log.stats.feedback_frames, 2u);
  EXPECT_EQ(log.stats.dropped(), 0u);
}

TEST(CandumpLog, WithoutFeedbackTheCommandIsTheCurrent) {
  LogWriter w;
  w.command(0.0, 0.25);
  w.lvdt(0.001, 0.0);
  w.command(0.0015, 0.5);
  w.lvdt(0.002, 0.0);
  const auto run = parse_candump(w.text, "bus.log").run;
  EXPECT_EQ(run.coil_source, "Coil_CurrentCommand (commanded current)");
  EXPECT_DOUBLE_EQ(run.coil[1], 0.5);
}

TEST(CandumpLog, FeedbackIgnoredWhenTheConfigSaysTheDriverSendsNone) {
  LogWriter w;
  w.command(0.0, 0.25);
  w.feedback(0.0, 0.2);
  w.lvdt(0.001, 0.0);
  w.lvdt(0.002, 0.0);
  RunReadOptions o;
  o.can.use_feedback = false;
  const auto log = parse_candump(w.text, "bus.log", o);
  EXPECT_DOUBLE_EQ(log.run.coil[0], 0.25);
  EXPECT_EQ(log.stats.other_frames, 1u);
}

TEST(CandumpLog, BadFramesAreDroppedCountedAndReported) {
  LogWriter w;
  w.feedback(0.0, 0.1);
  w.lvdt(0.001, 0.001);
  auto bad = can::encode_lvdt(can::kDefaultLvdtId, {0.002, false, 1}).frame;
  bad.data[0] ^= 0x01;
  w.add(0.002, bad);                                  // line 3: bad checksum
  w.raw(LogWriter::line(0.0025, bad).substr(0, 40));  // line 4: 5 bytes, wrong DLC
  w.add(0.003, can::encode_lvdt(can::kDefaultLvdtId, {0.003, false, 1}).frame);  // counter 1: ok
  w.add(0.004, can::encode_lvdt(can::kDefaultLvdtId, {0.004, false, 1}).frame);  // repeated
  w.add(0.005, can::encode_lvdt(can::kDefaultLvdtId, {0.005, true, 2}).frame);   // sensor fault
  w.add(0.006, can::encode_lvdt(can::kDefaultLvdtId, {0.006, false, 5}).frame);  // gap, used
  const auto log = parse_candump(w.text, "bus.log");
  EXPECT_EQ(log.stats.bad_checksum, 1u);
  EXPECT_EQ(log.stats.wrong_dlc, 1u);
  EXPECT_EQ(log.stats.repeated_counter, 1u);
  EXPECT_EQ(log.stats.sensor_fault, 1u);
  EXPECT_EQ(log.stats.first_dropped_line, 3u);
  EXPECT_EQ(log.stats.sequence_gaps, 1u);
  ASSERT_EQ(log.run.size(), 3u);
  EXPECT_DOUBLE_EQ(log.run.displacement[1], 0.003);
  EXPECT_DOUBLE_EQ(log.run.displacement[2], 0.006);
  ASSERT_EQ(log.run.notes.size(), 1u);
  EXPECT_EQ(log.run.notes[0],
            "candump: 3 LVDT, 0 command, 1 feedback frames used; dropped 4 (bad checksum 1, wrong "
            "DLC 1, repeated counter 1, sensor fault 1), first at line 3; 1 counter gaps; 0 other "
            "frames ignored; 0 LVDT samples before the first current frame left out");
}

TEST(CandumpLog, OtherFramesAreIgnoredAndCounted) {
  LogWriter w;
  w.command(0.0, 0.1);
  w.raw("(1700000000.000100) vcan0 123#DEADBEEF");
  w.raw("(1700000000.000200) vcan0 110#R");
  w.raw("(1700000000.000300) vcan0 110##1AABBCCDDEEFF0011");
  w.raw("(1700000000.000400) vcan0 20000004#0004000000000000");
  w.raw("(1700000000.000500) vcan0 00000110#E803000000000376");  // 29-bit, not our 11-bit LVDT
  w.raw("(1700000000.000600) can1 211#0000000000000000 R");      // bad checksum: ours, dropped
  w.lvdt(0.001, 0.0);
  w.lvdt(0.002, 0.0);
  const auto log = parse_candump(w.text, "bus.log");
  EXPECT_EQ(log.stats.other_frames, 5u);
  EXPECT_EQ(log.stats.bad_checksum, 1u);
  EXPECT_EQ(log.run.size(), 2u);
}

TEST(CandumpLog, SamplesBeforeTheFirstCurrentAreLeftOutAndCounted) {
  LogWriter w;
  w.lvdt(0.000, 0.0);
  w.command(0.0005, 0.2);
  w.lvdt(0.001, 0.0);
  w.lvdt(0.002, 0.0);
  const auto log = parse_candump(w.text, "bus.log");
  EXPECT_EQ(log.stats.samples_before_current, 1u);
  EXPECT_EQ(log.run.size(), 2u);
  EXPECT_NEAR(log.run.time[0], 0.001, 1e-12);  // from the log's first frame
}

TEST(CandumpLog, ExtendedIdsFromTheConfig) {
  RunReadOptions o;
  o.can.extended_ids = true;
  o.can.lvdt_id = 0x18FF0110;
  o.can.command_id = 0x18FF0210;
  LogWriter w;
  w.add(0.0, can::encode_command(o.can.command_id, {0.3, true, 0}).frame, true);
  w.add(0.001, can::encode_lvdt(o.can.lvdt_id, {0.01, false, 0}).frame, true);
  w.add(0.002, can::encode_lvdt(o.can.lvdt_id, {0.02, false, 1}).frame, true);
  const auto run = parse_candump(w.text, "bus.log", o).run;
  ASSERT_EQ(run.size(), 2u);
  EXPECT_DOUBLE_EQ(run.coil[1], 0.3);
}

TEST(CandumpLog, ConstantCurrentForALogWithoutCurrentFrames) {
  LogWriter w;
  w.lvdt(0.0, 0.0);
  w.lvdt(0.001, 0.001);
  EXPECT_EQ(candump_error_of(w.text),
            "bus.log: no current frames (command 0x210, feedback 0x211); give --current");
  RunReadOptions o;
  o.current = 0.6;
  EXPECT_DOUBLE_EQ(parse_candump(w.text, "bus.log", o).run.coil[1], 0.6);
  w.command(0.002, 0.1);
  EXPECT_EQ(candump_error_of(w.text, o),
            "bus.log: the log has current frames; --current and --current-from-name are for logs "
            "without them");
}

TEST(CandumpLogErrors, SyntaxErrorsNameLineAndColumn) {
  const std::string ok = "(1700000000.000000) vcan0 210#0000000000000000\n";
  auto second = [&](const std::string& line) { return candump_error_of(ok + line + "\n"); };
  EXPECT_EQ(second("1700000000.1 vcan0 110#00"),
            "bus.log:2: column 'timestamp': expected '(seconds.microseconds)', got '1700000000.1'");
  EXPECT_EQ(second("(17000x.1) vcan0 110#00"),
            "bus.log:2: column 'timestamp': '17000x.1' is not seconds.microseconds");
  EXPECT_EQ(second("(1700000000.000001)"),
            "bus.log:2: column 'interface': missing: expected '(time) interface id#data'");
  EXPECT_EQ(second("(1700000000.000001) vcan0"),
            "bus.log:2: column 'frame': missing: expected '(time) interface id#data'");
  EXPECT_EQ(second("(1700000000.000001) vcan0 110"),
            "bus.log:2: column 'frame': expected id#data, got '110'");
  EXPECT_EQ(second("(1700000000.000001) vcan0 1100#00"),
            "bus.log:2: column 'frame': id '1100' must be 3 hex digits (11-bit) or 8 (29-bit)");
  EXPECT_EQ(second("(1700000000.000001) vcan0 11G#00"),
            "bus.log:2: column 'frame': id '11G' is not hexadecimal");
  EXPECT_EQ(second("(1700000000.000001) vcan0 800#00"),
            "bus.log:2: column 'frame': id '800' is out of range");
  EXPECT_EQ(second("(1700000000.000001) vcan0 110#012"),
            "bus.log:2: column 'frame': odd number of hex digits in the data '012'");
  EXPECT_EQ(second("(1700000000.000001) vcan0 110#001122334455667788"),
            "bus.log:2: column 'frame': 9 data bytes; at most 8");
  EXPECT_EQ(second("(1700000000.000001) vcan0 110#ZZ"),
            "bus.log:2: column 'frame': data 'ZZ' is not hexadecimal");
  EXPECT_EQ(second("(1700000000.000001) vcan0 110#00 extra"),
            "bus.log:2: column 'frame': unexpected text after the frame: 'extra'");
}

TEST(CandumpLogErrors, TimeGoingBackwards) {
  EXPECT_EQ(candump_error_of("(1700000000.000002) vcan0 123#00\n(1700000000.000001) vcan0 123#00\n"),
            "bus.log:2: column 'timestamp': time goes backwards: 1700000000.000001 after "
            "1700000000.000002");
  LogWriter w;
  w.command(0.0, 0.1);
  w.lvdt(0.001, 0.0);
  w.add(0.001, can::encode_lvdt(can::kDefaultLvdtId, {0.0, false, 1}).frame);
  EXPECT_EQ(candump_error_of(w.text),
            "bus.log:3: column 'timestamp': LVDT time does not increase: 1700000000.001000 again");
}

TEST(CandumpLogErrors, WholeLogProblems) {
  EXPECT_EQ(candump_error_of("(1700000000.000000) vcan0 123#00\n"),
            "bus.log: no usable LVDT frames (id 0x110)");
  RunReadOptions o;
  o.columns = mrd::record::parse_column_mapping("t=time_s");
  EXPECT_EQ(candump_error_of("(1.0) vcan0 123#00\n", o),
            "bus.log: --columns is for CSV files, not candump logs");
}

TEST(CandumpLog, ARunWrittenAsALogReadsBackAtTheWiresResolution) {
  const auto run = mrd::tools::simulate_run(mrd::model::DamperModel{});
  const mrd::hal::can::SocketCanConfig ids;
  const auto back = parse_candump(mrd::record::format_candump(run, 1.0, ids), "sim.log");
  EXPECT_EQ(back.stats.dropped(), 0u);
  ASSERT_EQ(back.run.size(), run.size());
  for (std::size_t i = 0; i < run.size(); ++i) {
    ASSERT_NEAR(back.run.time[i], run.time[i], 0.5e-6);
    ASSERT_NEAR(back.run.displacement[i], run.displacement[i], 0.5e-6);
    ASSERT_NEAR(back.run.coil[i], run.coil[i], 0.5e-3);
  }
}

TEST(CandumpLog, ReadsLikeACsvThroughTheCommonReader) {
  LogWriter w;
  w.command(0.0, 0.2);
  w.lvdt(0.001, 0.01);
  w.lvdt(0.002, 0.02);
  const auto run = mrd::record::parse_recorded_run("\n  " + w.text, "bus.log");
  EXPECT_EQ(run.size(), 2u);
  EXPECT_EQ(run.notes.size(), 1u);
}

}  // namespace
