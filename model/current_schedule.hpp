#pragma once

#include <array>
#include <cstddef>

#include "common/validation_report.hpp"

namespace mrd::model {

// Table 4 of the paper: coil current as a function of |x|. Level i applies when
// thresholds[i-1] < |x| <= thresholds[i]; above the last threshold the last current applies.
struct CurrentScheduleTable {
  static constexpr std::size_t kThresholds = 5;
  std::array<double, kThresholds> thresholds{0.005, 0.010, 0.020, 0.030, 0.040};  // [m]
  std::array<double, kThresholds + 1> currents{0.0, 0.2, 0.4, 0.6, 0.8, 1.2};       // [A]
  // Anti-chatter band [m]: a level is left downwards only once |x| <= threshold - band.
  double band = 2e-4;
};

ValidationReport validate(const CurrentScheduleTable& table);

// The schedule with memory. Rising |x| switches at the exact Table 4 edges; falling |x| must
// cross the edge by `band` first. An LVDT with noise smaller than the band that sits on an
// edge therefore switches once, not every sample. A non-finite x keeps the current level.
class CurrentSchedule {
 public:
  explicit CurrentSchedule(const CurrentScheduleTable& table = {});

  double update(double displacement);  // returns the scheduled current [A]
  [[nodiscard]] std::size_t level() const { return level_; }
  [[nodiscard]] double current() const { return table_.currents[level_]; }
  void reset() { started_ = false; level_ = 0; }

  // The memoryless Table 4 lookup: how many thresholds |x| exceeds.
  [[nodiscard]] std::size_t level_of(double magnitude) const;
  [[nodiscard]] const CurrentScheduleTable& table() const { return table_; }

 private:
  CurrentScheduleTable table_;
  std::size_t level_ = 0;
  bool started_ = false;
};

}  // namespace mrd::model
