// The telemetry's course over time: the gaps between its rows and the supervisor's transitions.
#include <algorithm>
#include <cstdio>

#include "tools/hil/telemetry_csv.hpp"

namespace mrd::tools {

using control::SupervisorState;

std::vector<TelemetryGap> find_gaps(const std::vector<TelemetryRow>& rows, double record_rate) {
  std::vector<TelemetryGap> gaps;
  if (rows.size() < 2 || record_rate <= 0.0) return gaps;
  // The file's own cycle step (telemetry.decimation): the median one.
  std::vector<std::uint64_t> steps;
  const auto cycles_between = [&](std::size_t i) {
    return rows[i].cycle > rows[i - 1].cycle ? rows[i].cycle - rows[i - 1].cycle : 0;
  };
  for (std::size_t i = 1; i < rows.size(); ++i) steps.push_back(cycles_between(i));
  std::ranges::nth_element(steps, steps.begin() + static_cast<std::ptrdiff_t>(steps.size() / 2));
  const std::uint64_t step = std::max<std::uint64_t>(steps[steps.size() / 2], 1);
  const double period = 1.0 / record_rate;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const std::uint64_t cycles = cycles_between(i);
    const double dt = rows[i].time - rows[i - 1].time;
    if (cycles <= step && dt <= 1.5 * period) continue;
    gaps.push_back({i - 1, rows[i - 1].time, rows[i].time, cycles > step ? (cycles - 1) / step : 0});
  }
  return gaps;
}

std::string to_string(const TelemetryGap& g, const std::vector<TelemetryRow>& rows) {
  char text[200];
  std::snprintf(text, sizeof text, "%.3f s from %.3f s (lines %zu-%zu): ", g.duration(), g.start,
                rows[g.before].line, rows[g.before + 1].line);
  return text + (g.missing > 0 ? std::to_string(g.missing) + " records missing"
                               : std::string("no record missing by the cycle count (the loop ran late)"));
}

std::vector<StateChange> state_changes(const std::vector<TelemetryRow>& rows, const std::vector<TelemetryGap>& gaps) {
  std::vector<StateChange> out;
  SupervisorState state = SupervisorState::kInit;
  auto gap = gaps.begin();
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto& r = rows[i];
    while (gap != gaps.end() && gap->before + 1 < i) ++gap;
    if (r.state != state) {
      out.push_back({r.cycle, r.time, state, r.state, r.trigger, std::nullopt});
      // After a late loop the row is the cycle itself, dated by its own time.
      if (gap != gaps.end() && gap->before + 1 == i && gap->missing > 0) out.back().within = *gap;
    }
    state = r.state;
  }
  return out;
}

std::string to_string(const StateChange& c) {
  char text[200];
  const int n = std::snprintf(text, sizeof text, "%s -> %s (%s) ", control::to_string(c.from).data(),
                              control::to_string(c.to).data(), control::to_string(c.trigger).data());
  if (c.within) {
    std::snprintf(text + n, sizeof text - static_cast<std::size_t>(n),
                  "within a gap: after %.3f s, by cycle %llu (%.3f s)", c.within->start,
                  static_cast<unsigned long long>(c.cycle), c.time);
  } else {
    std::snprintf(text + n, sizeof text - static_cast<std::size_t>(n), "at cycle %llu (%.3f s)",
                  static_cast<unsigned long long>(c.cycle), c.time);
  }
  return text;
}

}  // namespace mrd::tools
