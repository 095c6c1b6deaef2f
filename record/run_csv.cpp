#include "record/run_csv.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

#include "record/csv.hpp"

namespace mrd::record {

namespace {

// One column the run uses: where it is in each row and how to convert it.
struct UsedColumn {
  std::string label;  // header name, or the 1-based position for headerless files
  std::size_t index = 0;
  ColumnUnit unit;
};

std::string seconds(double t) {
  char text[40];
  std::snprintf(text, sizeof text, "%.9g s", t);
  return text;
}

class RunCsvParser {
 public:
  RunCsvParser(std::string_view text, const std::string& name, const RunReadOptions& options)
      : lines_(text, name), name_(name), options_(options) {
    run_.name = name;
  }

  RecordedRun parse() {
    const auto first = next_line();
    if (!first) throw fail("", "empty file: expected a header (time_s, displacement_mm, ...)");
    whitespace_ = first->find(',') == std::string_view::npos;
    const bool headerless = options_.columns && options_.columns->by_position;
    headerless ? map_positions(*first) : read_header(*first);
    const std::size_t header_line = lines_.line_number();
    check_required();
    for (auto row = headerless ? first : next_line(); row; row = next_line()) read_row(*row);
    note_set_aside_rows();
    if (run_.size() < 2) {
      throw InputError(input_error_message(
          name_, header_line, "",
          "a run needs at least 2 samples, got " + std::to_string(run_.size()) +
              (run_.set_aside_rows.empty() ? std::string()
                                           : " (" + std::to_string(run_.set_aside_rows.size()) + " rows set aside)")));
    }
    run_.sample_rate = nominal_sample_rate(run_.time);
    return std::move(run_);
  }

 private:
  std::optional<std::string_view> next_line() { return next_data_line(lines_, run_.time_origin); }

  InputError fail(std::string_view column, const std::string& message) const {
    return InputError(input_error_message(name_, lines_.line_number(), column, message));
  }

  std::vector<std::string_view> fields(std::string_view line) const {
    auto out = split_csv_line(line, whitespace_);
    for (auto& f : out) f = unquote(f);
    return out;
  }

  void use(std::string label, std::size_t index, const ColumnUnit& unit) {
    for (const auto& c : used_) {
      if (c.unit.quantity == unit.quantity) {
        throw fail(label, "a second " + std::string(to_string(unit.quantity)) +
                              " column (the first is '" + c.label + "')");
      }
    }
    used_.push_back({std::move(label), index, unit});
  }

  void map_positions(std::string_view first_row) {
    width_ = fields(first_row).size();
    for (const auto& e : options_.columns->entries) {
      if (e.position > width_) {
        throw fail(e.source, "no such column: the first row has " + std::to_string(width_));
      }
      use(e.source, e.position - 1, e.unit);
    }
  }

  void read_header(std::string_view line) {
    const auto names = fields(line);
    width_ = names.size();
    header_.assign(names.begin(), names.end());
    if (options_.columns) {
      for (const auto& e : options_.columns->entries) {
        std::optional<std::size_t> index;
        for (std::size_t i = 0; i < names.size(); ++i) {
          if (names[i] != e.source) continue;
          if (index) throw fail(e.source, "appears twice in the header");
          index = i;
        }
        if (!index)
          throw fail(e.source, "mapped by --columns but not in the header (" + header_list() + ")");
        use(e.source, *index, e.unit);
      }
      std::string ignored;
      for (const auto& h : header_) {
        bool mapped = false;
        for (const auto& c : used_) mapped = mapped || c.label == h;
        if (!mapped && !h.empty()) ignored.append(ignored.empty() ? "" : ", ").append(h);
      }
      if (!ignored.empty()) run_.notes.push_back("columns not mapped, ignored: " + ignored);
      return;
    }
    if (is_controller_telemetry(names)) {
      read_telemetry_header(names);
      return;
    }
    for (std::size_t i = 0; i < names.size(); ++i) {
      if (names[i].empty()) throw fail(std::to_string(i + 1), "empty column name");
      const UnitLookup lookup = column_unit(names[i]);
      if (!lookup.unit) throw fail(names[i], lookup.error);
      use(std::string(names[i]), i, *lookup.unit);
    }
  }

  // The controller's own telemetry (runtime/csv_telemetry_writer.cpp) names columns that are
  // no run quantity (cycle, sample, state, ...) and three currents: recognised by its first
  // columns, it is read without --columns.
  static bool is_controller_telemetry(const std::vector<std::string_view>& names) {
    return names.size() >= 12 && names[0] == "cycle" && names[1] == "time_s" && names[2] == "displacement_mm" &&
           names[3] == "sample" && names[4] == "measured_current_A";
  }

