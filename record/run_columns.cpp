#include "record/run_columns.hpp"

#include <algorithm>
#include <array>
#include <charconv>

#include "record/csv.hpp"

namespace mrd::record {

namespace {

constexpr std::array kUnits{
    ColumnUnit{RunQuantity::kTime, "time_s", 1.0},
    ColumnUnit{RunQuantity::kTime, "time_ms", 1e-3},
    ColumnUnit{RunQuantity::kDisplacement, "displacement_m", 1.0},
    ColumnUnit{RunQuantity::kDisplacement, "displacement_mm", 1e-3},
    ColumnUnit{RunQuantity::kDisplacement, "displacement_cm", 1e-2},
    ColumnUnit{RunQuantity::kCurrent, "current_A", 1.0},
    ColumnUnit{RunQuantity::kCurrent, "current_mA", 1e-3},
    ColumnUnit{RunQuantity::kVoltage, "voltage_V", 1.0},
    ColumnUnit{RunQuantity::kVoltage, "voltage_mV", 1e-3},
    ColumnUnit{RunQuantity::kForce, "force_N", 1.0},
    ColumnUnit{RunQuantity::kForce, "force_kN", 1e3},
    ColumnUnit{RunQuantity::kVelocity, "velocity_m_s", 1.0},
    ColumnUnit{RunQuantity::kVelocity, "velocity_mm_s", 1e-3},
    ColumnUnit{RunQuantity::kVelocity, "velocity_cm_s", 1e-2},
    ColumnUnit{RunQuantity::kFluxDensity, "B_T", 1.0},
    ColumnUnit{RunQuantity::kFluxDensity, "B_mT", 1e-3},
    ColumnUnit{RunQuantity::kTemperature, "temperature_C", 1.0},
    ColumnUnit{RunQuantity::kTemperature, "temperature_K", 1.0, -273.15},
    ColumnUnit{RunQuantity::kSampleTime, "sample_time_s", 1.0},
    ColumnUnit{RunQuantity::kSampleTime, "sample_time_ms", 1e-3},
    ColumnUnit{RunQuantity::kSampleRate, "sample_rate_Hz", 1.0},
    ColumnUnit{RunQuantity::kSampleRate, "sample_rate_kHz", 1e3},
};

// "a, b or c"
std::string alternatives(RunQuantity q) {
  std::vector<std::string_view> names;
  for (const auto& u : kUnits) {
    if (u.quantity == q) names.push_back(u.name);
  }
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) out += i + 1 == names.size() ? " or " : ", ";
    out += names[i];
  }
  return out;
}

InputError mapping_error(std::string_view entry, const std::string& message) {
  std::string text = "--columns: ";
  if (!entry.empty()) text.append("'").append(entry).append("': ");
  return InputError(text + message);
}

}  // namespace

std::string_view to_string(RunQuantity q) {
  switch (q) {
    case RunQuantity::kTime: return "time";
    case RunQuantity::kDisplacement: return "displacement";
    case RunQuantity::kCurrent: return "current";
    case RunQuantity::kVoltage: return "voltage";
    case RunQuantity::kForce: return "force";
    case RunQuantity::kVelocity: return "velocity";
    case RunQuantity::kFluxDensity: return "B";
    case RunQuantity::kTemperature: return "temperature";
    case RunQuantity::kSampleTime: return "sample time";
    case RunQuantity::kSampleRate: return "sample rate";
  }
  return "unknown";
}

UnitLookup column_unit(std::string_view name) {
  for (const auto& u : kUnits) {
    if (u.name == name) return {u, {}};
  }
  // A known quantity with a unit we do not know is a different mistake from a stray column.
  const std::string_view prefix = name.substr(0, name.find('_'));
  for (const auto& u : kUnits) {
    if (to_string(u.quantity) != prefix) continue;
    const std::string problem =
        prefix.size() == name.size()
            ? "no unit"
            : "unknown unit '" + std::string(name.substr(prefix.size() + 1)) + "'";
    return {std::nullopt,
            problem + " for " + std::string(prefix) + "; expected " + alternatives(u.quantity)};
  }
  return {std::nullopt, "unknown column; expected " + known_unit_names()};
}

std::string known_unit_names() {
  std::string out;
  for (const auto& u : kUnits) out.append(out.empty() ? "" : ", ").append(u.name);
  return out;
}

ColumnMapping parse_column_mapping(std::string_view text) {
  ColumnMapping mapping;
  if (text.find_first_not_of(" \t") == std::string_view::npos)
    throw mapping_error("", "no columns mapped");
  bool any_name = false, any_position = false;
  for (const std::string_view entry : split_csv_line(text)) {
    const auto eq = entry.find('=');
    if (entry.empty() || eq == std::string_view::npos || eq == 0) {
      throw mapping_error(entry,
                          "expected SOURCE=UNIT, e.g. D=displacement_cm or 2=displacement_mm");
    }
    const std::string_view source = entry.substr(0, eq);
    std::string_view unit_name = entry.substr(eq + 1);
    const bool flipped = !unit_name.empty() && unit_name.front() == '-';
    if (flipped) unit_name.remove_prefix(1);
    const UnitLookup lookup = column_unit(unit_name);
    if (!lookup.unit) throw mapping_error(entry, lookup.error);

    ColumnMapping::Entry e{std::string(source), 0, *lookup.unit};
    if (flipped) {
      e.unit.scale = -e.unit.scale;
      e.unit.offset = -e.unit.offset;
    }
    const auto [end, ec] =
        std::from_chars(source.data(), source.data() + source.size(), e.position);
    const bool numeric = ec == std::errc{} && end == source.data() + source.size();
    if (numeric && e.position == 0) throw mapping_error(entry, "positions count from 1");
    (numeric ? any_position : any_name) = true;
    for (const auto& other : mapping.entries) {
      if (other.source == e.source)
        throw mapping_error(entry, "'" + e.source + "' is mapped twice");
      if (other.unit.quantity == e.unit.quantity) {
        throw mapping_error(entry, "a second " + std::string(to_string(e.unit.quantity)) +
                                       " column (the first is '" + other.source + "')");
      }
    }
    mapping.entries.push_back(std::move(e));
  }
  if (any_name && any_position) {
    throw mapping_error("", "mixes positions (1=...) and header names (t=...); use one kind");
  }
  mapping.by_position = any_position;
  return mapping;
}

}  // namespace mrd::record
