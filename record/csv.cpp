#include "record/csv.hpp"

#include "common/file_error.hpp"
#include "common/time_origin.hpp"

#include <cctype>
#include <cerrno>
#include <cstring>
#include <charconv>
#include <cmath>
#include <fstream>
#include <vector>

namespace mrd::record {

namespace {
bool is_blank(char ch) { return ch == ' ' || ch == '\t' || ch == '\r' || ch == '\n'; }

std::string_view trim(std::string_view s) {
  while (!s.empty() && is_blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_blank(s.back())) s.remove_suffix(1);
  return s;
}
}  // namespace

std::string line_too_long_message(std::string_view file, std::size_t line) {
  return input_error_message(file, line, "",
                             "line longer than " + std::to_string(kMaxLineLength) +
                                 " bytes: not a text file this reader takes");
}

LineReader::LineReader(std::string_view text, std::string name) : rest_(text), name_(std::move(name)) {
  if (rest_.starts_with("\xEF\xBB\xBF")) rest_.remove_prefix(3);
}

std::optional<std::string_view> LineReader::next() {
  while (!rest_.empty()) {
    const std::size_t end = rest_.find('\n');
    const std::string_view line = rest_.substr(0, end);
    rest_.remove_prefix(end == std::string_view::npos ? rest_.size() : end + 1);
    ++line_number_;
    if (line.size() > kMaxLineLength) throw InputError(line_too_long_message(name_, line_number_));
    if (!trim(line).empty()) return line;
  }
  return std::nullopt;
}

std::optional<std::string_view> next_data_line(LineReader& lines, std::optional<double>& origin) {
  auto line = lines.next();
  for (; line && is_comment_line(*line); line = lines.next()) {
    if (!line->starts_with(kTimeOriginPrefix)) continue;
    const auto parsed = parse_time_origin(*line);
    const auto fail = [&](const char* why) {
      return InputError(input_error_message(lines.name(), lines.line_number(), "", why));
    };
    if (!parsed) throw fail("a time-origin line must read '# time_s 0 is CLOCK_MONOTONIC <seconds> s'");
    if (origin) throw fail("a second time-origin line");
    origin = *parsed;
  }
  return line;
}

std::string write_text_file(const std::string& path, const std::string& text) {
  errno = 0;
  std::ofstream out(path);
  if (!out) return "cannot write " + path + ": " + open_failure_reason(path);
  out << text;
  out.close();
  if (!out) return "cannot write " + path + ": " + (errno != 0 ? std::strerror(errno) : "the write failed");
  return {};
}

std::string read_text_file(const std::string& path) {
  if (std::string why; !readable_file(path, why)) throw InputError(path + ": cannot open the file: " + why);
  std::ifstream file(path, std::ios::binary);
  if (!file) throw InputError(path + ": cannot open the file: " + open_failure_reason(path));
  std::string text;
  std::vector<char> chunk(std::size_t{64} << 10);
  std::size_t line = 1;
  std::size_t line_length = 0;  // bytes of `line` read so far
  while (file.read(chunk.data(), static_cast<std::streamsize>(chunk.size())) || file.gcount() > 0) {
    const std::string_view got(chunk.data(), static_cast<std::size_t>(file.gcount()));
    for (std::size_t start = 0;;) {
      const std::size_t end = got.find('\n', start);
      line_length += (end == std::string_view::npos ? got.size() : end) - start;
      if (line_length > kMaxLineLength) throw InputError(line_too_long_message(path, line));
      if (end == std::string_view::npos) break;
      ++line;
      line_length = 0;
      start = end + 1;
    }
    text.append(got);
  }
  return text;
}

Delimiter find_delimiter(std::string_view line) {
  for (const Delimiter d : {Delimiter::kSemicolon, Delimiter::kComma, Delimiter::kTab})
    if (line.find(static_cast<char>(d)) != std::string_view::npos) return d;
  return Delimiter::kBlanks;
}

std::vector<std::string_view> split_csv_line(std::string_view line, Delimiter delimiter) {
  std::vector<std::string_view> fields;
  if (delimiter == Delimiter::kBlanks) {
    std::size_t i = 0;
    while (i < line.size()) {
      while (i < line.size() && is_blank(line[i])) ++i;
      const std::size_t start = i;
      while (i < line.size() && !is_blank(line[i])) ++i;
      if (i > start) fields.push_back(line.substr(start, i - start));
    }
    return fields;
  }
  const char separator = static_cast<char>(delimiter);
  std::size_t start = 0;
  while (true) {
    const std::size_t end = line.find(separator, start);
    fields.push_back(trim(line.substr(start, end == std::string_view::npos ? end : end - start)));
    if (end == std::string_view::npos) break;
    start = end + 1;
  }
  if (fields.size() > 1 && fields.back().empty()) fields.pop_back();
  return fields;
}

std::string_view unquote(std::string_view field) {
  if (field.size() >= 2 && field.front() == '"' && field.back() == '"') {
    field = field.substr(1, field.size() - 2);
  }
  return field;
}

bool is_non_finite(std::string_view cell) {
  if (!cell.empty() && (cell.front() == '+' || cell.front() == '-')) cell.remove_prefix(1);
  std::string lower(cell);
  for (char& ch : lower) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return lower.empty() || lower == "nan" || lower == "inf" || lower == "infinity";
}

std::optional<double> parse_finite(std::string_view field, bool decimal_comma) {
  field = trim(field);
  if (!field.empty() && field.front() == '+') field.remove_prefix(1);
  std::string swapped;  // only for a decimal comma: from_chars reads a point
  if (decimal_comma && field.find(',') != std::string_view::npos) {
    if (field.find('.') != std::string_view::npos) return std::nullopt;
    swapped = field;
    swapped[swapped.find(',')] = '.';
    field = swapped;
  }
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

}  // namespace mrd::record
