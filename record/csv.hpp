#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace mrd::record {

// A malformed input file or option. what() names the file, the line and the column.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The longest line the readers take. Instrument exports write a few hundred bytes a line; a
// longer one is a damaged or hostile file, refused before it is held in memory whole.
inline constexpr std::size_t kMaxLineLength = std::size_t{1} << 20;

// "file:line: line longer than 1048576 bytes: ...", the error for a line over kMaxLineLength.
std::string line_too_long_message(std::string_view file, std::size_t line);

// Walks text line by line, skipping blank lines and numbering lines from 1 as an editor does.
// A UTF-8 byte-order mark at the start (spreadsheet exports) is skipped. A line longer than
// kMaxLineLength throws InputError naming `name` (the file) and the line.
class LineReader {
 public:
  LineReader(std::string_view text, std::string name);
  // The next non-blank line without its end of line, or nullopt at the end of the text.
  std::optional<std::string_view> next();
  // The number of the line next() returned last (0 before the first).
  [[nodiscard]] std::size_t line_number() const { return line_number_; }
  [[nodiscard]] const std::string& name() const { return name_; }

 private:
  std::string_view rest_;
  std::string name_;
  std::size_t line_number_ = 0;
};

// The next line of `lines` that is not a '#' comment. A time-origin comment
// (common/time_origin.hpp) sets `origin`; one that starts like it but does not parse, or a second
// one, throws InputError naming the file and the line.
std::optional<std::string_view> next_data_line(LineReader& lines, std::optional<double>& origin);

// The whole file as text. Throws InputError "path: cannot open the file: <why>" (the system's
// reason, or that it is a folder), and
// line_too_long_message as soon as a line passes kMaxLineLength, so a file with a 2 GB line
// costs 1 MiB of memory, not 2 GB.
std::string read_text_file(const std::string& path);

// Writes `text` to `path`, replacing the file: empty, or "cannot write PATH: <the system's reason>".
[[nodiscard]] std::string write_text_file(const std::string& path, const std::string& text);

// What separates the fields of a line: one character, or runs of blanks (spaces and tabs).
enum class Delimiter : char { kComma = ',', kSemicolon = ';', kTab = '\t', kBlanks = ' ' };

// The delimiter a file's header (or first) line uses: a semicolon where it has one (spreadsheets
// where the comma is the decimal point), else a comma, else a tab, else blanks.
[[nodiscard]] Delimiter find_delimiter(std::string_view line);

// Splits one line on `delimiter`, trimming blanks and a trailing '\r' from each field. A
// trailing delimiter yields no extra empty field, since some instruments end every line with one.
std::vector<std::string_view> split_csv_line(std::string_view line, Delimiter delimiter = Delimiter::kComma);

// The field without one pair of surrounding double quotes ("t" -> t), as spreadsheet and
// MATLAB exports write header names.
std::string_view unquote(std::string_view field);

// The whole field must be a finite decimal number; nullopt otherwise. With decimal_comma, the
// one decimal separator is a comma ("0,25"), as semicolon-delimited exports write it.
std::optional<double> parse_finite(std::string_view field, bool decimal_comma = false);

// An empty cell, or nan / inf in any spelling: a logger's failed read, not a malformed file.
[[nodiscard]] bool is_non_finite(std::string_view cell);

// "file:line: column 'name': message", the one shape every input error takes.
std::string input_error_message(std::string_view file, std::size_t line, std::string_view column,
                                std::string_view message);

}  // namespace mrd::record
