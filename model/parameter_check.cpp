#include "model/parameter_check.hpp"

#include <cmath>
#include <sstream>

namespace mrd::model {

namespace {
std::string format_value(double v) {
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}
}  // namespace

void ParameterReport::error(std::string_view field, std::string message) {
  issues_.push_back({ParameterIssue::Severity::kError, std::string(field), std::move(message)});
}

void ParameterReport::warning(std::string_view field, std::string message) {
  issues_.push_back({ParameterIssue::Severity::kWarning, std::string(field), std::move(message)});
}

void ParameterReport::require_positive(std::string_view field, double value) {
  if (!std::isfinite(value) || value <= 0.0) {
    error(field, "must be a finite value > 0, got " + format_value(value));
  }
}

void ParameterReport::require_non_negative(std::string_view field, double value) {
  if (!std::isfinite(value) || value < 0.0) {
    error(field, "must be a finite value >= 0, got " + format_value(value));
  }
}

void ParameterReport::require_in_range(std::string_view field, double value, double lo, double hi,
                                       bool hi_open) {
  const bool above = hi_open ? value >= hi : value > hi;
  if (!std::isfinite(value) || value < lo || above) {
    error(field, "must lie in [" + format_value(lo) + ", " + format_value(hi) + (hi_open ? ")" : "]") +
                     ", got " + format_value(value));
  }
}

void ParameterReport::merge(const ParameterReport& other, std::string_view prefix) {
  for (const auto& issue : other.issues_) {
    std::string field(prefix);
    if (!field.empty() && !issue.field.empty()) field += '.';
    field += issue.field;
    issues_.push_back({issue.severity, std::move(field), issue.message});
  }
}

bool ParameterReport::ok() const {
  for (const auto& issue : issues_) {
    if (issue.severity == ParameterIssue::Severity::kError) return false;
  }
  return true;
}

std::string ParameterReport::to_string() const {
  std::string out;
  for (const auto& issue : issues_) {
    out += issue.severity == ParameterIssue::Severity::kError ? "error: " : "warning: ";
    out += issue.field + ": " + issue.message + '\n';
  }
  return out;
}

}  // namespace mrd::model
