#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "record/recorded_run.hpp"

namespace mrd::record {

// How a run's samples sit in time after fill_gaps.
enum class RunTiming : std::uint8_t {
  kEven,       // as logged, evenly (or on a time column coarser than its jitter)
  kResampled,  // taken unevenly and put on the even grid (resample_on_even_grid)
  kRecorded,   // taken unevenly and kept at their recorded times (UnevenTimes::kKeep)
};

// What fill_gaps does with samples taken unevenly.
enum class UnevenTimes : std::uint8_t {
  kResample,  // onto the even grid: for tools that step at one fixed period (mrd-replay)
  kKeep,      // at their recorded times: for tools that step each sample by its own interval
};

// A run with its logging gaps filled: a step longer than `gap_step` gets samples at the
// nominal period, every channel interpolated linearly across it. The inputs then carry a model's
// state through the gap (the coil most likely moved between the samples on either side); the
// filled samples are no measurement and are flagged.
struct GapFilledRun {
  RecordedRun run;
  std::vector<std::uint8_t> filled;  // per sample of `run`: 1 where no logger wrote it
  // Each gap's filled samples [first, last] in `run`, in order.
  std::vector<std::pair<std::size_t, std::size_t>> gaps;
  RunTiming timing = RunTiming::kEven;
  // [s] the step beyond which a step was a gap: 1.5 nominal periods, plus twice the wander on
  // a run taken unevenly (0 without a rate).
  double gap_step = 0.0;
};
// The run itself (no sample filled) when it has no gap, or when long steps are too many to be
// gaps (over 1 % of them, or 10: a time column coarser than the period; a note says so). A run
// whose samples were taken unevenly (measure_jitter) comes back resampled onto the even grid,
// its gaps filled the same way (resample_on_even_grid), or with `uneven` kKeep at its recorded
// times, only a step longer than 1.5 periods plus twice the wander filled. Throws
// InputError when the gaps would take over 4 times the run's samples (a timestamp far off, or
// separate runs in one file). The reader's set-aside rows are moved to the filled run's samples.
GapFilledRun fill_gaps(const RecordedRun& run, UnevenTimes uneven = UnevenTimes::kResample);

// The run with each step longer than `longest_step` [s] filled at the nominal period, every
// channel interpolated linearly across it (fill_gaps' filling, without its checks).
GapFilledRun fill_steps_longer_than(const RecordedRun& run, double longest_step);

}  // namespace mrd::record
