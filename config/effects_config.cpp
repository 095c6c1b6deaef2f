#include "config/effects_config.hpp"

#include <charconv>
#include <span>
#include <string>
#include <type_traits>

namespace mrd::config {

namespace {

constexpr std::string_view kPrefix = "damper.effects.";

// Calls v(table, key, field) for every key of every effect, in file order, from the effects'
// descriptors (model/effects/effect_set.hpp). `field` is a double, int, bool or an enum with
// enum_choices().
template <typename Visitor>
void visit(model::EffectSet& effects, Visitor& v) {
  effects.for_each([&]<typename E>(typename E::Params& p) {
    E::fields(p, [&](std::string_view key, auto& field) { v(E::kName, key, field); });
  });
}

struct Reader {
  TomlReader& in;
  template <typename T>
  void operator()(std::string_view table, std::string_view key, T& field) {
    std::string path(kPrefix);
    path.append(table).append(".").append(key);
    if constexpr (std::is_enum_v<T>) {
      const auto choices = enum_choices(T{});
      in.get_enum(path, field, std::span<const typename decltype(choices)::value_type>(choices));
    } else {
      in.get(path, field);
    }
  }
};

// The shortest text that reads back as the same double, with a '.' or an exponent so that TOML
// sees a float.
std::string format_double(double value) {
  char buf[32];
  const auto end = std::to_chars(buf, buf + sizeof buf, value).ptr;
  std::string text(buf, end);
  if (text.find_first_of(".eEn") == std::string::npos) text += ".0";  // 'n': nan, inf
  return text;
}

struct Writer {
  std::string out;
  std::string_view table;
  template <typename T>
  void operator()(std::string_view t, std::string_view key, const T& field) {
    if (t != table) {
      if (!out.empty()) out += '\n';
      out.append("[").append(kPrefix).append(t).append("]\n");
      table = t;
    }
    out.append(key).append(" = ");
    if constexpr (std::is_same_v<T, bool>) {
      out += field ? "true" : "false";
    } else if constexpr (std::is_same_v<T, int>) {
      out += std::to_string(field);
    } else if constexpr (std::is_enum_v<T>) {
      for (const auto& [name, value] : enum_choices(T{})) {
        if (value == field) out.append("\"").append(name).append("\"");
      }
    } else {
      out += format_double(field);
    }
    out += '\n';
  }
};

}  // namespace

void read_effects(TomlReader& in, model::EffectSet& effects) {
  Reader reader{in};
  visit(effects, reader);
}

std::string effects_toml(const model::EffectSet& effects) {
  model::EffectSet copy = effects;  // visit() hands out mutable fields; the writer only reads
  Writer writer;
  visit(copy, writer);
  return writer.out;
}

}  // namespace mrd::config
