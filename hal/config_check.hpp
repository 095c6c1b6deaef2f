#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace mrd::hal {

// One problem with a config struct. `field` is the key path the user wrote ("modbus.tcp.port"),
// so the TOML loader can print one clear line per problem.
struct ConfigProblem {
  std::string field;
  std::string message;
};

// hal must not link mrd_model, so it keeps this minimal twin of model::ParameterReport.
// Start-up only: it allocates.
class ConfigReport {
 public:
  void add(std::string_view field, std::string message);
  // Adds `message` under `field` when `ok` is false; returns `ok` so checks can chain.
  bool check(bool ok, std::string_view field, std::string_view message);
  // Adopts another report's problems under `prefix` ("tcp" + "port" -> "tcp.port").
  void merge(const ConfigReport& other, std::string_view prefix);

  [[nodiscard]] bool ok() const { return problems_.empty(); }
  [[nodiscard]] const std::vector<ConfigProblem>& problems() const { return problems_; }
  [[nodiscard]] bool mentions(std::string_view field) const;  // for tests and callers
  [[nodiscard]] std::string to_string() const;                 // "field: message\n" per problem

 private:
  std::vector<ConfigProblem> problems_;
};

}  // namespace mrd::hal
