#include "tools/hil/telemetry_csv.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>

#include "telemetry/csv_telemetry_writer.hpp"
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

// The columns the report's figures use (time, displacement, the observer's force): a nan there
// spoils the row. Elsewhere the writer writes nan for a value not computed (no current sensor).
bool figure_column(std::string_view name) {
  return name == "time_s" || name == "displacement_mm" || name == "force_N" || name == "force_kN";
}
// The columns that hold a real number (the rest are counts, flags and names).
bool number_column(std::string_view name) {
  return name.ends_with("_s") || name.ends_with("_mm") || name.ends_with("_A") || name.ends_with("_T") ||
         name.ends_with("_N") || name.ends_with("_kN") || name == "force_scale";
}

class TelemetryParser {
 public:
  TelemetryParser(std::string_view text, const std::string& name) : lines_(text, name), name_(name) {}

  TelemetryLog parse() {
    static const std::vector<std::string_view> kTable4 = header_columns(telemetry::CsvTelemetryWriter::header());
    static const std::vector<std::string_view> kForce = header_columns(telemetry::CsvTelemetryWriter::force_header());
    const auto first = next();
    const std::size_t header_line = lines_.line_number();
    // Owned: the line's buffer does not outlive the next read.
    const auto cells = first ? record::split_csv_line(*first) : std::vector<std::string_view>{};
    header_text_.assign(cells.begin(), cells.end());
    header_.assign(header_text_.begin(), header_text_.end());
    // Columns by name, in any order; the force in N, or in kN as older files wrote it. A name
    // twice is refused: which one is the value?
    for (std::size_t i = 0; i < header_.size(); ++i)
      if (std::find(header_.begin(), header_.begin() + static_cast<std::ptrdiff_t>(i), header_[i]) !=
          header_.begin() + static_cast<std::ptrdiff_t>(i))
        throw fail(header_[i], "the column appears twice");
    const auto has = [&](std::string_view name) { return column_of(name).has_value(); };
    const bool all_table4 = std::all_of(kTable4.begin(), kTable4.end(), [&](std::string_view name) {
      return has(name) || (name == "force_N" && has("force_kN"));
    });
    if (!all_table4) {
      std::string missing;
      for (const std::string_view name : kTable4)
        if (!has(name) && !(name == "force_N" && has("force_kN"))) missing += (missing.empty() ? "" : ", ") + std::string(name);
      throw fail("", "not an mrd-controller telemetry file: no column " + missing + " (the header must name " +
                         std::string(telemetry::CsvTelemetryWriter::header()).substr(0, 60) + "...)");
    }
    log_.force_mode = std::all_of(kForce.begin() + static_cast<std::ptrdiff_t>(kTable4.size()), kForce.end(), has);
    // Only the columns read are screened: another tool's extra column cannot set rows aside.
    for (const std::string_view name : log_.force_mode ? kForce : kTable4) used_.push_back(name);
    used_.push_back("force_kN");
    header_line_ = header_line;
    while (const auto line = next()) read_row(*line);
    if (log_.rows.empty()) {
      const std::string counts = record::set_aside_counts(log_.set_aside_rows, "line");
      throw record::InputError(record::input_error_message(
          name_, header_line_, "", "no telemetry row left" + (counts.empty() ? "" : " (set aside: " + counts + ")")));
    }
    std::vector<double> times;
    for (const auto& r : log_.rows) times.push_back(r.time);
    log_.record_rate = record::nominal_sample_rate(times);
    log_.gaps = find_gaps(log_.rows, log_.record_rate);
    return std::move(log_);
  }

 private:
  std::optional<std::string_view> next() { return record::next_data_line(lines_, log_.time_origin); }

  [[nodiscard]] std::optional<std::size_t> column_of(std::string_view name) const {
    const auto at = std::find(header_.begin(), header_.end(), name);
    return at == header_.end() ? std::nullopt : std::optional<std::size_t>(static_cast<std::size_t>(at - header_.begin()));
  }
  // The first cell that sets the row aside as non_finite: an empty one, or nan / inf where the
  // writer never writes one (a figure's column, a count, a flag, a name).
  [[nodiscard]] std::optional<std::size_t> non_finite_cell(const std::vector<std::string_view>& f) const {
    for (std::size_t i = 0; i < f.size(); ++i) {
      if (!record::is_non_finite(f[i])) continue;
      if (std::find(used_.begin(), used_.end(), header_[i]) == used_.end()) continue;
      if (f[i].empty() || figure_column(header_[i]) || !number_column(header_[i])) return i;
    }
    return std::nullopt;
  }

  [[nodiscard]] record::InputError fail(std::string_view column, const std::string& message) const {
    return record::InputError(record::input_error_message(name_, lines_.line_number(), column, message));
  }

