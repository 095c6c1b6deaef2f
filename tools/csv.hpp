#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace mrd::tools {

// A malformed input file or option. what() names the file, the line and the column.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Walks text line by line, skipping blank lines and numbering lines from 1 as an editor does.
// A UTF-8 byte-order mark at the start (spreadsheet exports) is skipped.
class LineReader {
 public:
  explicit LineReader(std::string_view text);
  // The next non-blank line without its end of line, or nullopt at the end of the text.
  std::optional<std::string_view> next();
  // The number of the line next() returned last (0 before the first).
  [[nodiscard]] std::size_t line_number() const { return line_number_; }

 private:
  std::string_view rest_;
  std::size_t line_number_ = 0;
};

// The whole file as text; throws InputError "path: cannot open the file".
std::string read_text_file(const std::string& path);

// Splits one CSV line on `separator` (',' or, when whitespace_separated, runs of blanks),
// trimming blanks and a trailing '\r'. A trailing separator yields no extra empty field,
// since some instruments end every line with one.
std::vector<std::string_view> split_csv_line(std::string_view line, bool whitespace_separated = false);

// The field without one pair of surrounding double quotes ("t" -> t), as spreadsheet and
// MATLAB exports write header names.
std::string_view unquote(std::string_view field);

// The whole field must be a finite decimal number; nullopt otherwise.
std::optional<double> parse_finite(std::string_view field);

// "file:line: column 'name': message", the one shape every input error takes.
std::string input_error_message(std::string_view file, std::size_t line, std::string_view column,
                                std::string_view message);

}  // namespace mrd::tools
