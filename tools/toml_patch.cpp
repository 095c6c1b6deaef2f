#include "tools/toml_patch.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace mrd::tools {

namespace {

struct KeySpan {
  std::string key;
  std::size_t value_begin = 0, value_end = 0;  // the value, without spaces or comment
  std::size_t line_end = 0;                    // after the line's newline
};

struct Section {
  std::string name;  // "" for the root
  bool array = false;  // [[name]]
  std::size_t header_end = 0;  // after the header line's newline (0 for the root)
  std::size_t end = 0;         // where the next header line starts
  std::vector<KeySpan> keys;
};

bool is_space(char c) { return c == ' ' || c == '\t'; }

// "a . b" -> "a.b" (bare names only).
std::string table_name(std::string_view inside) {
  std::string out;
  for (const char c : inside)
    if (!is_space(c)) out += c;
  return out;
}

// The end of a value starting at `at`: outside strings, at a comment or the end of the line,
// once brackets and braces are closed (arrays may span lines).
std::size_t value_end(const std::string& t, std::size_t at) {
  int depth = 0;
  std::size_t last = at;  // after the last non-space character of the value
  for (std::size_t i = at; i < t.size(); ++i) {
    const char c = t[i];
    if (c == '"' || c == '\'') {
      std::size_t j = i + 1;
      while (j < t.size() && t[j] != c && t[j] != '\n') j += (c == '"' && t[j] == '\\') ? 2 : 1;
      i = std::min(j, t.size() - 1);
      last = i + 1;
      continue;
    }
    if (c == '#') {
      while (i < t.size() && t[i] != '\n') ++i;
      if (depth == 0) return last;
      continue;
    }
    if (c == '\n') {
      if (depth == 0) return last;
      continue;
    }
    if (c == '[' || c == '{') ++depth;
    if (c == ']' || c == '}') --depth;
    if (!is_space(c) && c != '\r') last = i + 1;
  }
  return last;
}

std::vector<Section> scan(const std::string& t) {
  std::vector<Section> sections(1);
  std::size_t pos = 0;
  while (pos < t.size()) {
    std::size_t eol = t.find('\n', pos);
    std::size_t next = eol == std::string::npos ? t.size() : eol + 1;
    std::size_t i = pos;
    while (i < t.size() && is_space(t[i])) ++i;
    if (i < t.size() && t[i] == '[') {
      const bool array = i + 1 < t.size() && t[i + 1] == '[';
      const std::size_t close = t.find(array ? "]]" : "]", i);
      sections.back().end = pos;
      Section s;
      s.array = array;
      s.name = table_name(std::string_view(t).substr(i + (array ? 2 : 1), close - i - (array ? 2 : 1)));
      s.header_end = next;
      sections.push_back(s);
    } else if (i < t.size() && t[i] != '#' && t[i] != '\n' && t[i] != '\r') {
      const std::size_t eq = t.find('=', i);
      if (eq != std::string::npos && eq < next) {
        KeySpan k;
        k.key = table_name(std::string_view(t).substr(i, eq - i));
        std::size_t v = eq + 1;
        while (v < t.size() && is_space(t[v])) ++v;
        k.value_begin = v;
        k.value_end = value_end(t, v);
        eol = t.find('\n', k.value_end);
        next = eol == std::string::npos ? t.size() : eol + 1;
        k.line_end = next;
        sections.back().keys.push_back(k);
      }
    }
    pos = next;
  }
  sections.back().end = t.size();
  return sections;
}

std::optional<toml::table> parse_value(const std::string& value_text) {
  try {
    return toml::parse("v = " + value_text);
  } catch (const toml::parse_error&) {
    return std::nullopt;
  }
}

}  // namespace

std::string toml_value_text(const toml::node& value) {
  if (const auto* d = value.as_floating_point()) {
    const double x = d->get();
    if (x != x) return "nan";
    if (x == std::numeric_limits<double>::infinity()) return "inf";
    if (x == -std::numeric_limits<double>::infinity()) return "-inf";
    char buffer[32];
    const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, x);
    std::string out(buffer, end);
    // TOML floats need a fraction or an exponent; 1e+20 is fine, 3 is an integer.
    if (out.find_first_of(".eE") == std::string::npos) out += ".0";
    return out;
  }
  std::ostringstream out;
  value.visit([&](const auto& v) { out << v; });
  return out.str();
}

