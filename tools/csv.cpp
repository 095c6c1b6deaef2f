#include "tools/csv.hpp"

#include <charconv>
#include <cmath>

namespace mrd::tools {

namespace {
bool is_blank(char ch) { return ch == ' ' || ch == '\t' || ch == '\r' || ch == '\n'; }

std::string_view trim(std::string_view s) {
  while (!s.empty() && is_blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_blank(s.back())) s.remove_suffix(1);
  return s;
}
}  // namespace

std::vector<std::string_view> split_csv_line(std::string_view line, bool whitespace_separated) {
  std::vector<std::string_view> fields;
  if (whitespace_separated) {
    std::size_t i = 0;
    while (i < line.size()) {
      while (i < line.size() && is_blank(line[i])) ++i;
      const std::size_t start = i;
      while (i < line.size() && !is_blank(line[i])) ++i;
      if (i > start) fields.push_back(line.substr(start, i - start));
    }
    return fields;
  }
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(trim(line.substr(start, comma == std::string_view::npos ? comma : comma - start)));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  if (fields.size() > 1 && fields.back().empty()) fields.pop_back();
  return fields;
}

std::optional<double> parse_finite(std::string_view field) {
  field = trim(field);
  if (!field.empty() && field.front() == '+') field.remove_prefix(1);
  double value = 0.0;
  const auto [end, ec] = std::from_chars(field.data(), field.data() + field.size(), value);
  if (ec != std::errc{} || end != field.data() + field.size() || !std::isfinite(value)) {
    return std::nullopt;
  }
  return value;
}

std::string input_error_message(std::string_view file, std::size_t line, std::string_view column,
                                std::string_view message) {
  std::string out;
  out.append(file).append(":").append(std::to_string(line)).append(": ");
  if (!column.empty()) out.append("column '").append(column).append("': ");
  out.append(message);
  return out;
}

}  // namespace mrd::tools