  void read_row(std::string_view line) {
    const auto f = record::split_csv_line(line);
    const auto& columns = header_;
    if (f.size() != columns.size()) {
      throw fail("", "expected " + std::to_string(columns.size()) + " fields, got " + std::to_string(f.size()));
    }
    if (const auto cell = non_finite_cell(f)) return set_aside("non_finite", columns[*cell]);
    TelemetryRow r = to_row(f);
    r.line = lines_.line_number();
    // The cycle counts the loop's periods: one that does not advance is no later record.
    if (!log_.rows.empty() && r.time > log_.rows.back().time && r.cycle <= log_.rows.back().cycle)
      return set_aside("time_conflict", "cycle");
    const bool repeats = screen_.repeats_last_time(r.time) && line == last_line_;
    switch (screen_.screen(r.time, repeats, r.line)) {
      case record::RowScreen::Verdict::kKeep: return keep(std::move(r), line);
      case record::RowScreen::Verdict::kDuplicate: return set_aside("duplicate", "");
      case record::RowScreen::Verdict::kTimeConflict:
        pending_ = Pending{r, std::string(line)};
        return set_aside("time_conflict", "time_s");
      case record::RowScreen::Verdict::kKeepAfterStray: {
        const Pending pending = *pending_;
        const TelemetryRow stray = log_.rows.back();
        log_.rows.pop_back();
        std::erase_if(log_.set_aside_rows, [&](const auto& a) { return a.line == pending.row.line; });
        log_.set_aside_rows.push_back({"time_conflict", stray.line, log_.rows.size(), "time_s"});
        keep(pending.row, pending.line);
        return keep(std::move(r), line);
      }
      case record::RowScreen::Verdict::kClockJumpedBack: throw fail("time_s", screen_.clock_jumped_back("line"));
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
    const auto cell = [&](std::string_view name) -> std::pair<std::string_view, std::string_view> {
      const std::size_t i = *column_of(name);
      return {header_[i], f[i]};
    };
    // nan / inf only where non_finite_cell let them through: a value the writer did not compute.
    const auto number = [&](std::string_view name) {
      const auto [column, text] = cell(name);
      if (record::is_non_finite(text)) return std::numeric_limits<double>::quiet_NaN();
      const auto v = record::parse_finite(text);
      if (!v) throw fail(column, "'" + std::string(text) + "' is not a number");
      return *v;
    };
    // Counts and flags as the writer prints them: whole numbers, and 0 or 1.
    const auto count = [&](std::string_view name) {
      const auto [column, text] = cell(name);
      std::uint64_t v = 0;
      const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), v);
      if (error != std::errc{} || end != text.data() + text.size()) {
        throw fail(column, "'" + std::string(text) + "' is not a count");
      }
      return v;
    };
    const auto count32 = [&](std::string_view name) {
      const std::uint64_t v = count(name);
      if (v > std::numeric_limits<std::uint32_t>::max()) throw fail(name, "more than 2^32 - 1");
      return static_cast<std::uint32_t>(v);
    };
    const auto flag = [&](std::string_view name) {
      const auto [column, text] = cell(name);
      if (text != "0" && text != "1") throw fail(column, "'" + std::string(text) + "' is not 0 or 1");
      return text == "1";
    };
    const auto check_name = [&](std::string_view name, const char* what) {
      const auto [column, text] = cell(name);
      control::SampleCheck check{};
      if (!enum_named(text, kSampleChecks, check)) throw fail(column, std::string("unknown ") + what);
      return std::string(text);
    };
    TelemetryRow r;
    r.cycle = count("cycle");
    r.time = number("time_s");
    r.displacement = number("displacement_mm") * 1e-3;
    r.sample = check_name("sample", "sample check");
    r.measured_current = number("measured_current_A");
    r.scheduled_current = number("scheduled_current_A");
    r.law_current = number("law_current_A");
    r.setpoint = number("setpoint_A");
    r.target_B = number("target_B_T");
    r.B = number("B_T");
    r.velocity = number("velocity_mm_s") * 1e-3;
    r.force = column_of("force_N") ? number("force_N") : number("force_kN") * 1e3;
    if (!enum_named(cell("state").second, SupervisorState::kCount, r.state)) throw fail("state", "unknown state");
    if (!enum_named(cell("trigger").second, Trigger::kCount, r.trigger)) throw fail("trigger", "unknown trigger");
    r.overruns = count32("overruns");
    r.enable = flag("enable");
    r.latched = flag("latched");
    r.recoveries = count("recoveries");
    if (log_.force_mode) {
      r.demand = number("demand_N");
      r.yield_force = number("yield_force_N");
      r.demand_check = check_name("demand", "demand check");
      r.clipped = flag("clipped");
      r.reached = flag("reached");
      r.force_scale = number("force_scale");
      r.load_cell_frozen = count32("load_cell_frozen");
    }
    return r;
  }

  record::LineReader lines_;
  const std::string& name_;
  TelemetryLog log_;
  std::vector<std::string> header_text_;    // the column names, owned
  std::vector<std::string_view> header_;    // views of them, by position
  std::size_t header_line_ = 0;
  std::vector<std::string_view> used_;      // the columns read (the rest are ignored)
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
