#include "common/validation_report.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace mrd {

std::string format_value(double v) {
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}

void ValidationReport::error(std::string_view field, std::string message) {
  issues_.push_back({ValidationIssue::Severity::kError, std::string(field), std::move(message)});
}

void ValidationReport::warning(std::string_view field, std::string message) {
  issues_.push_back({ValidationIssue::Severity::kWarning, std::string(field), std::move(message)});
}

bool ValidationReport::check(bool ok, std::string_view field, std::string_view message) {
  if (!ok) error(field, std::string(message));
  return ok;
}

void ValidationReport::require_positive(std::string_view field, double value) {
  if (!std::isfinite(value) || value <= 0.0) {
    error(field, "must be a finite value > 0, got " + format_value(value));
  }
}

void ValidationReport::require_positive(std::string_view field, double value, double max) {
  if (!std::isfinite(value) || value <= 0.0 || value > max) {
    error(field, "must lie in (0, " + format_value(max) + "], got " + format_value(value));
  }
}

void ValidationReport::expect_typical(std::string_view field, double value, double lo, double hi,
                                      std::string_view what, std::string_view quantity) {
  if (std::isfinite(value) && (value < lo || value > hi)) {
    warning(field, (quantity.empty() ? std::string() : std::string(quantity) + " = ") + format_value(value) + " is outside what " + std::string(what) + " show (" + format_value(lo) + " to " +
                       format_value(hi) + "): a fit run to an edge, or a unit slip? (docs/MODEL.md, \"Typical ranges\")");
  }
}

void ValidationReport::require_non_negative(std::string_view field, double value) {
  if (!std::isfinite(value) || value < 0.0) {
    error(field, "must be a finite value >= 0, got " + format_value(value));
  }
}

void ValidationReport::require_in_range(std::string_view field, double value, double lo, double hi,
                                        bool hi_open) {
  const bool above = hi_open ? value >= hi : value > hi;
  if (!std::isfinite(value) || value < lo || above) {
    error(field, "must lie in [" + format_value(lo) + ", " + format_value(hi) + (hi_open ? ")" : "]") +
                     ", got " + format_value(value));
  }
}

void ValidationReport::merge(const ValidationReport& other, std::string_view prefix) {
  for (const auto& issue : other.issues_) {
    std::string field(prefix);
    if (!field.empty() && !issue.field.empty()) field += '.';
    field += issue.field;
    issues_.push_back({issue.severity, std::move(field), issue.message});
  }
}

bool ValidationReport::ok() const {
  return std::none_of(issues_.begin(), issues_.end(), [](const ValidationIssue& i) {
    return i.severity == ValidationIssue::Severity::kError;
  });
}

bool ValidationReport::mentions(std::string_view field) const {
  return std::any_of(issues_.begin(), issues_.end(), [&](const ValidationIssue& i) { return i.field == field; });
}

std::string ValidationReport::to_string() const {
  std::string out;
  for (const auto& issue : issues_) {
    out += issue.severity == ValidationIssue::Severity::kError ? "error: " : "warning: ";
    out += issue.field + ": " + issue.message + '\n';
  }
  return out;
}

}  // namespace mrd
