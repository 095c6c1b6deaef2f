#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mrd::tools {

// Splits one CSV line on `separator` (',' or, when whitespace_separated, runs of blanks),
// trimming blanks and a trailing '\r'. A trailing separator yields no extra empty field,
// since some instruments end every line with one.
std::vector<std::string_view> split_csv_line(std::string_view line, bool whitespace_separated = false);

// The whole field must be a finite decimal number; nullopt otherwise.
std::optional<double> parse_finite(std::string_view field);

// "file:line: column 'name': message", the one shape every input error takes.
std::string input_error_message(std::string_view file, std::size_t line, std::string_view column,
                                std::string_view message);

}  // namespace mrd::tools
