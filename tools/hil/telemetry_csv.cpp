#include "tools/hil/telemetry_csv.hpp"

#include <charconv>
#include <cmath>
#include <limits>

#include "runtime/csv_telemetry_writer.hpp"
#include "record/csv.hpp"
#include "record/row_screen.hpp"

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

namespace {

// The columns the report's figures use (time, displacement, the observer's force): a nan there
// spoils the row. Elsewhere the writer writes nan for a value not computed (no current sensor).
bool figure_column(std::size_t i) { return i == 1 || i == 2 || i == 11; }
bool number_column(std::size_t i) { return (i >= 1 && i <= 11 && i != 3) || i == 18 || i == 19 || i == 23; }

// The first cell that sets the row aside as non_finite: an empty one, or nan / inf where the
// writer never writes one (a figure's column, a count, a flag, a name).
std::optional<std::size_t> non_finite_cell(const std::vector<std::string_view>& f) {
  for (std::size_t i = 0; i < f.size(); ++i) {
    if (!record::is_non_finite(f[i])) continue;
    if (f[i].empty() || figure_column(i) || !number_column(i)) return i;
  }
  return std::nullopt;
}

class TelemetryParser {
 public:
  TelemetryParser(std::string_view text, const std::string& name) : lines_(text, name), name_(name) {}

  TelemetryLog parse() {
    static const std::vector<std::string_view> kTable4 = header_columns(runtime::CsvTelemetryWriter::header());
    static const std::vector<std::string_view> kForce = header_columns(runtime::CsvTelemetryWriter::force_header());
    const auto first = next();
    const std::size_t header_line = lines_.line_number();
    const auto header = first ? record::split_csv_line(*first) : std::vector<std::string_view>{};
    log_.force_mode = header == kForce;
    if (header != kTable4 && !log_.force_mode) {
      throw fail("", "not an mrd-controller telemetry file: the header must be " +
                         std::string(runtime::CsvTelemetryWriter::header()).substr(0, 60) + "...");
    }
    columns_ = log_.force_mode ? &kForce : &kTable4;
    while (const auto line = next()) read_row(*line);
    if (log_.rows.empty()) {
      const std::string counts = record::set_aside_counts(log_.set_aside_rows, "line");
      throw record::InputError(record::input_error_message(
          name_, header_line, "", "no telemetry row left" + (counts.empty() ? "" : " (set aside: " + counts + ")")));
    }
    std::vector<double> times;
    for (const auto& r : log_.rows) times.push_back(r.time);
    log_.record_rate = record::nominal_sample_rate(times);
    log_.gaps = find_gaps(log_.rows, log_.record_rate);
    return std::move(log_);
  }

 private:
  std::optional<std::string_view> next() { return record::next_data_line(lines_, log_.time_origin); }

  [[nodiscard]] record::InputError fail(std::string_view column, const std::string& message) const {
    return record::InputError(record::input_error_message(name_, lines_.line_number(), column, message));
  }

  void read_row(std::string_view line) {
    const auto f = record::split_csv_line(line);
    const auto& columns = *columns_;
    if (f.size() != columns.size()) {
      throw fail("", "expected " + std::to_string(columns.size()) + " fields, got " + std::to_string(f.size()));
    }
    if (const auto cell = non_finite_cell(f)) return set_aside("non_finite", columns[*cell]);
    TelemetryRow r = to_row(f);
    r.line = lines_.line_number();
    // The cycle counts the loop's periods: one that does not advance is no later record.
    if (!log_.rows.empty() && r.time > log_.rows.back().time && r.cycle <= log_.rows.back().cycle)
      return set_aside("time_conflict", columns[0]);
    const bool repeats = screen_.repeats_last_time(r.time) && line == last_line_;
    switch (screen_.screen(r.time, repeats, r.line)) {
      case record::RowScreen::Verdict::kKeep: return keep(std::move(r), line);
      case record::RowScreen::Verdict::kDuplicate: return set_aside("duplicate", "");
      case record::RowScreen::Verdict::kTimeConflict:
        pending_ = Pending{r, std::string(line)};
        return set_aside("time_conflict", columns[1]);
      case record::RowScreen::Verdict::kKeepAfterStray: {
        const Pending pending = *pending_;
        const TelemetryRow stray = log_.rows.back();
        log_.rows.pop_back();
        std::erase_if(log_.set_aside_rows, [&](const auto& a) { return a.line == pending.row.line; });
        log_.set_aside_rows.push_back({"time_conflict", stray.line, log_.rows.size(), std::string(columns[1])});
        keep(pending.row, pending.line);
        return keep(std::move(r), line);
      }
      case record::RowScreen::Verdict::kClockJumpedBack: throw fail(columns[1], screen_.clock_jumped_back("line"));
    }
  }

  void keep(TelemetryRow r, std::string_view line) {
    log_.rows.push_back(std::move(r));
    last_line_ = line;
  }

  void set_aside(std::string_view reason, std::string_view column) {
    log_.set_aside_rows.push_back({reason, lines_.line_number(), log_.rows.size(), std::string(column)});
  }

  TelemetryRow to_row(const std::vector<std::string_view>& f) const {
    const auto& columns = *columns_;
    // nan / inf only where non_finite_cell let them through: a value the writer did not compute.
    const auto number = [&](std::size_t i) {
      if (record::is_non_finite(f[i])) return std::numeric_limits<double>::quiet_NaN();
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
    if (log_.force_mode) {
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
    return r;
  }

  record::LineReader lines_;
  const std::string& name_;
  TelemetryLog log_;
  const std::vector<std::string_view>* columns_ = nullptr;
  record::RowScreen screen_;
  std::string last_line_;  // the row kept last, as written: a duplicate is the same text
  // The row set aside last for its time: kept after all when the row before it was a stray.
  struct Pending {
    TelemetryRow row;
    std::string line;
  };
  std::optional<Pending> pending_;
};

}  // namespace

TelemetryLog parse_telemetry_csv(std::string_view text, const std::string& name) {
  return TelemetryParser(text, name).parse();
}

TelemetryLog read_telemetry_csv(const std::string& path) {
  return parse_telemetry_csv(record::read_text_file(path), path);
}

}  // namespace mrd::tools
