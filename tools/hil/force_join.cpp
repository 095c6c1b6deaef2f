#include "tools/hil/force_join.hpp"

#include <algorithm>
#include <cmath>

#include "record/csv.hpp"
#include "record/run_gaps.hpp"

namespace mrd::tools {

namespace {

// The plant log with its logging gaps marked (record::fill_gaps): a sample between two logged
// ones is known, one inside a gap is not, and a straight line across the gap is no force.
struct PlantLog {
  record::GapFilledRun log;

  [[nodiscard]] bool covers(double at) const {
    return !log.run.time.empty() && at >= log.run.time.front() && at <= log.run.time.back();
  }
  // Linear interpolation of `y` at `at`; false outside the log or inside a gap.
  bool sample_at(const std::vector<double>& y, double at, double& out) const {
    const std::vector<double>& t = log.run.time;
    if (t.size() < 2 || at < t.front() || at > t.back()) return false;
    const auto hi = static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), at) - t.begin());
    const std::size_t i = std::min(hi, t.size() - 1) - 1;
    const double w = (at - t[i]) / (t[i + 1] - t[i]);
    if (log.filled[i] != 0 || (w > 0.0 && log.filled[i + 1] != 0)) return false;
    out = y[i] + w * (y[i + 1] - y[i]);
    return true;
  }
};

double displacement_mismatch(const std::vector<TelemetryRow>& rows, const PlantLog& plant, double shift) {
  double sum = 0.0;
  std::size_t n = 0;
  for (const auto& r : rows) {
    double x = 0.0;
    if (!r.in_control() || !plant.sample_at(plant.log.run.displacement, r.time + shift, x)) continue;
    sum += (r.displacement - x) * (r.displacement - x);
    ++n;
  }
  return n > 0 ? std::sqrt(sum / static_cast<double>(n)) : INFINITY;
}

}  // namespace

ForceJoin join_force(const std::vector<TelemetryRow>& telemetry, const record::RecordedRun& plant_run,
                     double offset, double max_lag) {
  if (!plant_run.has_force()) throw record::InputError(plant_run.name + ": the plant log has no force column");
  const PlantLog plant{record::fill_gaps(plant_run)};
  const record::RecordedRun& run = plant.log.run;
  ForceJoin j;
  j.offset = offset;
  for (const auto& [first, last] : plant.log.gaps)
    j.plant_gaps.push_back({run.time[first - 1], run.time[last + 1]});
  const double step = run.sample_rate > 0.0 ? 0.25 / run.sample_rate : 2.5e-4;
  j.displacement_rms = INFINITY;
  for (double lag = -max_lag; lag <= max_lag + 1e-12; lag += step) {
    const double m = displacement_mismatch(telemetry, plant, offset + lag);
    if (m < j.displacement_rms) {
      j.displacement_rms = m;
      j.lag = lag;
    }
  }
  double sum = 0.0;
  for (const auto& r : telemetry) {
    double x = 0.0;
    double f = 0.0;
    const double at = r.time + offset + j.lag;
    if (!r.in_control()) continue;
    if (!plant.sample_at(run.force, at, f)) {
      if (plant.covers(at)) ++j.in_plant_gaps;
      continue;
    }
    plant.sample_at(run.displacement, at, x);
    const double e = r.force - f;
    sum += e * e;
    j.max_error = std::max(j.max_error, std::fabs(e));
    j.peak_force = std::max(j.peak_force, std::fabs(f));
    j.time.push_back(r.time);
    j.displacement.push_back(x);
    j.true_force.push_back(f);
    j.observer_force.push_back(r.force);
  }
  j.rows = j.true_force.size();
  if (j.rows == 0) {
    throw record::InputError(run.name + ": no telemetry row in control falls inside the plant log (offset " +
                     std::to_string(offset) + " s)");
  }
  j.rms_error = std::sqrt(sum / static_cast<double>(j.rows));
  return j;
}

}  // namespace mrd::tools
