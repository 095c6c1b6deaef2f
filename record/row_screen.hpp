#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "record/recorded_run.hpp"

namespace mrd::record {

// What a table keeps of a row by its time, whatever else the row holds: the rules of issue 27
// shared by the run readers (RunAssembler) and the controller's telemetry (tools/hil). The
// caller keeps the rows and acts on each verdict; the screen only remembers times.
class RowScreen {
 public:
  enum class Verdict : std::uint8_t {
    kKeep,
    kDuplicate,     // same time and values as the row kept last: set aside (the first is kept)
    kTimeConflict,  // the time repeats with other values, or goes back: set aside
    // The row kept last was a stray written far ahead: set it aside (time_conflict), keep the
    // row set aside just before this one after all, then this one.
    kKeepAfterStray,
    // The time stayed behind for kMaxConflictsInARow rows: a clock that jumped back, two runs in
    // one file; clock_jumped_back() says so.
    kClockJumpedBack,
  };

  // Whether a row at `time` needs its values compared with the row kept last (repeats_last_row).
  [[nodiscard]] bool repeats_last_time(double time) const { return kept_ > 0 && time == last_; }
  // The verdict on a row of finite cells at `position` (its line or sample), and the screen
  // moved on as if the caller followed it.
  [[nodiscard]] Verdict screen(double time, bool repeats_last_row, std::size_t position);
  // "time stays behind 0.109 s for 20 rows from line 12: the clock jumped back; split the file there"
  [[nodiscard]] std::string clock_jumped_back(std::string_view where) const;

  static constexpr int kMaxConflictsInARow = 20;

 private:
  void keep(double time);

  std::size_t kept_ = 0;
  double last_ = 0.0;    // time of the row kept last
  double before_ = 0.0;  // and of the one before it
  bool pending_ = false;  // the last row was set aside for its time (a stray's neighbour, maybe)
  double pending_time_ = 0.0;
  int conflicts_in_a_row_ = 0;
  std::size_t conflict_start_ = 0;
};

// "20 duplicate (first at line 240), 5 non_finite (first at line 3012)": the rows set aside,
// counted per reason, "" when none.
[[nodiscard]] std::string set_aside_counts(const std::vector<RecordedRun::SetAsideRow>& rows,
                                           std::string_view where);

}  // namespace mrd::record
