#pragma once

#include <string>
#include <string_view>
#include <toml++/toml.h>

// Writes values into a TOML text in place: the value span of an existing key is replaced and
// everything else (order, comments, spacing, the formatting of untouched values) stays byte for
// byte; a new key goes after the last key of its table, a new table after the last table that
// shares its parent (or at the end). toml++ reads a file into maps, so printing its table would
// sort the keys and drop the comments of an annotated config.
//
// Handled: [table] headers with bare or dotted names, `key = value` lines with bare keys, values
// on one line or arrays over several, comments after values. Arrays of tables ([[x]]) are kept
// but never patched into. Throws std::runtime_error when the result does not parse.
namespace mrd::tools {

class TomlPatch {
 public:
  explicit TomlPatch(std::string text) : text_(std::move(text)) {}

  // Sets `key` of `table` ("a.b"; "" for the root) to `value`. A key whose present value is
  // already equal is left as written (1e-3 stays 1e-3).
  void set(std::string_view table, std::string_view key, const toml::node& value);
  // Every leaf of `values`, its tables as table paths (an inline table is one value).
  void set_all(const toml::table& values, const std::string& table = "");

  [[nodiscard]] const std::string& text() const { return text_; }

 private:
  std::string text_;
};

// A value as TOML writes it; doubles in the shortest form that reads back to the same bits.
[[nodiscard]] std::string toml_value_text(const toml::node& value);

// Every floating-point leaf of `values` (arrays and inner tables too) rounded to `digits`
// significant digits: fitted values are written as far as they mean anything, not to 17 digits.
void round_floats(toml::table& values, int digits = 7);

// `text` with every leaf of `values` set (TomlPatch::set_all); checked to parse.
[[nodiscard]] std::string patch_toml(std::string_view text, const toml::table& values);

}  // namespace mrd::tools
