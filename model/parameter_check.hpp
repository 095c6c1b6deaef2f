#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace mrd::model {

// One finding about a parameter set. `field` is the name the user wrote (for example
// "jiles_atherton.c"), so config loaders can print it next to the file and line.
struct ParameterIssue {
  enum class Severity { kError, kWarning };
  Severity severity;
  std::string field;
  std::string message;
};

// Validation runs at start-up, never on the hot path, so it may allocate.
class ParameterReport {
 public:
  void error(std::string_view field, std::string message);
  void warning(std::string_view field, std::string message);

  // Helpers for the common physical-range checks; each reports one error when it fails.
  void require_positive(std::string_view field, double value);
  void require_non_negative(std::string_view field, double value);
  void require_in_range(std::string_view field, double value, double lo, double hi, bool hi_open);

  // Prefix every field name, so nested structs report "damper.geometry.gap".
  void merge(const ParameterReport& other, std::string_view prefix);

  [[nodiscard]] bool ok() const;  // true when there are no errors (warnings allowed)
  [[nodiscard]] const std::vector<ParameterIssue>& issues() const { return issues_; }
  [[nodiscard]] std::string to_string() const;

 private:
  std::vector<ParameterIssue> issues_;
};

}  // namespace mrd::model