  void read_telemetry_header(const std::vector<std::string_view>& names) {
    for (std::size_t i = 0; i < names.size(); ++i) {
      const std::string_view n = names[i];
      // The coil current the observer integrates is the measured one (the loop's feedback).
      const std::string_view as = n == "measured_current_A" ? std::string_view("current_A") : n;
      if (n == "time_s" || n == "displacement_mm" || n == "velocity_mm_s" || n == "measured_current_A")
        use(std::string(n), i, *column_unit(as).unit);
    }
    run_.notes.push_back(
        "the controller's telemetry (recognised by its header): time_s, displacement_mm, velocity_mm_s and "
        "measured_current_A as the coil current; its force_kN is the observer's own estimate, not a "
        "measurement, so the run has no measured force");
  }

  std::string header_list() const {
    std::string out;
    for (const auto& h : header_) out.append(out.empty() ? "" : ", ").append(h);
    return out;
  }

  const UsedColumn* find(RunQuantity q) const {
    for (const auto& c : used_) {
      if (c.unit.quantity == q) return &c;
    }
    return nullptr;
  }

  // Time (or a rate), displacement and a coil signal are needed; decided once, before any row.
  void check_required() {
    const UsedColumn* time = find(RunQuantity::kTime);
    if (time && options_.sample_rate) {
      throw fail(time->label, "--sample-rate is for files without a time column");
    }
    if (!time && !options_.sample_rate) {
      throw fail("", "no time column: expected time_s or time_ms (or give --sample-rate)");
    }
    if (options_.sample_rate &&
        !(*options_.sample_rate > 0.0 && std::isfinite(*options_.sample_rate))) {
      throw fail("", "--sample-rate must be a finite number > 0");
    }
    if (!find(RunQuantity::kDisplacement)) {
      throw fail(
          "",
          "no displacement column: expected displacement_m, displacement_mm or displacement_cm");
    }
    const UsedColumn* current = find(RunQuantity::kCurrent);
    const UsedColumn* voltage = find(RunQuantity::kVoltage);
    constant_ = constant_current(options_, name_);
    if (constant_ && (current || voltage)) {
      throw fail((current ? current : voltage)->label,
                 "the file has a coil column; --current and --current-from-name are for files "
                 "without one");
    }
    if (!constant_ && !current && !voltage) {
      throw fail("",
                 "no coil current: expected a current_A or current_mA column, a voltage_V column, "
                 "or --current / --current-from-name");
    }
    if (current && voltage) {
      run_.notes.push_back("column '" + voltage->label +
                           "' ignored: the run has the coil current ('" + current->label + "')");
      std::erase_if(used_,
                    [](const UsedColumn& c) { return c.unit.quantity == RunQuantity::kVoltage; });
    }
    if (constant_) {
      run_.coil_source = constant_->source;
    } else {
      run_.coil_signal = current ? CoilSignal::kCurrent : CoilSignal::kCommandVoltage;
      run_.coil_source = (current ? current : voltage)->label;
    }
  }

  std::vector<double>& channel(RunQuantity q) {
    switch (q) {
      case RunQuantity::kTime: return run_.time;
      case RunQuantity::kDisplacement: return run_.displacement;
      case RunQuantity::kCurrent:
      case RunQuantity::kVoltage: return run_.coil;
      case RunQuantity::kForce: return run_.force;
      case RunQuantity::kVelocity: return run_.velocity;
      case RunQuantity::kFluxDensity: return run_.B;
      case RunQuantity::kTemperature: return run_.temperature;
    }
    return run_.time;  // not reached: the switch covers every quantity
  }

  void read_row(std::string_view line) {
    const auto cells = fields(line);
    if (cells.size() != width_) {
      const std::string where = header_.empty() ? "the first row" : "the header";
      const std::string column =
          cells.size() < width_
              ? (header_.empty() ? std::to_string(cells.size() + 1) : header_[cells.size()])
              : std::to_string(width_ + 1);
      throw fail(column, "ragged row: " + std::to_string(cells.size()) + " fields, but " + where +
                             " has " + std::to_string(width_));
    }
    const std::size_t n = run_.size();
    // The row is read whole before any of it is kept: a row set aside leaves every channel as
    // it was.
    row_.clear();
    for (const auto& c : used_) {
      const std::string_view cell = cells[c.index];
      if (is_non_finite(cell)) return set_aside("non_finite", c.label);
      const auto value = parse_finite(cell);
      if (!value) throw fail(c.label, "'" + std::string(cell) + "' is not a finite number");
      const double v = c.unit.to_internal(*value);
      if (!std::isfinite(v)) {
        throw fail(c.label, "'" + std::string(cell) + "' overflows once converted to SI");
      }
      row_.push_back(v);
    }
    for (std::size_t k = 0; k < used_.size(); ++k) {
      if (used_[k].unit.quantity != RunQuantity::kTime || n == 0) continue;
      const double previous = run_.time.back();
      if (row_[k] > previous) break;
      if (row_[k] == previous && same_as_last_row()) return set_aside("duplicate", "");
      // Two rows in a row that go back, in order and past the row before the last kept one: that
      // row was the stray (a time written too far ahead), not they and every row after them.
      if (conflict_ && row_[k] > conflict_->values[k] &&
          (n == 1 || conflict_->values[k] > run_.time[n - 2])) {
        const PendingRow pending = *conflict_;
        drop_last_row(used_[k].label);
        std::erase_if(run_.set_aside_rows, [&](const auto& r) { return r.line == pending.line; });
        keep_row(pending.values, pending.line);
        break;
      }
      // A clock that jumped back is no stray row: the file holds two runs.
      if (++conflicts_in_a_row_ == kMaxConflictsInARow)
        throw fail(used_[k].label, "time stays behind " + seconds(run_.time.back()) + " for " +
                                       std::to_string(kMaxConflictsInARow) + " rows from line " +
                                       std::to_string(conflict_start_) + ": the clock jumped back; split the file there");
      if (conflicts_in_a_row_ == 1) conflict_start_ = lines_.line_number();
      conflict_ = PendingRow{row_, lines_.line_number()};
      return set_aside("time_conflict", used_[k].label);
    }
    keep_row(row_, lines_.line_number());
  }

