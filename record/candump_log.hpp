#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "hal/can/can_codec.hpp"
#include "hal/can/socketcan_config.hpp"
#include "record/recorded_run.hpp"
#include "record/run_read_options.hpp"

namespace mrd::record {

// What the reader did with the frames of a candump log.
struct CandumpStats {
  std::size_t lvdt_frames = 0;      // LVDT_Displacement frames used
  std::size_t command_frames = 0;   // Coil_CurrentCommand frames decoded
  std::size_t feedback_frames = 0;  // Coil_CurrentFeedback frames decoded
  // Dropped, as the controller drops them (hal/can): never used, always counted.
  std::size_t bad_checksum = 0;
  std::size_t wrong_dlc = 0;
  std::size_t repeated_counter = 0;    // a stale or duplicated frame
  std::size_t sensor_fault = 0;        // LVDT frames flagging the sensor unusable
  std::size_t first_dropped_line = 0;  // the log line of the first dropped frame; 0 if none
  // Counter jumps (frames lost on the bus before the log saw them); their values are used.
  std::size_t sequence_gaps = 0;
  // Other ids, remote, CAN FD and error frames: not ours, ignored.
  std::size_t other_frames = 0;
  // LVDT samples before the first current frame: no known current, left out of the run.
  std::size_t samples_before_current = 0;

  [[nodiscard]] std::size_t dropped() const {
    return bad_checksum + wrong_dlc + repeated_counter + sensor_fault;
  }
  [[nodiscard]] std::string summary() const;  // one line for the run's notes
};

struct CandumpLog {
  RecordedRun run;
  CandumpStats stats;
};

// Reads a `candump -l` log: one frame a line, "(1700000000.123456) can0 110#0123456789ABCDEF"
// (3 hex digits: an 11-bit id, 8: a 29-bit id; "#R" remote, "##" CAN FD; an optional trailing
// direction R/T). The frames are decoded with the project's codec (hal/can, mrd.dbc) on the
// ids of options.can, from any interface.
//
// One run sample per usable LVDT frame, at the frame's time from the log's first frame. Its
// coil current is the newest current frame before it in the log: Coil_CurrentFeedback (the
// measured current) when the log has any and can.use_feedback is set, otherwise
// Coil_CurrentCommand, otherwise options.current. Force is not on the bus.
//
// Policy, the controller's: a frame with a wrong DLC, a bad checksum or a repeated rolling
// counter, and an LVDT frame flagging a sensor fault, are dropped and counted in the stats and
// the run's notes (with the first such line), never silently. A line that is not candump
// syntax, or time going backwards, is an InputError naming the line and the column
// ('timestamp', 'interface' or 'frame').
CandumpLog parse_candump(std::string_view text, const std::string& name,
                         const RunReadOptions& options = {});

// "(1700000000.123456) can0 110#0123456789ABCDEF": a frame as candump -l writes it, for tests
// and for writing a run as a log (canplayer can send it onto a bus). 8 hex digits when
// `extended`.
[[nodiscard]] std::string candump_line(std::int64_t seconds, std::int64_t microseconds,
                                       std::string_view interface, const hal::can::Frame& frame,
                                       bool extended = false);

// The run as a candump -l log, for replaying it onto a bus with canplayer or for trying the
// log path: per sample, a Coil_CurrentFeedback frame with the coil current (voltage x
// amps_per_volt, which a voltage run needs), then an LVDT_Displacement frame, both at the sample's
// time from the run's first sample, on the ids of `can`. Values take the wire's resolution (1 um,
// 1 mA); force is not on the bus. Throws InputError for a value the frame cannot carry.
[[nodiscard]] std::string format_candump(const RecordedRun& run,
                                         std::optional<double> amps_per_volt,
                                         const hal::can::SocketCanConfig& can,
                                         std::string_view interface = "can0");

}  // namespace mrd::record
