#include "record/recorded_run.hpp"

#include <algorithm>
#include <cstdio>

#include "record/csv.hpp"

namespace mrd::record {

std::string_view to_string(CoilSignal s) {
  switch (s) {
    case CoilSignal::kCurrent: return "current";
    case CoilSignal::kCommandVoltage: return "command voltage";
  }
  return "unknown";
}

double nominal_sample_rate(const std::vector<double>& time) {
  // (Gaps: see the header.)
  if (time.size() < 2 || !(time.back() > time.front())) return 0.0;
  std::vector<double> steps(time.size() - 1);
  for (std::size_t i = 1; i < time.size(); ++i) steps[i - 1] = time[i] - time[i - 1];
  std::vector<double> sorted = steps;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2), sorted.end());
  const double median = sorted[sorted.size() / 2];
  // The mean of the steps that are not gaps: exact for a rounded time column, and a lost stretch
  // of samples does not slow the rate of the rest.
  // Only when such steps are rare: a time column coarser than the period (800 Hz written to
  // the millisecond) alternates steps of one and two units, and then the span is the rate.
  double span = 0.0;
  std::size_t count = 0;
  for (const double dt : steps) {
    if (dt > 1.5 * median) continue;
    span += dt;
    ++count;
  }
  const bool rare = steps.size() - count <= std::max<std::size_t>(10, steps.size() / 100);
  return rare && count > 0 && span > 0.0 ? static_cast<double>(count) / span
                                         : static_cast<double>(time.size() - 1) / (time.back() - time.front());
}

void check_sample_rate(const RecordedRun& run) {
  if (run.sample_rate >= kMinSampleRate && run.sample_rate <= kMaxSampleRate) return;
  char text[200];
  std::snprintf(text, sizeof text,
                ": sample rate %g Hz is outside %g Hz to %g Hz: is the time column in seconds "
                "(--columns names its unit, e.g. t=time_ms), or the rate (--sample-rate) right?",
                run.sample_rate, kMinSampleRate, kMaxSampleRate);
  throw InputError(run.name + text);
}

SamplingSummary summarize_sampling(const std::vector<double>& time) {
  SamplingSummary s;
  const double rate = nominal_sample_rate(time);
  if (rate <= 0.0) return s;
  s.nominal_period = 1.0 / rate;
  s.min_period = time[1] - time[0];
  s.max_period = s.min_period;
  for (std::size_t i = 1; i < time.size(); ++i) {
    const double dt = time[i] - time[i - 1];
    s.min_period = std::min(s.min_period, dt);
    s.max_period = std::max(s.max_period, dt);
    if (dt > 1.5 * s.nominal_period) ++s.gaps;
  }
  return s;
}

}  // namespace mrd::record
