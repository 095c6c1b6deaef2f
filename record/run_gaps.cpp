#include "record/run_gaps.hpp"

#include <array>
#include <cmath>
#include <string>

namespace mrd::record {

namespace {

// The channels a run may carry beside time, each filled alike; const or not as the run is.
template <typename Run>
auto channels_of(Run& run) {
  return std::array{&run.displacement, &run.coil, &run.force, &run.velocity, &run.B, &run.temperature};
}

}  // namespace

GapFilledRun fill_gaps(const RecordedRun& run) {
  GapFilledRun out;
  const std::size_t n = run.size();
  const double period = run.sample_rate > 0.0 ? 1.0 / run.sample_rate : 0.0;
  bool any = false;
  for (std::size_t i = 1; i < n && period > 0.0; ++i) any = any || run.time[i] - run.time[i - 1] > 1.5 * period;
  out.run = run;
  out.filled.assign(n, 0);
  if (!any) return out;

  RecordedRun& f = out.run;
  f.time.clear();
  for (std::vector<double>* c : channels_of(f)) c->clear();
  out.filled.clear();
  const auto from = channels_of(run);
  const auto to = channels_of(f);
  const auto append = [&](std::size_t i) {
    f.time.push_back(run.time[i]);
    for (std::size_t c = 0; c < from.size(); ++c)
      if (!from[c]->empty()) to[c]->push_back((*from[c])[i]);
    out.filled.push_back(0);
  };
  append(0);
  for (std::size_t i = 1; i < n; ++i) {
    const double dt = run.time[i] - run.time[i - 1];
    if (dt > 1.5 * period) {
      const auto missing = static_cast<std::size_t>(std::lround(dt / period)) - 1;
      const std::size_t first = f.size();
      for (std::size_t k = 1; k <= missing; ++k) {
        const double w = static_cast<double>(k) / static_cast<double>(missing + 1);
        f.time.push_back(run.time[i - 1] + w * dt);
        for (std::size_t c = 0; c < from.size(); ++c)
          if (!from[c]->empty()) to[c]->push_back((*from[c])[i - 1] + w * ((*from[c])[i] - (*from[c])[i - 1]));
        out.filled.push_back(1);
      }
      if (missing > 0) out.gaps.emplace_back(first, f.size() - 1);
    }
    append(i);
  }
  f.notes.push_back(std::to_string(out.gaps.size()) + " logging gaps filled with " +
                    std::to_string(f.size() - n) + " samples at the nominal period (inputs bridged, not fitted)");
  return out;
}

std::vector<std::pair<std::size_t, std::size_t>> unfilled_segments(const std::vector<std::uint8_t>& filled) {
  std::vector<std::pair<std::size_t, std::size_t>> out;
  std::size_t i = 0;
  while (i < filled.size()) {
    if (filled[i]) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j < filled.size() && !filled[j]) ++j;
    out.emplace_back(i, j);
    i = j;
  }
  return out;
}

}  // namespace mrd::record
