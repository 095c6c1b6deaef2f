#include "hal/config_check.hpp"

namespace mrd::hal {

void ConfigReport::add(std::string_view field, std::string message) {
  problems_.push_back({std::string(field), std::move(message)});
}

bool ConfigReport::check(bool ok, std::string_view field, std::string_view message) {
  if (!ok) add(field, std::string(message));
  return ok;
}

void ConfigReport::merge(const ConfigReport& other, std::string_view prefix) {
  for (const auto& p : other.problems_) {
    std::string field(prefix);
    if (!field.empty() && !p.field.empty()) field += '.';
    field += p.field;
    problems_.push_back({std::move(field), p.message});
  }
}

bool ConfigReport::mentions(std::string_view field) const {
  for (const auto& p : problems_) {
    if (p.field == field) return true;
  }
  return false;
}

std::string ConfigReport::to_string() const {
  std::string out;
  for (const auto& p : problems_) out += p.field + ": " + p.message + '\n';
  return out;
}

}  // namespace mrd::hal
