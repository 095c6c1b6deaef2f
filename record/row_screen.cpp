#include "record/row_screen.hpp"

#include <cstdio>

namespace mrd::record {

RowScreen::Verdict RowScreen::screen(double time, bool repeats_last_row, std::size_t position) {
  if (kept_ == 0 || time > last_) {
    keep(time);
    return Verdict::kKeep;
  }
  if (time == last_ && repeats_last_row) return Verdict::kDuplicate;
  // Two rows in a row that go back, in order and past the row before the last kept one: that
  // row was the stray (a time written too far ahead), not they and every row after them.
  if (pending_ && time > pending_time_ && (kept_ == 1 || pending_time_ > before_)) {
    const double pending = pending_time_;
    --kept_;
    last_ = before_;
    keep(pending);
    keep(time);
    return Verdict::kKeepAfterStray;
  }
  if (++conflicts_in_a_row_ == kMaxConflictsInARow) return Verdict::kClockJumpedBack;
  if (conflicts_in_a_row_ == 1) conflict_start_ = position;
  pending_ = true;
  pending_time_ = time;
  return Verdict::kTimeConflict;
}

void RowScreen::keep(double time) {
  before_ = last_;
  last_ = time;
  ++kept_;
  pending_ = false;
  conflicts_in_a_row_ = 0;
}

std::string RowScreen::clock_jumped_back(std::string_view where) const {
  char behind[40];
  std::snprintf(behind, sizeof behind, "%.9g s", last_);
  return "time stays behind " + std::string(behind) + " for " + std::to_string(kMaxConflictsInARow) +
         " rows from " + std::string(where) + " " + std::to_string(conflict_start_) +
         ": the clock jumped back; split the file there";
}

std::string set_aside_counts(const std::vector<RecordedRun::SetAsideRow>& rows, std::string_view where) {
  std::string text;
  for (const std::string_view reason : {"duplicate", "time_conflict", "non_finite"}) {
    std::size_t count = 0, first = 0;
    for (const auto& r : rows) {
      if (r.reason != reason) continue;
      if (count++ == 0) first = r.line;
    }
    if (count == 0) continue;
    text.append(text.empty() ? "" : ", ")
        .append(std::to_string(count))
        .append(" ")
        .append(reason)
        .append(" (first at ")
        .append(where)
        .append(" ")
        .append(std::to_string(first))
        .append(")");
  }
  return text;
}

}  // namespace mrd::record
