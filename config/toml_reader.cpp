#include "config/toml_reader.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include "common/file_error.hpp"

namespace mrd::config {

std::string ConfigMessage::to_string() const {
  std::string out = file;
  if (line > 0) {
    out += ':';
    out += std::to_string(line);
  }
  out += ": ";
  if (warning) out += "warning: ";
  if (!key.empty()) {
    out += key;
    out += ": ";
  }
  out += message;
  return out;
}

std::string_view type_name(toml::node_type t) {
  switch (t) {
    case toml::node_type::table: return "a table";
    case toml::node_type::array: return "an array";
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a float";
    case toml::node_type::boolean: return "a boolean";
    case toml::node_type::date: return "a date";
    case toml::node_type::time: return "a time";
    case toml::node_type::date_time: return "a date-time";
    case toml::node_type::none: break;
  }
  return "nothing";
}

namespace {

std::string format_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// Levenshtein distance, for "did you mean" on unknown keys.
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

std::string_view parent_of(std::string_view path) {
  const auto dot = path.rfind('.');
  return dot == std::string_view::npos ? std::string_view{} : path.substr(0, dot);
}

}  // namespace

const toml::node* TomlReader::find(std::string_view path) const {
  const toml::node* node = &root_;
  std::size_t start = 0;
  while (node != nullptr && start <= path.size()) {
    const auto dot = path.find('.', start);
    const auto key = path.substr(start, dot == std::string_view::npos ? path.size() - start : dot - start);
    const toml::table* table = node->as_table();
    node = table != nullptr ? table->get(key) : nullptr;
    if (dot == std::string_view::npos) break;
    start = dot + 1;
  }
  return node;
}

const toml::node* TomlReader::lookup(std::string_view path) {
  if (known_.insert(std::string(path)).second) order_.emplace_back(path);
  for (auto p = parent_of(path); !p.empty(); p = parent_of(p)) {
    known_.insert(std::string(p));
    tables_.insert(std::string(p));
  }
  const toml::node* node = find(path);
  if (node == nullptr) defaulted_.emplace_back(path);
  return node;
}

bool TomlReader::expect(const toml::node& node, std::string_view path, toml::node_type type,
                        std::string_view what) {
  if (node.type() == type) return true;
  add(path, "must be " + std::string(what) + ", got " + std::string(type_name(node.type())), false,
      static_cast<int>(node.source().begin.line));
  return false;
}

bool TomlReader::get_number(std::string_view path, double& value) {
  const toml::node* node = lookup(path);
  if (node == nullptr) return false;
  if (const auto* f = node->as_floating_point()) {
    value = f->get();
    return true;
  }
  if (const auto* n = node->as_integer()) {
    value = static_cast<double>(n->get());
    return true;
  }
  return expect(*node, path, toml::node_type::floating_point, "a number");
}

void TomlReader::get(std::string_view path, double& value) {
  double v = value;
  if (!get_number(path, v)) return;
  if (!std::isfinite(v)) {
    error(path, "must be finite, got " + format_number(v));
    return;
  }
  value = v;
}

void TomlReader::get(std::string_view path, int& value) {
  const toml::node* node = lookup(path);
  if (node == nullptr || !expect(*node, path, toml::node_type::integer, "an integer")) return;
  const std::int64_t v = node->as_integer()->get();
  if (v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max()) {
    error(path, "is out of the integer range, got " + std::to_string(v));
    return;
  }
  value = static_cast<int>(v);
}

void TomlReader::get(std::string_view path, std::int64_t& value) {
  const toml::node* node = lookup(path);
  if (node == nullptr || !expect(*node, path, toml::node_type::integer, "an integer")) return;
  value = node->as_integer()->get();
}

void TomlReader::get(std::string_view path, std::uint32_t& value) {
  const toml::node* node = lookup(path);
  if (node == nullptr || !expect(*node, path, toml::node_type::integer, "an integer")) return;
  const std::int64_t v = node->as_integer()->get();
  if (v < 0 || v > std::numeric_limits<std::uint32_t>::max()) {
    error(path, "must be in 0..4294967295, got " + std::to_string(v));
    return;
  }
  value = static_cast<std::uint32_t>(v);
}

void TomlReader::get(std::string_view path, bool& value) {
  const toml::node* node = lookup(path);
  if (node == nullptr || !expect(*node, path, toml::node_type::boolean, "true or false")) return;
  value = node->as_boolean()->get();
}

void TomlReader::get(std::string_view path, std::string& value) {
  const toml::node* node = lookup(path);
  if (node == nullptr || !expect(*node, path, toml::node_type::string, "a string")) return;
  value = node->as_string()->get();
}

void TomlReader::get(std::string_view path, char& value) {
  std::string text(1, value);
  const toml::node* node = find(path);
  get(path, text);
  if (node == nullptr || !node->is_string()) return;
  if (text.size() != 1) {
    error(path, "must be one character, got \"" + text + "\"");
    return;
  }
  value = text[0];
}

int TomlReader::line_of(std::string_view path) const {
  std::string_view p = path.substr(0, path.find('['));
  for (; !p.empty(); p = parent_of(p)) {
    if (const toml::node* node = find(p)) return static_cast<int>(node->source().begin.line);
  }
  return 0;
}

void TomlReader::add(std::string_view path, std::string message, bool warning, int line) {
  messages_.push_back({file_, line, std::string(path), std::move(message), warning});
}

void TomlReader::error(std::string_view path, std::string message) {
  add(path, std::move(message), false, line_of(path));
}

void TomlReader::warning(std::string_view path, std::string message) {
  add(path, std::move(message), true, line_of(path));
}

void TomlReader::report_unknown_keys() { walk(root_, ""); }

void TomlReader::walk(const toml::table& table, const std::string& prefix) {
  for (auto&& [key, node] : table) {
    const std::string path = prefix.empty() ? std::string(key.str()) : prefix + "." + std::string(key.str());
    if (known_.contains(path)) {
      if (const toml::table* sub = node.as_table()) {
        walk(*sub, path);
      } else if (tables_.contains(path)) {
        add(path, "must be a table, got " + std::string(type_name(node.type())), false,
            static_cast<int>(node.source().begin.line));
      }
      continue;
    }
    // Suggest the closest key known at the same level.
    std::string best;
    std::size_t best_distance = 3;  // at most two edits away
    for (const auto& k : known_) {
      if (parent_of(k) != std::string_view(prefix)) continue;
      const std::string_view name = std::string_view(k).substr(prefix.empty() ? 0 : prefix.size() + 1);
      const std::size_t d = edit_distance(key.str(), name);
      if (d < best_distance) {
        best_distance = d;
        best = name;
      }
    }
    std::string message = node.is_table() ? "unknown table" : "unknown key";
    if (!best.empty()) message += " (did you mean \"" + best + "\"?)";
    add(path, message, false, static_cast<int>(key.source().begin.line > 0 ? key.source().begin.line
                                                                            : node.source().begin.line));
  }
}

std::optional<toml::table> parse_config_text(std::string_view text, const std::string& file_name,
                                             ConfigMessages& errors) {
  try {
    return toml::parse(text, file_name);
  } catch (const toml::parse_error& e) {
    errors.push_back({file_name, static_cast<int>(e.source().begin.line), "",
                      "TOML syntax error at column " + std::to_string(e.source().begin.column) + ": " +
                          std::string(e.description()),
                      false});
    return std::nullopt;
  }
}

std::optional<std::string> read_config_file(const std::string& path, ConfigMessages& errors) {
  std::string why;
  std::ifstream file;
  if (readable_file(path, why)) {
    file.open(path);
    if (!file) why = open_failure_reason(path);
  }
  if (!why.empty()) {
    errors.push_back({path, 0, "", "cannot open the file: " + why, false});
    return std::nullopt;
  }
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

void file_messages(ConfigMessages& messages, ConfigMessages& errors, ConfigMessages& warnings) {
  // In file order, so the report reads top to bottom.
  std::stable_sort(messages.begin(), messages.end(), [](const ConfigMessage& a, const ConfigMessage& b) {
    return (a.line == 0 ? INT_MAX : a.line) < (b.line == 0 ? INT_MAX : b.line);
  });
  for (auto& m : messages) (m.warning ? warnings : errors).push_back(std::move(m));
}

}  // namespace mrd::config
