#include "record/run_assembler.hpp"

#include <algorithm>
#include <cmath>

namespace mrd::record {

namespace {

// The controller's own telemetry (telemetry/csv_telemetry_writer.cpp) names columns that are no
// run quantity (cycle, sample, state, ...) and three currents: recognised by the names, in any
// order, it is read without --columns.
bool is_controller_telemetry(const std::vector<std::string_view>& names) {
  const auto has = [&](std::string_view name) { return std::find(names.begin(), names.end(), name) != names.end(); };
  return has("cycle") && has("time_s") && has("displacement_mm") && has("sample") && has("measured_current_A") &&
         has("scheduled_current_A");
}

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out.append(out.empty() ? "" : ", ").append(n);
  return out;
}

}  // namespace

RunAssembler::RunAssembler(const std::string& name, const RunReadOptions& options, RowPlace place)
    : name_(name), options_(options), place_(place) {
  run_.name = name;
}

InputError RunAssembler::fail(std::string_view column, const std::string& message) const {
  if (place_ == RowPlace::kLine) return InputError(input_error_message(name_, position_, column, message));
  std::string out(name_);
  out.append(": ");
  if (position_ > 0) out.append("sample ").append(std::to_string(position_)).append(": ");
  if (!column.empty()) out.append("variable '").append(column).append("': ");
  return InputError(out.append(message));
}

void RunAssembler::use(std::string label, std::size_t index, const ColumnUnit& unit) {
  for (const auto& c : used_) {
    if (c.unit.quantity == unit.quantity) {
      throw fail(label, "a second " + std::string(to_string(unit.quantity)) + " column (the first is '" + c.label +
                            "')");
    }
  }
  if (unit.quantity == RunQuantity::kSampleTime || unit.quantity == RunQuantity::kSampleRate)
    throw fail(label, "a sample time or rate is a .mat file's scalar; for a table without a time column give "
                      "--sample-rate");
  used_.push_back({std::move(label), index, unit});
}

void RunAssembler::map_positions(std::size_t width) {
  for (const auto& e : options_.columns->entries) {
    if (e.position > width) throw fail(e.source, "no such column: the first row has " + std::to_string(width));
    use(e.source, e.position - 1, e.unit);
  }
}

void RunAssembler::map_names(const std::vector<std::string_view>& names) {
  names_.assign(names.begin(), names.end());
  if (!options_.columns) {
    is_controller_telemetry(names) ? map_telemetry(names) : map_own_names(names);
    return;
  }
  const std::string in = place_ == RowPlace::kLine ? "the header" : "the file";
  for (const auto& e : options_.columns->entries) {
    std::optional<std::size_t> index;
    for (std::size_t i = 0; i < names.size(); ++i) {
      if (names[i] != e.source) continue;
      if (index) throw fail(e.source, "appears twice in " + in);
      index = i;
    }
    if (!index) throw fail(e.source, "mapped by --columns but not in " + in + " (" + joined(names_) + ")");
    use(e.source, *index, e.unit);
  }
  std::vector<std::string> ignored;
  for (const auto& n : names_) {
    const bool mapped = std::ranges::any_of(used_, [&](const Column& c) { return c.label == n; });
    if (!mapped && !n.empty()) ignored.push_back(n);
  }
  if (!ignored.empty())
    note((place_ == RowPlace::kLine ? "columns" : "variables") + std::string(" not mapped, ignored: ") + joined(ignored));
}

void RunAssembler::map_own_names(const std::vector<std::string_view>& names) {
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (names[i].empty()) throw fail(std::to_string(i + 1), "empty column name");
    const UnitLookup lookup = column_unit(names[i]);
    if (!lookup.unit) throw fail(names[i], lookup.error);
    use(std::string(names[i]), i, *lookup.unit);
  }
}

void RunAssembler::map_telemetry(const std::vector<std::string_view>& names) {
  for (std::size_t i = 0; i < names.size(); ++i) {
    const std::string_view n = names[i];
    // The coil current the observer integrates is the measured one (the loop's feedback).
    const std::string_view as = n == "measured_current_A" ? std::string_view("current_A") : n;
    if (n == "time_s" || n == "displacement_mm" || n == "velocity_mm_s" || n == "measured_current_A")
      use(std::string(n), i, *column_unit(as).unit);
  }
  note("the controller's telemetry (recognised by its header): time_s, displacement_mm, velocity_mm_s and "
       "measured_current_A as the coil current; its force column is the observer's own estimate, not a "
       "measurement, so the run has no measured force");
}

const RunAssembler::Column* RunAssembler::find(RunQuantity q) const {
  for (const auto& c : used_) {
    if (c.unit.quantity == q) return &c;
  }
  return nullptr;
}

