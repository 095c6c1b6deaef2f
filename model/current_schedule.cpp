#include "model/current_schedule.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace mrd::model {

ValidationReport validate(const CurrentScheduleTable& t) {
  ValidationReport report;
  for (std::size_t i = 0; i < t.thresholds.size(); ++i) {
    const std::string field = "thresholds[" + std::to_string(i) + "]";
    report.require_positive(field, t.thresholds[i]);
    if (i > 0 && !(t.thresholds[i] > t.thresholds[i - 1])) {
      report.error(field, "thresholds must increase strictly");
    }
  }
  for (std::size_t i = 0; i < t.currents.size(); ++i) {
    report.require_non_negative("currents[" + std::to_string(i) + "]", t.currents[i]);
  }
  report.require_non_negative("band", t.band);
  if (report.ok()) {
    for (std::size_t i = 1; i < t.thresholds.size(); ++i) {
      if (t.band >= t.thresholds[i] - t.thresholds[i - 1]) {
        report.error("band", "must be narrower than the gap between two thresholds");
        break;
      }
    }
  }
  return report;
}

CurrentSchedule::CurrentSchedule(const CurrentScheduleTable& table) : table_(table) {}

std::size_t CurrentSchedule::level_of(double magnitude) const {
  std::size_t level = 0;
  while (level < table_.thresholds.size() && magnitude > table_.thresholds[level]) ++level;
  return level;
}

double CurrentSchedule::update(double displacement) {
  if (!std::isfinite(displacement)) return current();
  const double magnitude = std::fabs(displacement);
  const std::size_t exact = level_of(magnitude);
  if (!started_ || exact >= level_) {
    level_ = exact;
    started_ = true;
  } else {
    // Falling: only drop to the level that |x| + band still reaches.
    level_ = std::min(level_, level_of(magnitude + table_.band));
  }
  return current();
}

}  // namespace mrd::model
