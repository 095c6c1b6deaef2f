#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace mrd {

// One finding about a parameter or config value. `field` is the key path the user wrote
// ("jiles_atherton.c", "modbus.tcp.port"), so loaders can print it next to the file and line.
struct ValidationIssue {
  enum class Severity { kError, kWarning };
  Severity severity = Severity::kError;
  std::string field;
  std::string message;
};

// What validate() found in a config or parameter struct: the one report type of model/, hal/
// and everything above them. Validation runs at start-up, never on the hot path, so it may
// allocate.
// A number as %g prints it ("1e+308", "-0", "0.001"), for messages.
[[nodiscard]] std::string format_value(double v);

class ValidationReport {
 public:
  void error(std::string_view field, std::string message);
  void warning(std::string_view field, std::string message);
  // An error under `field` when `ok` is false; returns `ok` so checks can chain.
  bool check(bool ok, std::string_view field, std::string_view message);

  // The common physical-range checks; each reports one error when it fails.
  void require_positive(std::string_view field, double value);
  // In (0, max]: a physical bound on a positive quantity (1e308 is no magnetisation).
  void require_positive(std::string_view field, double value, double max);
  void require_non_negative(std::string_view field, double value);
  void require_in_range(std::string_view field, double value, double lo, double hi, bool hi_open);
  // A warning when `value` lies outside [lo, hi], what real devices show; `what` names them, and
  // `quantity` the value when it is not the field itself ("k/a").
  void expect_typical(std::string_view field, double value, double lo, double hi, std::string_view what,
                      std::string_view quantity = {});

  // Adopts another report's issues under `prefix` ("tcp" + "port" -> "tcp.port").
  void merge(const ValidationReport& other, std::string_view prefix);

  [[nodiscard]] bool ok() const;  // no errors (warnings allowed)
  [[nodiscard]] const std::vector<ValidationIssue>& issues() const { return issues_; }
  [[nodiscard]] bool mentions(std::string_view field) const;
  // "error: field: message\n" per issue ("warning: ..." for warnings).
  [[nodiscard]] std::string to_string() const;

 private:
  std::vector<ValidationIssue> issues_;
};

}  // namespace mrd