  void keep_row(const std::vector<double>& values, std::size_t line) {
    const std::size_t n = run_.size();
    for (std::size_t k = 0; k < used_.size(); ++k) channel(used_[k].unit.quantity).push_back(values[k]);
    if (options_.sample_rate) run_.time.push_back(static_cast<double>(n) / *options_.sample_rate);
    if (constant_) run_.coil.push_back(constant_->amps);
    last_line_ = line;
    conflict_.reset();
    conflicts_in_a_row_ = 0;
  }

  // An empty cell, or nan / inf in any spelling: a logger's failed read, not a malformed file.
  static bool is_non_finite(std::string_view cell) {
    if (!cell.empty() && (cell.front() == '+' || cell.front() == '-')) cell.remove_prefix(1);
    std::string lower(cell);
    for (char& ch : lower) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    return lower.empty() || lower == "nan" || lower == "inf" || lower == "infinity";
  }

  bool same_as_last_row() {
    for (std::size_t k = 0; k < used_.size(); ++k) {
      const std::vector<double>& c = channel(used_[k].unit.quantity);
      if (c.empty() || c.back() != row_[k]) return false;
    }
    return true;
  }

  // The last row kept, set aside after all as a time_conflict.
  void drop_last_row(const std::string& column) {
    const std::size_t n = run_.size();
    for (std::vector<double>* c : run_.channels())
      if (c->size() == n && n > 0) c->pop_back();
    if (n > 0) run_.time.pop_back();
    conflict_.reset();
    run_.set_aside_rows.push_back({"time_conflict", last_line_, run_.size(), column});
    std::ranges::sort(run_.set_aside_rows, {}, &RecordedRun::SetAsideRow::line);
  }

  void set_aside(std::string_view reason, const std::string& column) {
    run_.set_aside_rows.push_back({reason, lines_.line_number(), run_.size(), column});
  }

  // Counts per reason in one note, with the first line of each.
  void note_set_aside_rows() {
    std::string note;
    for (const std::string_view reason : {"duplicate", "time_conflict", "non_finite"}) {
      std::size_t count = 0, first = 0;
      for (const auto& r : run_.set_aside_rows) {
        if (r.reason != reason) continue;
        if (count++ == 0) first = r.line;
      }
      if (count == 0) continue;
      note.append(note.empty() ? "" : ", ")
          .append(std::to_string(count))
          .append(" ")
          .append(reason)
          .append(" (first at line ")
          .append(std::to_string(first))
          .append(")");
    }
    if (!note.empty()) run_.notes.push_back("rows set aside: " + note);
  }

  std::vector<double> row_;
  std::size_t last_line_ = 0;  // the line of the last row kept
  // The row just set aside for going back, with its line: kept after all if the next row shows
  // that the row before it strayed.
  struct PendingRow {
    std::vector<double> values;
    std::size_t line = 0;
  };
  std::optional<PendingRow> conflict_;
  static constexpr int kMaxConflictsInARow = 20;
  int conflicts_in_a_row_ = 0;
  std::size_t conflict_start_ = 0;
  LineReader lines_;
  const std::string& name_;
  const RunReadOptions& options_;
  RecordedRun run_;
  bool whitespace_ = false;
  std::size_t width_ = 0;
  std::vector<std::string> header_;
  std::vector<UsedColumn> used_;
  std::optional<ConstantCurrent> constant_;
};

}  // namespace

RecordedRun parse_run_csv(std::string_view text, const std::string& name,
                          const RunReadOptions& options) {
  return RunCsvParser(text, name, options).parse();
}

}  // namespace mrd::record
