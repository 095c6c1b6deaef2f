#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <utility>

#include <toml++/toml.h>

#include "common/validation_report.hpp"
#include "config/config_message.hpp"

namespace mrd::config {

// Reads typed values out of a parsed TOML table by key path ("safety.stale_periods"),
// remembering every path asked for. A key that is absent keeps the caller's default; a key of
// the wrong type is an error and keeps the default too. unknown_keys() then reports every key
// in the file that nobody asked for, so a typo is an error, not a silently ignored setting.
// Start-up only: allocates freely.
class TomlReader {
 public:
  TomlReader(const toml::table& root, std::string file, ConfigMessages& messages)
      : root_(root), file_(std::move(file)), messages_(messages) {}

  void get(std::string_view path, double& value);
  void get(std::string_view path, int& value);
  void get(std::string_view path, std::int64_t& value);
  void get(std::string_view path, std::uint32_t& value);
  void get(std::string_view path, bool& value);
  void get(std::string_view path, std::string& value);
  void get(std::string_view path, char& value);  // a one-character string
  // A number of seconds, stored as a std::chrono duration.
  template <typename Rep, typename Period>
  void get_seconds(std::string_view path, std::chrono::duration<Rep, Period>& value);
  // An array of exactly N numbers.
  template <std::size_t N>
  void get(std::string_view path, std::array<double, N>& value);
  // A string naming one of `choices`.
  template <typename E>
  void get_enum(std::string_view path, E& value, std::span<const std::pair<std::string_view, E>> choices);
  template <typename E>
  void get_enum(std::string_view path, E& value, std::initializer_list<std::pair<std::string_view, E>> choices) {
    get_enum(path, value, std::span<const std::pair<std::string_view, E>>(choices.begin(), choices.size()));
  }

  // Reports every key and table of the file that no get() asked for.
  void report_unknown_keys();

  // The line of `path` in the file, or of its nearest parent that is there; 0 when none is.
  // Array indices ("schedule.thresholds[2]") resolve to the array's own line.
  [[nodiscard]] int line_of(std::string_view path) const;
  void error(std::string_view path, std::string message);
  void warning(std::string_view path, std::string message);
  // Keys read, in order: the config reference in docs/FIRMWARE.md is checked against them.
  [[nodiscard]] const std::vector<std::string>& keys() const { return order_; }
  // Keys read that the file does not state (so their defaults apply).
  [[nodiscard]] const std::vector<std::string>& defaulted() const { return defaulted_; }

 private:
  const toml::node* find(std::string_view path) const;
  const toml::node* lookup(std::string_view path);  // find + remember as known
  bool expect(const toml::node& node, std::string_view path, toml::node_type type,
              std::string_view what);
  bool get_number(std::string_view path, double& value);
  void walk(const toml::table& table, const std::string& prefix);
  void add(std::string_view path, std::string message, bool warning, int line);

  const toml::table& root_;
  std::string file_;
  ConfigMessages& messages_;
  std::set<std::string, std::less<>> known_;
  std::set<std::string, std::less<>> tables_;  // known paths that must be tables
  std::vector<std::string> order_;
  std::vector<std::string> defaulted_;
};

[[nodiscard]] std::string_view type_name(toml::node_type t);

template <typename Rep, typename Period>
void TomlReader::get_seconds(std::string_view path, std::chrono::duration<Rep, Period>& value) {
  double seconds = std::chrono::duration<double>(value).count();
  if (!get_number(path, seconds)) return;
  if (!(seconds >= -1e6 && seconds <= 1e6)) {
    error(path, "must be a finite number of seconds, got " + format_value(seconds));
    return;
  }
  value = std::chrono::round<std::chrono::duration<Rep, Period>>(std::chrono::duration<double>(seconds));
  if (seconds > 0.0 && value.count() == 0) {
    error(path, "must be at least one tick of " + format_value(static_cast<double>(Period::num) / Period::den) + " s");
  }
}

template <std::size_t N>
void TomlReader::get(std::string_view path, std::array<double, N>& value) {
  const toml::node* node = lookup(path);
  if (node == nullptr || !expect(*node, path, toml::node_type::array, "an array of numbers")) return;
  const toml::array& array = *node->as_array();
  if (array.size() != N) {
    error(path, "must have " + std::to_string(N) + " values, got " + std::to_string(array.size()));
    return;
  }
  std::array<double, N> parsed = value;
  for (std::size_t i = 0; i < N; ++i) {
    const toml::node& item = array[i];
    if (const auto* f = item.as_floating_point()) {
      parsed[i] = f->get();
    } else if (const auto* n = item.as_integer()) {
      parsed[i] = static_cast<double>(n->get());
    } else {
      error(std::string(path) + "[" + std::to_string(i) + "]",
            "must be a number, got " + std::string(type_name(item.type())));
      return;
    }
  }
  value = parsed;
}

template <typename E>
void TomlReader::get_enum(std::string_view path, E& value,
                          std::span<const std::pair<std::string_view, E>> choices) {
  std::string text;
  for (const auto& [name, e] : choices) {
    if (e == value) text = name;
  }
  const toml::node* node = find(path);
  get(path, text);
  if (node == nullptr || !node->is_string()) return;
  std::string names;
  for (const auto& [name, e] : choices) {
    if (name == text) {
      value = e;
      return;
    }
    names += names.empty() ? "" : ", ";
    names += name;
  }
  error(path, "must be one of " + names + ", got \"" + text + "\"");
}

// The pieces every config loader shares (the controller's, mrd-plant's).
// The parsed text, or nullopt with the syntax error (file:line, column) added to `errors`.
std::optional<toml::table> parse_config_text(std::string_view text, const std::string& file_name,
                                             ConfigMessages& errors);
// The file's text, or nullopt with "cannot open the file: <why>" added to `errors`.
std::optional<std::string> read_config_file(const std::string& path, ConfigMessages& errors);
// `messages` in file order (those without a line last), split into errors and warnings.
void file_messages(ConfigMessages& messages, ConfigMessages& errors, ConfigMessages& warnings);

}  // namespace mrd::config
