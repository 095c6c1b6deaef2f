#include "tools/hil/force_join.hpp"

#include <algorithm>
#include <cmath>

#include "record/csv.hpp"

namespace mrd::tools {

namespace {

// Linear interpolation of `y` over the strictly increasing `t`; false outside.
bool sample_at(const std::vector<double>& t, const std::vector<double>& y, double at, double& out) {
  if (t.size() < 2 || at < t.front() || at > t.back()) return false;
  const auto hi = static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), at) - t.begin());
  const std::size_t i = std::min(hi, t.size() - 1) - 1;
  const double w = (at - t[i]) / (t[i + 1] - t[i]);
  out = y[i] + w * (y[i + 1] - y[i]);
  return true;
}

double displacement_mismatch(const std::vector<TelemetryRow>& rows, const record::RecordedRun& plant,
                             double shift) {
  double sum = 0.0;
  std::size_t n = 0;
  for (const auto& r : rows) {
    double x = 0.0;
    if (!r.in_control() || !sample_at(plant.time, plant.displacement, r.time + shift, x)) continue;
    sum += (r.displacement - x) * (r.displacement - x);
    ++n;
  }
  return n > 0 ? std::sqrt(sum / static_cast<double>(n)) : INFINITY;
}

}  // namespace

ForceJoin join_force(const std::vector<TelemetryRow>& telemetry, const record::RecordedRun& plant,
                     double offset, double max_lag) {
  if (!plant.has_force()) throw record::InputError(plant.name + ": the plant log has no force column");
  ForceJoin j;
  j.offset = offset;
  const double step = plant.sample_rate > 0.0 ? 0.25 / plant.sample_rate : 2.5e-4;
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
    if (!r.in_control() || !sample_at(plant.time, plant.force, at, f)) continue;
    sample_at(plant.time, plant.displacement, at, x);
    const double e = r.force - f;
    sum += e * e;
    j.max_error = std::max(j.max_error, std::fabs(e));
    j.peak_force = std::max(j.peak_force, std::fabs(f));
    j.displacement.push_back(x);
    j.true_force.push_back(f);
    j.observer_force.push_back(r.force);
  }
  j.rows = j.true_force.size();
  if (j.rows == 0) {
    throw record::InputError(plant.name + ": no telemetry row in control falls inside the plant log (offset " +
                     std::to_string(offset) + " s)");
  }
  j.rms_error = std::sqrt(sum / static_cast<double>(j.rows));
  return j;
}

}  // namespace mrd::tools
