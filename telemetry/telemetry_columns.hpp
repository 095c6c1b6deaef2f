#pragma once

#include <array>
#include <cstddef>
#include <cstdio>
#include <string_view>

#include "control/sample_check.hpp"
#include "control/supervisor.hpp"
#include "telemetry/telemetry_record.hpp"

// The controller's telemetry CSV, column by column: the one place that names a column, gives its
// unit and writes a record's field into it. The writer's header and lines come from this table,
// and the readers find the columns by these names (tools/hil/telemetry_csv, record/run_assembler).
// Adding a column: a field in TelemetryRecord, a row here, and the reader's line if a tool uses it.
namespace mrd::telemetry {

struct TelemetryColumn {
  std::string_view name;  // with the file's unit: "displacement_mm"
  bool force_mode;        // written only in force mode, after every other column
  // The value as text into buf, no separator: snprintf's return. `t`: seconds from the file's origin.
  int (*write)(const TelemetryRecord& r, double t, char* buf, std::size_t size);
};

namespace telemetry_columns {

template <typename E>
int name(char* buf, std::size_t size, E value) {
  const std::string_view text = control::to_string(value);
  return std::snprintf(buf, size, "%.*s", static_cast<int>(text.size()), text.data());
}
inline int count(char* buf, std::size_t size, unsigned long long v) { return std::snprintf(buf, size, "%llu", v); }
inline int flag(char* buf, std::size_t size, bool v) { return std::snprintf(buf, size, "%d", v ? 1 : 0); }

using R = const TelemetryRecord&;

// Significant digits: a current or a field to 5 (a driver's resolution is coarser), a force to 6.
inline constexpr std::array<TelemetryColumn, 25> kColumns{{
    {"cycle", false, [](R r, double, char* b, std::size_t n) { return count(b, n, r.cycle); }},
    {"time_s", false, [](R, double t, char* b, std::size_t n) { return std::snprintf(b, n, "%.6f", t); }},
    {"displacement_mm", false, [](R r, double, char* b, std::size_t n) { return std::snprintf(b, n, "%.4f", r.displacement * 1e3); }},
    {"sample", false, [](R r, double, char* b, std::size_t n) { return name(b, n, static_cast<control::SampleCheck>(r.sample)); }},
    {"measured_current_A", false, [](R r, double, char* b, std::size_t n) { return std::snprintf(b, n, "%.5g", r.measured_current); }},
    {"scheduled_current_A", false, [](R r, double, char* b, std::size_t n) { return std::snprintf(b, n, "%.4g", r.scheduled_current); }},
    {"law_current_A", false, [](R r, double, char* b, std::size_t n) { return std::snprintf(b, n, "%.5g", r.law_current); }},
    {"setpoint_A", false, [](R r, double, char* b, std::size_t n) { return std::snprintf(b, n, "%.5g", r.setpoint); }},
    {"target_B_T", false, [](R r, double, char* b, std::size_t n) { return std::snprintf(b, n, "%.5g", r.target_B); }},
    {"B_T", false, [](R r, double, char* b, std::size_t n) { return std::snprintf(b, n, "%.5g", r.B); }},
    {"velocity_mm_s", false, [](R r, double, char* b, std::size_t n) { return std::snprintf(b, n, "%.5g", r.velocity * 1e3); }},
    {"force_N", false, [](R r, double, char* b, std::size_t n) { return std::snprintf(b, n, "%.6g", r.force); }},
    {"state", false, [](R r, double, char* b, std::size_t n) { return name(b, n, static_cast<control::SupervisorState>(r.state)); }},
    {"trigger", false, [](R r, double, char* b, std::size_t n) { return name(b, n, static_cast<control::Trigger>(r.trigger)); }},
    {"overruns", false, [](R r, double, char* b, std::size_t n) { return count(b, n, r.overruns); }},
    {"enable", false, [](R r, double, char* b, std::size_t n) { return flag(b, n, r.enable); }},
    {"latched", false, [](R r, double, char* b, std::size_t n) { return flag(b, n, r.latched); }},
    {"recoveries", false, [](R r, double, char* b, std::size_t n) { return count(b, n, r.recoveries); }},
    // Force mode (docs/FORCE-CONTROL.md): the demand the law used, Eq. 12's yield force at its
    // target, the demand's check, the inverse's flags, the load-cell correction's scale and its
    // frozen periods.
    {"demand_N", true, [](R r, double, char* b, std::size_t n) { return std::snprintf(b, n, "%.6g", r.demand); }},
    {"yield_force_N", true, [](R r, double, char* b, std::size_t n) { return std::snprintf(b, n, "%.6g", r.yield_force); }},
    {"demand", true, [](R r, double, char* b, std::size_t n) { return name(b, n, static_cast<control::SampleCheck>(r.demand_check)); }},
    {"clipped", true, [](R r, double, char* b, std::size_t n) { return flag(b, n, r.clipped); }},
    {"reached", true, [](R r, double, char* b, std::size_t n) { return flag(b, n, r.reached); }},
    {"force_scale", true, [](R r, double, char* b, std::size_t n) { return std::snprintf(b, n, "%.6g", r.force_scale); }},
    {"load_cell_frozen", true, [](R r, double, char* b, std::size_t n) { return count(b, n, r.load_cell_frozen); }},
}};

}  // namespace telemetry_columns

inline constexpr const auto& kTelemetryColumns = telemetry_columns::kColumns;

}  // namespace mrd::telemetry