void TomlPatch::set(std::string_view table, std::string_view key, const toml::node& value) {
  const std::string text = toml_value_text(value);
  const std::vector<Section> sections = scan(text_);
  const Section* home = nullptr;
  for (const Section& s : sections)
    if (!s.array && s.name == table) home = &s;
  if (home != nullptr) {
    for (const KeySpan& k : home->keys) {
      if (k.key != key) continue;
      const std::string present = text_.substr(k.value_begin, k.value_end - k.value_begin);
      const auto old_value = parse_value(present), new_value = parse_value(text);
      if (old_value && new_value && *old_value == *new_value) return;
      // Keep a comment after the value in its column while the new value leaves room.
      std::size_t gap = k.value_end;
      while (gap < text_.size() && is_space(text_[gap])) ++gap;
      if (gap < text_.size() && text_[gap] == '#' && gap > k.value_end && present.find('\n') == std::string::npos) {
        const std::size_t room = gap - k.value_begin;
        const std::string padded = text + std::string(room > text.size() ? room - text.size() : 1, ' ');
        text_.replace(k.value_begin, gap - k.value_begin, padded);
      } else {
        text_.replace(k.value_begin, k.value_end - k.value_begin, text);
      }
      return;
    }
    // A new key: after the table's last key, else right under its header.
    std::size_t at = home->keys.empty() ? home->header_end : home->keys.back().line_end;
    std::string line = std::string(key) + " = " + text + "\n";
    if (at > 0 && text_[at - 1] != '\n') line = "\n" + line;
    text_.insert(at, line);
    return;
  }
  // A new table: after the last table inside its nearest existing ancestor ("a.b.c" looks for
  // "a.b.*", then "a.*"), else at the end.
  std::string parent(table);
  std::size_t at = text_.size();
  while (!parent.empty()) {
    const auto dot = parent.rfind('.');
    parent = dot == std::string::npos ? "" : parent.substr(0, dot);
    if (parent.empty()) break;
    const Section* last = nullptr;
    for (const Section& s : sections)
      if (s.name == parent || s.name.rfind(parent + ".", 0) == 0) last = &s;
    if (last != nullptr) {
      at = last->keys.empty() ? last->header_end : last->keys.back().line_end;
      break;
    }
  }
  std::string block = "\n[" + std::string(table) + "]\n" + std::string(key) + " = " + text + "\n";
  if (at > 0 && text_[at - 1] != '\n') block = "\n" + block;
  text_.insert(at, block);
}

void TomlPatch::set_all(const toml::table& values, const std::string& table) {
  for (const auto& [key, node] : values) {
    const std::string name(key.str());
    if (const auto* sub = node.as_table(); sub != nullptr && !sub->is_inline())
      set_all(*sub, table.empty() ? name : table + "." + name);
    else
      set(table, name, node);
  }
}

std::string patch_toml(std::string_view text, const toml::table& values) {
  TomlPatch patch{std::string(text)};
  patch.set_all(values);
  try {
    (void)toml::parse(patch.text());
  } catch (const toml::parse_error& e) {
    throw std::runtime_error("the patched config does not parse: " + std::string(e.description()));
  }
  return patch.text();
}

namespace {

void round_node(toml::node& node, int digits) {
  if (auto* d = node.as_floating_point()) {
    const double x = d->get();
    if (!std::isfinite(x) || x == 0.0) return;
    char buffer[40];
    std::snprintf(buffer, sizeof buffer, "%.*g", digits, x);
    *d = std::strtod(buffer, nullptr);
  } else if (auto* t = node.as_table()) {
    for (auto&& [key, child] : *t) round_node(child, digits);
  } else if (auto* a = node.as_array()) {
    for (toml::node& child : *a) round_node(child, digits);
  }
}

}  // namespace

void round_floats(toml::table& values, int digits) {
  for (auto&& [key, child] : values) round_node(child, digits);
}

}  // namespace mrd::tools