void RunAssembler::check_required() {
  const Column* time = find(RunQuantity::kTime);
  if (time && options_.sample_rate) throw fail(time->label, "--sample-rate is for files without a time column");
  if (!time && !options_.sample_rate) {
    throw fail("", place_ == RowPlace::kLine
                       ? "no time column: expected time_s or time_ms (or give --sample-rate)"
                       : "no time: expected a time_s or time_ms vector, a sample_time_s or sample_rate_Hz scalar, "
                         "or --sample-rate");
  }
  if (options_.sample_rate && !(*options_.sample_rate > 0.0 && std::isfinite(*options_.sample_rate)))
    throw fail("", "--sample-rate must be a finite number > 0");
  if (!find(RunQuantity::kDisplacement))
    throw fail("", "no displacement column: expected displacement_m, displacement_mm or displacement_cm");
  const Column* current = find(RunQuantity::kCurrent);
  const Column* voltage = find(RunQuantity::kVoltage);
  constant_ = constant_current(options_, name_);
  if (constant_ && (current || voltage)) {
    throw fail((current ? current : voltage)->label,
               "the file has a coil column; --current and --current-from-name are for files without one");
  }
  if (!constant_ && !current && !voltage) {
    throw fail("",
               "no coil current: expected a current_A or current_mA column, a voltage_V column, "
               "or --current / --current-from-name");
  }
  if (current && voltage) {
    note("column '" + voltage->label + "' ignored: the run has the coil current ('" + current->label + "')");
    std::erase_if(used_, [](const Column& c) { return c.unit.quantity == RunQuantity::kVoltage; });
  }
  if (constant_) {
    run_.coil_source = constant_->source;
  } else {
    current = find(RunQuantity::kCurrent);
    voltage = find(RunQuantity::kVoltage);
    run_.coil_signal = current ? CoilSignal::kCurrent : CoilSignal::kCommandVoltage;
    run_.coil_source = (current ? current : voltage)->label;
  }
}

std::vector<double>& RunAssembler::channel(RunQuantity q) {
  switch (q) {
    case RunQuantity::kTime: return run_.time;
    case RunQuantity::kDisplacement: return run_.displacement;
    case RunQuantity::kCurrent:
    case RunQuantity::kVoltage: return run_.coil;
    case RunQuantity::kForce: return run_.force;
    case RunQuantity::kVelocity: return run_.velocity;
    case RunQuantity::kFluxDensity: return run_.B;
    case RunQuantity::kTemperature: return run_.temperature;
    case RunQuantity::kSampleTime:
    case RunQuantity::kSampleRate: break;  // never a column: use() refuses them
  }
  return run_.time;
}

double RunAssembler::to_internal(std::size_t k, double value, std::string_view written) const {
  const double v = used_[k].unit.to_internal(value);
  if (!std::isfinite(v)) throw fail(used_[k].label, "'" + std::string(written) + "' overflows once converted to SI");
  return v;
}

void RunAssembler::add_row(const std::vector<double>& values, std::size_t position) {
  position_ = position;
  for (std::size_t k = 0; k < used_.size(); ++k)
    if (!std::isfinite(values[k])) return set_aside("non_finite", used_[k].label);
  const Column* time = find(RunQuantity::kTime);
  if (time == nullptr) return keep_row(values, position);
  const double t = values[static_cast<std::size_t>(time - used_.data())];
  const bool repeats = screen_.repeats_last_time(t) && same_as_last_row(values);
  switch (screen_.screen(t, repeats, position)) {
    case RowScreen::Verdict::kKeep: return keep_row(values, position);
    case RowScreen::Verdict::kDuplicate: return set_aside("duplicate", "");
    case RowScreen::Verdict::kTimeConflict:
      conflict_ = PendingRow{values, position};
      return set_aside("time_conflict", time->label);
    case RowScreen::Verdict::kKeepAfterStray: {
      const PendingRow pending = *conflict_;
      drop_last_row(time->label);
      std::erase_if(run_.set_aside_rows, [&](const auto& r) { return r.line == pending.position; });
      keep_row(pending.values, pending.position);
      return keep_row(values, position);
    }
    case RowScreen::Verdict::kClockJumpedBack: throw fail(time->label, screen_.clock_jumped_back(where()));
  }
}

void RunAssembler::keep_row(const std::vector<double>& values, std::size_t position) {
  const std::size_t n = run_.size();
  for (std::size_t k = 0; k < used_.size(); ++k) channel(used_[k].unit.quantity).push_back(values[k]);
  if (options_.sample_rate) run_.time.push_back(static_cast<double>(n) / *options_.sample_rate);
  if (constant_) run_.coil.push_back(constant_->amps);
  last_position_ = position;
  conflict_.reset();
}

bool RunAssembler::same_as_last_row(const std::vector<double>& values) {
  for (std::size_t k = 0; k < used_.size(); ++k) {
    const std::vector<double>& c = channel(used_[k].unit.quantity);
    if (c.empty() || c.back() != values[k]) return false;
  }
  return true;
}

// The last row kept, set aside after all as a time_conflict.
void RunAssembler::drop_last_row(const std::string& column) {
  const std::size_t n = run_.size();
  for (std::vector<double>* c : run_.channels())
    if (c->size() == n && n > 0) c->pop_back();
  if (n > 0) run_.time.pop_back();
  conflict_.reset();
  run_.set_aside_rows.push_back({"time_conflict", last_position_, run_.size(), column});
  std::ranges::sort(run_.set_aside_rows, {}, &RecordedRun::SetAsideRow::line);
}

void RunAssembler::set_aside(std::string_view reason, const std::string& column) {
  run_.set_aside_rows.push_back({reason, position_, run_.size(), column});
}

// Counts per reason in one note, with the first position of each.
void RunAssembler::note_set_aside_rows() {
  const std::string counts = set_aside_counts(run_.set_aside_rows, where());
  if (!counts.empty()) note("rows set aside: " + counts);
}

RecordedRun RunAssembler::finish(std::size_t start) {
  note_set_aside_rows();
  if (run_.size() < 2) {
    position_ = start;
    throw fail("", "a run needs at least 2 samples, got " + std::to_string(run_.size()) +
                       (run_.set_aside_rows.empty()
                            ? std::string()
                            : " (" + std::to_string(run_.set_aside_rows.size()) + " rows set aside)"));
  }
  run_.sample_rate = nominal_sample_rate(run_.time);
  return std::move(run_);
}

}  // namespace mrd::record
