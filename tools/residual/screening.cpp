#include "tools/residual/screening.hpp"

#include <algorithm>
#include <cmath>

#include "tools/signal/signal_scale.hpp"

namespace mrd::tools {

std::string_view to_string(ScreenReason r) {
  switch (r) {
    case ScreenReason::kClipped: return "clipped";
    case ScreenReason::kStuck: return "stuck";
    case ScreenReason::kSpike: return "spike";
    case ScreenReason::kGap: return "gap";
    case ScreenReason::kDuplicate: return "duplicate";
    case ScreenReason::kTimeConflict: return "time_conflict";
    case ScreenReason::kNonFinite: return "non_finite";
    case ScreenReason::kImplausible: return "implausible";
    case ScreenReason::kSettling: return "settling";
  }
  return "?";
}

namespace {

// The value below which a share `q` of the channel lies.
double quantile(std::vector<double> c, double q) {
  const auto at = c.begin() + static_cast<std::ptrdiff_t>(q * static_cast<double>(c.size() - 1));
  std::nth_element(c.begin(), at, c.end());
  return *at;
}

// How far the channel moves per sample just outside [first, last]: the mean absolute step over
// up to four samples on each side.
double slope_outside(const std::vector<double>& c, std::size_t first, std::size_t last) {
  double sum = 0.0;
  int n = 0;
  for (std::size_t k = 1; k <= 4 && first >= k; ++k, ++n) sum += std::fabs(c[first - k + 1] - c[first - k]);
  for (std::size_t k = 1; k <= 4 && last + k < c.size(); ++k, ++n) sum += std::fabs(c[last + k] - c[last + k - 1]);
  return n > 0 ? sum / n : 0.0;
}

// Whether the damper moves over [first, last] by the other channels: the recorded velocity, or
// the displacement, or the force.
bool moving(const record::RecordedRun& run, const std::string& channel, std::size_t first, std::size_t last) {
  const double duration = run.time[last] - run.time[first];
  if (channel != "velocity" && run.has_velocity()) {
    double travel = 0.0;
    for (std::size_t i = first; i < last; ++i) travel += std::fabs(run.velocity[i]) * (run.time[i + 1] - run.time[i]);
    const auto [lo, hi] = std::minmax_element(run.displacement.begin(), run.displacement.end());
    if (travel > 0.02 * (*hi - *lo) && duration > 0.0) return true;
  }
  if (channel != "displacement") {
    const auto [lo, hi] = std::minmax_element(run.displacement.begin() + static_cast<std::ptrdiff_t>(first),
                                              run.displacement.begin() + static_cast<std::ptrdiff_t>(last) + 1);
    const auto [all_lo, all_hi] = std::minmax_element(run.displacement.begin(), run.displacement.end());
    if (*hi - *lo > 0.02 * (*all_hi - *all_lo)) return true;
  }
  if (channel != "force" && run.has_force()) {
    const auto [lo, hi] = std::minmax_element(run.force.begin() + static_cast<std::ptrdiff_t>(first),
                                              run.force.begin() + static_cast<std::ptrdiff_t>(last) + 1);
    const auto [all_lo, all_hi] = std::minmax_element(run.force.begin(), run.force.end());
    if (*hi - *lo > 0.1 * (*all_hi - *all_lo)) return true;
  }
  return false;
}

struct Channel {
  const char* name;
  const std::vector<double>* values;
};

void find_flat_runs(const record::RecordedRun& run, const Channel& ch, const ScreeningOptions& o,
                    std::vector<ScreenedSpan>& spans) {
  const std::vector<double>& c = *ch.values;
  if (c.size() < o.min_flat + 2) return;
  const auto [lo, hi] = std::minmax_element(c.begin(), c.end());
  const double q = std::max(resolution(c), 1e-12 * std::max(std::fabs(*lo), std::fabs(*hi)));
  std::size_t first = 0;
  for (std::size_t i = 1; i <= c.size(); ++i) {
    if (i < c.size() && c[i] == c[first]) continue;
    const std::size_t last = i - 1;
    const std::size_t length = last - first + 1;
    if (length >= o.min_flat) {
      // At an extreme of its surroundings (a plateau's own length on each side): a load cell
      // saturates wherever the force passes its full scale, not only at the run's peak.
      const std::size_t from = first > length ? first - length : 0, to = std::min(last + length, c.size() - 1);
      const auto [near_lo, near_hi] = std::minmax_element(c.begin() + static_cast<std::ptrdiff_t>(from),
                                                          c.begin() + static_cast<std::ptrdiff_t>(to) + 1);
      const bool at_extreme = c[first] == *near_lo || c[first] == *near_hi;
      // Continued at the slope it had just outside, would the signal have left the level by
      // far more than its resolution? A natural peak flattens (slope ~ q per half plateau);
      // a clip cuts the signal at speed.
      const bool cut_at_speed = slope_outside(c, first, last) * static_cast<double>(length) > 8.0 * q;
      if (at_extreme && cut_at_speed) {
        spans.push_back({first, last, 0, 0, ch.name, ScreenReason::kClipped});
      } else if (moving(run, ch.name, first, last)) {
        spans.push_back({first, last, 0, 0, ch.name, ScreenReason::kStuck});
      }
    }
    first = i;
  }
}

// Mean absolute step of the channel over +-`half` samples around i, the steps into and out of
// i left out: how fast the signal itself moves there.
double local_step(const std::vector<double>& c, std::size_t i, std::size_t half) {
  const std::size_t from = i > half ? i - half : 1, to = std::min(i + half, c.size() - 1);
  double sum = 0.0;
  int n = 0;
  for (std::size_t k = from; k <= to; ++k) {
    if (k == i || k == i + 1) continue;
    sum += std::fabs(c[k] - c[k - 1]);
    ++n;
  }
  return n > 0 ? sum / n : 0.0;
}

// Whether the coil's current changed next to sample i: a force that follows a one-sample current
// pulse is the damper's, not a spike.
bool current_changed_near(const record::RecordedRun& run, std::size_t i) {
  if (run.coil.size() != run.size()) return false;
  for (std::size_t k = i > 1 ? i - 1 : 1; k <= std::min(i + 1, run.size() - 1); ++k)
    if (run.coil[k] != run.coil[k - 1]) return true;
  return false;
}

void find_spikes(const record::RecordedRun& run, const Channel& ch, const ScreeningOptions& o,
                 std::vector<ScreenedSpan>& spans) {
  const std::vector<double>& c = *ch.values;
  if (c.size() < 5) return;
  const auto [lo, hi] = std::minmax_element(c.begin(), c.end());
  // Far above the noise, and a visible share of the channel's range: a real damper's force
  // chatters at reversals, sample to sample, by a few per cent.
  const double floor = std::max({o.spike_sigmas * sample_noise(c), 4.0 * resolution(c), 0.05 * (*hi - *lo)});
  for (std::size_t i = 1; i + 1 < c.size(); ++i) {
    const double up = c[i] - c[i - 1], down = c[i] - c[i + 1];
    const double jump = std::min(std::fabs(up), std::fabs(down));
    // Far from both neighbours on the same side, the neighbours agreeing with each other, and
    // far beyond how fast the signal moves around it.
    if (up * down > 0.0 && jump > floor && std::fabs(c[i + 1] - c[i - 1]) < 0.25 * jump &&
        jump > 8.0 * local_step(c, i, 20) && !(std::string_view(ch.name) == "force" && current_changed_near(run, i))) {
      spans.push_back({i, i, 0, 0, ch.name, ScreenReason::kSpike});
    }
  }
}

// Spans where the force contradicts the motion: the displacement held within a band (a share of
// its stroke, or 6 noise sigmas) while the force swings beyond +-F and back, again and again,
// where F is a share of the force's half range, standing in for the yield force (the screening
// runs before any fit). No damper reverses its force without moving: a rig at its end stop, a
// load cell ringing. One reversal is a sine's turning point, and is kept.
void find_implausible(const record::RecordedRun& run, const ScreeningOptions& o, std::vector<ScreenedSpan>& spans) {
  const std::vector<double>& x = run.displacement;
  const std::vector<double>& f = run.force;
  if (!run.has_force() || x.size() < 8) return;
  const double band = std::max(o.implausible_band * (quantile(x, 0.99) - quantile(x, 0.01)), 6.0 * sample_noise(x));
  const double swing = o.implausible_force * 0.5 * (quantile(f, 0.99) - quantile(f, 0.01));
  if (!(swing > 0.0)) return;
  for (std::size_t first = 0; first < x.size();) {
    double lo = x[first], hi = x[first];
    std::size_t last = first;
    int side = 0, reversals = 0;
    for (std::size_t i = first; i < x.size(); ++i) {
      lo = std::min(lo, x[i]);
      hi = std::max(hi, x[i]);
      if (hi - lo > band) break;
      last = i;
      const int now = f[i] > swing ? 1 : f[i] < -swing ? -1 : 0;
      if (now != 0 && now != side) {
        reversals += side != 0;
        side = now;
      }
    }
    if (reversals >= o.implausible_reversals)
      spans.push_back({first, last, 0, 0, "force", ScreenReason::kImplausible});
    first = last + 1;
  }
}

void find_gaps(const record::RecordedRun& run, double gap_step, std::vector<ScreenedSpan>& spans) {
  const double period = run.sample_rate > 0.0 ? 1.0 / run.sample_rate : 0.0;
  if (period <= 0.0) return;
  const double longest = gap_step > 0.0 ? gap_step : 1.5 * period;
  for (std::size_t i = 1; i < run.size(); ++i) {
    if (run.time[i] - run.time[i - 1] > longest) spans.push_back({i, i, 0, 0, "time", ScreenReason::kGap});
  }
}

}  // namespace

Screening screen_run(const record::RecordedRun& run, const ScreeningOptions& o) {
  Screening s;
  const std::size_t n = run.size();
  s.excluded.assign(n, 0);
  if (n < 4) return s;
  std::vector<Channel> channels{{"displacement", &run.displacement}};
  if (run.has_force()) channels.push_back({"force", &run.force});
  if (run.has_velocity()) channels.push_back({"velocity", &run.velocity});
  for (const Channel& ch : channels) {
    find_flat_runs(run, ch, o, s.spans);
    if (std::string_view(ch.name) != "velocity") find_spikes(run, ch, o, s.spans);
  }
  find_gaps(run, o.gap_step, s.spans);
  find_implausible(run, o, s.spans);
  std::vector<ScreenedSpan> found = std::move(s.spans);
  s.spans.clear();
  // The reader's rows: reported where they were, nothing more set aside for them.
  for (const record::RecordedRun::SetAsideRow& row : run.set_aside_rows) {
    const std::size_t at = std::min(row.next_sample, n - 1);
    const ScreenReason reason = row.reason == "duplicate"       ? ScreenReason::kDuplicate
                                : row.reason == "time_conflict" ? ScreenReason::kTimeConflict
                                                                : ScreenReason::kNonFinite;
    s.spans.push_back({at, at, run.time[at], run.time[at], row.column.empty() ? "row" : row.column, reason, row.line});
  }
  set_aside(s, run, std::move(found), o.margin_s);
  return s;
}

double resolution(const std::vector<double>& c) {
  double smallest = 0.0;
  for (std::size_t i = 1; i < c.size(); ++i) {
    const double d = std::fabs(c[i] - c[i - 1]);
    if (d > 0.0 && (smallest == 0.0 || d < smallest)) smallest = d;
  }
  return smallest;
}

double sample_noise(const std::vector<double>& c, const std::vector<std::uint8_t>& excluded) {
  if (c.size() < 5) return 0.0;
  const auto kept = [&](std::size_t i) { return excluded.empty() || !excluded[i]; };
  std::vector<double> r;
  r.reserve(c.size());
  for (std::size_t i = 1; i + 1 < c.size(); ++i)
    if (kept(i - 1) && kept(i) && kept(i + 1)) r.push_back(std::fabs(c[i] - 0.5 * (c[i - 1] + c[i + 1])));
  if (r.empty()) return 0.0;
  auto mid = r.begin() + static_cast<std::ptrdiff_t>(r.size() / 2);
  std::nth_element(r.begin(), mid, r.end());
  return 1.4826 * *mid / std::sqrt(1.5);  // r's sigma is sqrt(1.5) of one sample's
}

std::vector<ScreenedSpan> settling_spans(const record::RecordedRun& run,
                                         const std::vector<std::pair<std::size_t, std::size_t>>& gaps,
                                         bool from_start, double share, double longest_s) {
  std::vector<ScreenedSpan> spans;
  if (run.size() < 2) return spans;
  const double largest = largest_magnitude(run.coil);
  const bool current_varies = varies(run.coil);
  const auto [x_lo, x_hi] = std::minmax_element(run.displacement.begin(), run.displacement.end());
  const double turn = 0.05 * (*x_hi - *x_lo);
  const auto longest = static_cast<std::size_t>(std::ceil(longest_s * run.sample_rate));
  // The first sample from `first` on where the coil has reached its extreme (J-A) and the rod
  // has travelled 5 % of its stroke one way, from `first` or from a turn after it (the
  // pre-yield element's state saturates within its travel).
  const auto settled_at = [&](std::size_t first) {
    const std::size_t end = std::min(run.size(), first + longest);
    std::size_t coil_at = first;
    if (current_varies)
      while (coil_at < end && std::fabs(run.coil[coil_at]) < share * largest) ++coil_at;
    std::size_t moved_at = first;
    double high = run.displacement[first], low = high;
    for (; moved_at < end; ++moved_at) {
      const double x = run.displacement[moved_at];
      high = std::max(high, x);
      low = std::min(low, x);
      if (x - low >= turn || high - x >= turn) break;
    }
    return std::max(coil_at, moved_at);
  };
  const auto settle_from = [&](std::size_t first) {
    const std::size_t settled = settled_at(first);
    if (settled > first)
      spans.push_back({first, settled - 1, 0.0, 0.0, current_varies ? "current" : "displacement", ScreenReason::kSettling});
  };
  if (from_start) settle_from(0);
  // A gap of a few samples bridges what the coil and the rod did closely enough.
  const auto shortest = static_cast<std::size_t>(std::max(10.0, std::ceil(0.01 * run.sample_rate)));
  for (const auto& [first, last] : gaps)
    if (last - first + 1 >= shortest && last + 1 < run.size()) settle_from(last + 1);
  return spans;
}

void set_aside(Screening& screening, const record::RecordedRun& run, std::vector<ScreenedSpan> found, double margin_s) {
  const std::size_t n = run.size();
  screening.excluded.resize(n, 0);
  const auto margin = static_cast<std::size_t>(std::ceil(margin_s * std::max(run.sample_rate, 1.0)));
  for (ScreenedSpan& span : found) {
    span.first -= std::min(span.first, margin);
    span.last = std::min(span.last + margin, n - 1);
    span.start_s = run.time[span.first];
    span.end_s = run.time[span.last];
    std::fill(screening.excluded.begin() + static_cast<std::ptrdiff_t>(span.first),
              screening.excluded.begin() + static_cast<std::ptrdiff_t>(span.last) + 1, std::uint8_t{1});
    screening.spans.push_back(std::move(span));
  }
  std::ranges::stable_sort(screening.spans, {}, &ScreenedSpan::first);
  screening.excluded_samples = static_cast<std::size_t>(std::ranges::count(screening.excluded, std::uint8_t{1}));
}

FaultedInputs inputs_reached(const ScreenedSpan& span) {
  switch (span.reason) {
    case ScreenReason::kSettling: return {};  // the record is sound; the model's state is not known
    case ScreenReason::kImplausible: return {.displacement = true, .velocity = true};  // the rod "standing"
    default: break;
  }
  if (span.channel == "force") return {};
  if (span.channel == "displacement") return {.displacement = true, .velocity = true};
  if (span.channel == "velocity") return {.velocity = true};
  return {.displacement = true, .velocity = true, .coil = true};
}

std::vector<std::uint8_t> faulted_samples(const Screening& screening, std::size_t samples, bool FaultedInputs::*which) {
  std::vector<std::uint8_t> faulted(samples, 0);
  std::vector<std::uint8_t> covered(samples, 0);
  for (const ScreenedSpan& span : screening.spans) {
    const bool reached = inputs_reached(span).*which;
    // A reader's row is reported at the sample after it but sets nothing aside.
    for (std::size_t i = span.first; i <= span.last && i < std::min(samples, screening.excluded.size()); ++i) {
      covered[i] = 1;
      if (reached && screening.excluded[i]) faulted[i] = 1;
    }
  }
  for (std::size_t i = 0; i < std::min(samples, screening.excluded.size()); ++i)
    if (screening.excluded[i] && !covered[i]) faulted[i] = 1;
  return faulted;
}

namespace {

// `channel` interpolated linearly across each stretch of `faulted` samples, between the sound
// samples either side (or holding the one there is).
void bridge(std::vector<double>& channel, const std::vector<double>& time, const std::vector<std::uint8_t>& faulted) {
  const std::size_t n = channel.size();
  if (n != faulted.size()) return;
  std::size_t i = 0;
  while (i < n) {
    if (!faulted[i]) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j < n && faulted[j]) ++j;
    const bool before = i > 0, after = j < n;
    for (std::size_t k = i; k < j; ++k) {
      if (before && after) {
        const double w = (time[k] - time[i - 1]) / (time[j] - time[i - 1]);
        channel[k] = channel[i - 1] + w * (channel[j] - channel[i - 1]);
      } else if (before) {
        channel[k] = channel[i - 1];
      } else if (after) {
        channel[k] = channel[j];
      }
    }
    i = j;
  }
}

}  // namespace

void bridge_excluded_inputs(record::RecordedRun& run, const Screening& screening) {
  const std::size_t n = run.size();
  bridge(run.displacement, run.time, faulted_samples(screening, n, &FaultedInputs::displacement));
  bridge(run.velocity, run.time, faulted_samples(screening, n, &FaultedInputs::velocity));
  bridge(run.coil, run.time, faulted_samples(screening, n, &FaultedInputs::coil));
}

}  // namespace mrd::tools
