#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "record/recorded_run.hpp"

namespace mrd::tools {

// Why a span of samples was set aside: no damper produced it.
enum class ScreenReason : std::uint8_t {
  kClipped,  // a channel held at its extreme where the signal was still going beyond it
  kStuck,    // a channel repeating one value while the others say the damper moves
  kSpike,    // one sample far from both neighbours, far above the noise
  kGap,      // a time step longer than 1.5 nominal periods
  // Rows the reader set aside (record::RecordedRun::set_aside_rows): no sample of the run is
  // lost to them beyond the row itself (a missing row is then a gap).
  kDuplicate,     // a repeated row, one kept
  kTimeConflict,  // the same time with other values, or time going back
  kNonFinite,     // an empty, nan or inf cell
  kImplausible,   // the force swings through both signs again and again while the rod stands still
  // The model's own: its state (the core's, the pre-yield element's) is not the record's after a
  // logging gap or at a run's start, until the current and the rod have settled it (settling_spans).
  kSettling,
};
[[nodiscard]] std::string_view to_string(ScreenReason r);

struct ScreenedSpan {
  std::size_t first = 0;  // sample indices of the run, inclusive, margin included
  std::size_t last = 0;
  double start_s = 0.0;   // the run's own time of `first` and `last` [s]
  double end_s = 0.0;
  std::string channel;    // "displacement", "force", "velocity" or "time"; a set-aside row's column
  ScreenReason reason = ScreenReason::kClipped;
  std::size_t line = 0;  // a set-aside row's line in the file (0 for the others)
};

struct Screening {
  std::vector<ScreenedSpan> spans;
  std::vector<std::uint8_t> excluded;  // per sample: 1 set aside
  std::size_t excluded_samples = 0;
};

struct ScreeningOptions {
  std::size_t min_flat = 8;          // samples of exact repeats before a run can be clipped or stuck
  double spike_sigmas = 12.0;        // a spike stands this many robust noise sigmas off its neighbours
  double margin_s = 0.005;           // set aside around each span: the zero-phase velocity spreads it [s]
  // implausible: the displacement within this share of its stroke (1st to 99th percentile) ...
  double implausible_band = 0.02;
  // ... while the force crosses from beyond +-(this share of its half range) to beyond the
  // other sign this many times (a sine's turning point crosses once).
  double implausible_force = 0.25;
  int implausible_reversals = 4;
  // [s] a time step longer than this is a gap; 0: 1.5 nominal periods. make_fit_series passes
  // record::fill_gaps' own (GapFilledRun::gap_step), which allows a jittered run its wander.
  double gap_step = 0.0;
};

// The smallest step the channel takes: its resolution (quantisation), or its noise if finer;
// 0 for a constant channel.
[[nodiscard]] double resolution(const std::vector<double>& channel);
// One sample's noise, robustly: 1.4826 MAD of the channel's deviation from its neighbours'
// midpoint (a motion sampled well above its frequency leaves almost none), over the samples
// not `excluded` (empty: all). 0 for fewer than 5.
[[nodiscard]] double sample_noise(const std::vector<double>& channel, const std::vector<std::uint8_t>& excluded = {});

// Finds the samples of `run` no damper produced (docs/CLOSING-THE-LOOP.md, "Screening"). Pure;
// linear in the run's length.
Screening screen_run(const record::RecordedRun& run, const ScreeningOptions& options = {});

// `found` (sample spans of `run`) widened by `margin_s` on either side (the zero-phase velocity
// spreads a fault), timed on the run, their samples excluded, and merged into `screening` in
// sample order: how screen_run sets its faults aside, and how a caller adds spans of its own.
void set_aside(Screening& screening, const record::RecordedRun& run, std::vector<ScreenedSpan> found, double margin_s);

// Where the model's state cannot be known from the record: from the end of each of `gaps` of
// at least 10 samples and 10 ms (the bridge is not what the coil and the rod did) and, with `from_start`, from the run's start
// (the core's history before it is not logged), until |coil| first reaches `share` of its
// largest value over the run (a loop tip wipes out J-A's memory; skipped where the current
// varies by less than 5 % of its largest value) and the rod has travelled 5 % of its stroke one
// way (the pre-yield element's state saturates), at most `longest_s` [s] each. Spans
// of `run`'s samples, reason kSettling, channel "current" (or "displacement" at a constant
// current).
std::vector<ScreenedSpan> settling_spans(const record::RecordedRun& run,
                                         const std::vector<std::pair<std::size_t, std::size_t>>& gaps,
                                         bool from_start, double share = 0.95, double longest_s = 2.0);

// The model's inputs a span's fault reaches. A fault of the force alone leaves the motion and
// the coil current as recorded; only a logging gap (or a row) reaches the coil's.
struct FaultedInputs {
  bool displacement = false;
  bool velocity = false;
  bool coil = false;
};
[[nodiscard]] FaultedInputs inputs_reached(const ScreenedSpan& span);

// Per sample of a run of `samples`: 1 where an excluded sample's span reaches the input that
// `which` picks (excluded samples no span covers reach every input).
[[nodiscard]] std::vector<std::uint8_t> faulted_samples(const Screening& screening, std::size_t samples,
                                                        bool FaultedInputs::*which);

// Each of the model's inputs (displacement, velocity, coil) interpolated linearly across the
// samples where a fault reaches it, so that the model's state runs through a fault sanely and
// follows the recorded coil current through a fault of the force (bridged there, a telegraph
// current's switches would be lost, and with them the lag's and the core's state for several
// time constants after the span). The force is left as it is (excluded samples are not fitted).
void bridge_excluded_inputs(record::RecordedRun& run, const Screening& screening);

}  // namespace mrd::tools
