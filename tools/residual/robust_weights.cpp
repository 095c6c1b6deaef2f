#include "tools/residual/robust_weights.hpp"

#include <algorithm>
#include <cmath>

#include "tools/signal/signal_scale.hpp"

namespace mrd::tools {

namespace {

// The sigma of the kept samples' residual's Gaussian part.
double robust_sigma(const FitSeries& series, const std::vector<double>& predicted) {
  std::vector<double> r;
  r.reserve(series.size());
  for (std::size_t i = 0; i < series.size(); ++i)
    if (series.role[i] != SampleRole::kExcluded) r.push_back(series.force[i] - predicted[i]);
  return mad_sigma(std::move(r));
}

}  // namespace

RobustWeights huber_weights(const FitSeries& series, const std::vector<double>& predicted, const RobustLoss& loss) {
  RobustWeights out;
  out.weight.assign(series.size(), 1.0);
  out.sigma = robust_sigma(series, predicted);
  const double knee = loss.tuning * out.sigma;
  if (!(knee > 0.0)) return out;
  double lost = 0.0;
  std::size_t kept = 0;
  for (std::size_t i = 0; i < series.size(); ++i) {
    if (series.role[i] == SampleRole::kExcluded) continue;
    const double r = std::fabs(series.force[i] - predicted[i]);
    if (r > knee) out.weight[i] = knee / r;
    if (series.settles_after_switch(i)) continue;
    ++kept;
    lost += 1.0 - out.weight[i];
  }
  out.down_weighted_share = kept > 0 ? lost / static_cast<double>(kept) : 0.0;
  return out;
}

std::vector<DownWeightedSpan> down_weighted_spans(const FitSeries& series, const std::vector<double>& predicted,
                                                  const RobustWeights& weights, std::size_t most, double join_s) {
  std::vector<DownWeightedSpan> spans;
  for (std::size_t run = 0; run < series.run_starts.size(); ++run) {
    const std::size_t begin = series.run_starts[run];
    const std::size_t end = run + 1 < series.run_starts.size() ? series.run_starts[run + 1] : series.size();
    const std::string name = run < series.run_names.size() ? series.run_names[run] : "run " + std::to_string(run + 1);
    const auto time_of = [&](std::size_t i) {
      return series.time.empty() ? static_cast<double>(i - begin) * series.run_periods[run] : series.time[i];
    };
    DownWeightedSpan* open = nullptr;
    for (std::size_t i = begin; i < end; ++i) {
      if (series.role[i] == SampleRole::kExcluded || !(weights.weight[i] < 0.5)) continue;
      const double t = time_of(i);
      if (open == nullptr || t - open->end_s > join_s) {
        spans.push_back({name, t, t, 0, 0.0, 0.0});
        open = &spans.back();
      }
      open->end_s = t;
      ++open->samples;
      open->lost_weight += 1.0 - weights.weight[i];
      open->peak_residual = std::max(open->peak_residual, std::fabs(series.force[i] - predicted[i]));
    }
  }
  std::ranges::stable_sort(spans, std::greater<>{}, &DownWeightedSpan::lost_weight);
  if (spans.size() > most) spans.resize(most);
  return spans;
}

}  // namespace mrd::tools
