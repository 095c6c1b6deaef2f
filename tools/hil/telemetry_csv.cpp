#include "tools/hil/telemetry_csv.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>

#include "runtime/csv_telemetry_writer.hpp"
#include "record/csv.hpp"

namespace mrd::tools {

namespace {

using control::SupervisorState;
using control::Trigger;

// One past the last SampleCheck, for enum_named.
constexpr auto kSampleChecks =
    static_cast<control::SampleCheck>(static_cast<int>(control::SampleCheck::kFromFuture) + 1);

template <typename E>
bool enum_named(std::string_view name, E count, E& out) {
  for (std::size_t i = 0; i < static_cast<std::size_t>(count); ++i) {
    if (control::to_string(static_cast<E>(i)) == name) {
      out = static_cast<E>(i);
      return true;
    }
  }
  return false;
}

}  // namespace

namespace {

std::vector<std::string_view> header_columns(const char* header) {
  std::string_view line = header;
  line.remove_suffix(1);  // '\n'
  return record::split_csv_line(line);
}

}  // namespace

TelemetryLog parse_telemetry_csv(std::string_view text, const std::string& name) {
  static const std::vector<std::string_view> kTable4 = header_columns(runtime::CsvTelemetryWriter::header());
  static const std::vector<std::string_view> kForce = header_columns(runtime::CsvTelemetryWriter::force_header());
  record::LineReader lines(text, name);
  TelemetryLog log;
  const auto next = [&] { return record::next_data_line(lines, log.time_origin); };
  const auto fail = [&](std::string_view column, const std::string& message) {
    return record::InputError(record::input_error_message(name, lines.line_number(), column, message));
  };
  const auto first = next();
  const auto header = first ? record::split_csv_line(*first) : std::vector<std::string_view>{};
  log.force_mode = header == kForce;
  if (header != kTable4 && !log.force_mode) {
    throw fail("", "not an mrd-controller telemetry file: the header must be " +
                       std::string(runtime::CsvTelemetryWriter::header()).substr(0, 60) + "...");
  }
  const auto& columns = log.force_mode ? kForce : kTable4;
  while (const auto line = next()) {
    const auto f = record::split_csv_line(*line);
    if (f.size() != columns.size()) {
      throw fail("", "expected " + std::to_string(columns.size()) + " fields, got " + std::to_string(f.size()));
    }
    const auto number = [&](std::size_t i) {
      if (f[i] == "nan" || f[i] == "-nan") return std::numeric_limits<double>::quiet_NaN();
      const auto v = record::parse_finite(f[i]);
      if (!v) throw fail(columns[i], "'" + std::string(f[i]) + "' is not a number");
      return *v;
    };
    // Counts and flags as the writer prints them: whole numbers, and 0 or 1.
    const auto count = [&](std::size_t i) {
      std::uint64_t v = 0;
      const auto [end, error] = std::from_chars(f[i].data(), f[i].data() + f[i].size(), v);
      if (error != std::errc{} || end != f[i].data() + f[i].size()) {
        throw fail(columns[i], "'" + std::string(f[i]) + "' is not a count");
      }
      return v;
    };
    const auto flag = [&](std::size_t i) {
      if (f[i] != "0" && f[i] != "1") throw fail(columns[i], "'" + std::string(f[i]) + "' is not 0 or 1");
      return f[i] == "1";
    };
    TelemetryRow r;
    r.cycle = count(0);
    r.time = number(1);
    r.displacement = number(2) * 1e-3;
    control::SampleCheck sample{};
    if (!enum_named(f[3], kSampleChecks, sample)) throw fail(columns[3], "unknown sample check");
    r.sample = std::string(f[3]);
    r.measured_current = number(4);
    r.scheduled_current = number(5);
    r.law_current = number(6);
    r.setpoint = number(7);
    r.target_B = number(8);
    r.B = number(9);
    r.velocity = number(10) * 1e-3;
    r.force = number(11) * 1e3;
    if (!enum_named(f[12], SupervisorState::kCount, r.state)) throw fail(columns[12], "unknown state");
    if (!enum_named(f[13], Trigger::kCount, r.trigger)) throw fail(columns[13], "unknown trigger");
    const std::uint64_t overruns = count(14);
    if (overruns > std::numeric_limits<std::uint32_t>::max()) throw fail(columns[14], "more than 2^32 - 1");
    r.overruns = static_cast<std::uint32_t>(overruns);
    r.enable = flag(15);
    r.latched = flag(16);
    r.recoveries = count(17);
    if (log.force_mode) {
      r.demand = number(18);
      r.yield_force = number(19);
      control::SampleCheck check{};
      if (!enum_named(f[20], kSampleChecks, check)) throw fail(columns[20], "unknown demand check");
      r.demand_check = std::string(f[20]);
      r.clipped = flag(21);
      r.reached = flag(22);
      r.force_scale = number(23);
      const std::uint64_t frozen = count(24);
      if (frozen > std::numeric_limits<std::uint32_t>::max()) throw fail(columns[24], "more than 2^32 - 1");
      r.load_cell_frozen = static_cast<std::uint32_t>(frozen);
    }
    log.rows.push_back(std::move(r));
  }
  return log;
}

TelemetryLog read_telemetry_csv(const std::string& path) {
  return parse_telemetry_csv(record::read_text_file(path), path);
}

std::vector<StateChange> state_changes(const std::vector<TelemetryRow>& rows) {
  std::vector<StateChange> out;
  SupervisorState state = SupervisorState::kInit;
  for (const auto& r : rows) {
    if (r.state != state) out.push_back({r.cycle, r.time, state, r.state, r.trigger});
    state = r.state;
  }
  return out;
}

std::string to_string(const StateChange& c) {
  char text[160];
  std::snprintf(text, sizeof text, "%s -> %s (%s) at cycle %llu (%.3f s)",
                control::to_string(c.from).data(), control::to_string(c.to).data(),
                control::to_string(c.trigger).data(), static_cast<unsigned long long>(c.cycle), c.time);
  return text;
}

}  // namespace mrd::tools
