#include "record/run_mat.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>

#include "record/mat_file.hpp"
#include "record/run_assembler.hpp"

namespace mrd::record {

namespace {

bool is_scalar_quantity(RunQuantity q) { return q == RunQuantity::kSampleTime || q == RunQuantity::kSampleRate; }

std::string number(double v, const char* format = "%.17g") {
  char text[40];
  std::snprintf(text, sizeof text, format, v);
  return text;
}

std::string dims_text(const MatVariable& v) {
  std::string out;
  for (const std::size_t d : v.dims) out.append(out.empty() ? "" : "x").append(std::to_string(d));
  return out.empty() ? "empty" : out;
}

bool is_vector(const MatVariable& v) { return v.dims.size() == 2 && (v.dims[0] == 1 || v.dims[1] == 1); }

// One column of the run: a vector, or one column of a matrix.
struct Source {
  const MatVariable* variable = nullptr;
  std::size_t column = 0;  // 0-based, of a matrix
  std::size_t rows = 0;
};

class MatRunReader {
 public:
  MatRunReader(const std::string& path, const RunReadOptions& options)
      : path_(path), options_(options), file_(path) {}

  RecordedRun read() {
    if (options_.columns && options_.columns->by_position)
      throw InputError(path_ + ": --columns by position is for text files without a header; name the .mat "
                               "file's variables (x=displacement_mm, data:2=force_N)");
    choose_entries();
    resolve_time_scalar();
    RunAssembler table(path_, assembler_options_, RowPlace::kSample);
    for (const auto& n : notes_) table.note(n);
    std::vector<std::string_view> names(labels_.begin(), labels_.end());
    table.map_names(names);
    table.check_required();
    const std::size_t rows = sources_.empty() ? 0 : sources_.front().rows;
    std::vector<std::vector<double>> columns;
    for (const RunAssembler::Column& c : table.columns()) columns.push_back(data_of(sources_[c.index]));
    std::vector<double> values(columns.size());
    for (std::size_t r = 0; r < rows; ++r) {
      table.set_position(r + 1);
      std::ranges::fill(values, std::numeric_limits<double>::quiet_NaN());
      for (std::size_t k = 0; k < columns.size() && std::isfinite(columns[k][r]); ++k)
        values[k] = table.to_internal(k, columns[k][r], number(columns[k][r], "%.6g"));
      table.add_row(values, r + 1);
    }
    return table.finish(0);
  }

 private:
  InputError fail(std::string_view variable, const std::string& message) const {
    return InputError(path_ + ": variable '" + std::string(variable) + "': " + message);
  }

  const MatVariable* find(std::string_view name) const {
    for (const auto& v : file_.variables())
      if (v.name == name) return &v;
    return nullptr;
  }

  std::string variable_list() const {
    std::string out;
    for (const auto& v : file_.variables()) out.append(out.empty() ? "" : ", ").append(v.name);
    return out.empty() ? "none" : out;
  }

  // The mapping's entries, or the variables named the project's way; the rest is noted.
  void choose_entries() {
    if (options_.columns) {
      entries_ = options_.columns->entries;
    } else {
      std::string ignored;
      for (const auto& v : file_.variables()) {
        const UnitLookup lookup = column_unit(v.name);
        if (lookup.unit)
          entries_.push_back({v.name, 0, *lookup.unit});
        else
          ignored.append(ignored.empty() ? "" : ", ").append(v.name);
      }
      if (!ignored.empty()) notes_.push_back("variables not named time_s, displacement_mm, ..., ignored: " + ignored);
    }
    ColumnMapping columns;
    for (const auto& e : entries_) {
      if (is_scalar_quantity(e.unit.quantity)) {
        if (scalar_) throw fail(e.source, "a second sample time or rate (the first is '" + scalar_->source + "')");
        scalar_ = e;
        continue;
      }
      sources_.push_back(resolve(e.source));
      labels_.push_back(e.source);
      columns.entries.push_back(e);
      if (sources_.back().rows != sources_.front().rows) {
        throw fail(e.source, std::to_string(sources_.back().rows) + " samples, but '" + labels_.front() + "' has " +
                                 std::to_string(sources_.front().rows));
      }
    }
    assembler_options_ = options_;
    if (options_.columns) {
      assembler_options_.columns = columns;
      // The variables no entry reads, for the assembler's note.
      for (const auto& v : file_.variables()) {
        bool used = scalar_ && scalar_->source == v.name;
        for (const Source& s : sources_) used = used || s.variable == &v;
        if (!used) labels_.push_back(v.name);
      }
    }
  }

  // "x" or "data:2" to a vector or a matrix column.
  Source resolve(const std::string& label) const {
    std::string_view name = label;
    std::size_t k = 0;
    if (const auto colon = label.rfind(':'); colon != std::string::npos) {
      const std::string_view digits = std::string_view(label).substr(colon + 1);
      const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), k);
      if (ec == std::errc{} && end == digits.data() + digits.size()) {
        if (k == 0) throw fail(label, "matrix columns count from 1");
        name = name.substr(0, colon);
      } else {
        k = 0;
      }
    }
    const MatVariable* v = find(name);
    if (v == nullptr) throw fail(name, "not in the file (variables: " + variable_list() + ")");
    if (!v->not_numeric.empty()) throw fail(name, "is " + v->not_numeric + ", not numbers");
    if (v->dims.size() != 2) throw fail(name, "has " + std::to_string(v->dims.size()) + " dimensions; expected a vector or a matrix");
    if (is_vector(*v)) {
      if (k > 1) throw fail(label, "column " + std::to_string(k) + " out of range: '" + v->name + "' is a vector (" + dims_text(*v) + ")");
      return {v, 0, v->elements()};
    }
    const std::size_t columns = v->dims[1];
    const std::string range = v->name + ":1 to " + v->name + ":" + std::to_string(columns);
    if (k == 0) throw fail(name, "is a " + dims_text(*v) + " matrix: pick a column, " + range);
    if (k > columns) throw fail(label, "column " + std::to_string(k) + " out of range: '" + v->name + "' is " + dims_text(*v) + " (" + range + ")");
    return {v, k - 1, v->dims[0]};
  }

  // A sample time or rate scalar stands in for a missing time vector.
  void resolve_time_scalar() {
    if (!scalar_) return;
    const bool has_time = std::ranges::any_of(
        entries_, [](const ColumnMapping::Entry& e) { return e.unit.quantity == RunQuantity::kTime; });
    if (has_time) {
      if (options_.columns) throw fail(scalar_->source, "the run has a time vector; map one of the two");
      notes_.push_back("variable '" + scalar_->source + "' ignored: the run has a time vector");
      return;
    }
    if (options_.sample_rate) throw fail(scalar_->source, "--sample-rate is for files without a sample time");
    const MatVariable* v = find(scalar_->source);
    if (v == nullptr) throw fail(scalar_->source, "not in the file (variables: " + variable_list() + ")");
    if (!v->not_numeric.empty()) throw fail(v->name, "is " + v->not_numeric + ", not a number");
    if (v->elements() != 1) throw fail(v->name, "a sample time or rate must be a scalar, not " + dims_text(*v));
    const double value = scalar_->unit.to_internal(file_.read(*v).front());
    if (!(value > 0.0 && std::isfinite(value))) throw fail(v->name, "must be a finite number > 0, got " + number(value, "%.6g"));
    const bool period = scalar_->unit.quantity == RunQuantity::kSampleTime;
    // A denormal period or rate has no finite reciprocal: the times would not increase.
    if (!std::isfinite(1.0 / value)) throw fail(v->name, "is too small to time samples by, got " + number(value, "%.6g"));
    assembler_options_.sample_rate = period ? 1.0 / value : value;
    notes_.push_back("time from the sample " + std::string(period ? "time '" : "rate '") + v->name + "': " +
                     number(period ? value : 1.0 / value, "%.6g") + " s a sample");
  }

  std::vector<double> data_of(const Source& s) {
    auto [at, missing] = read_.try_emplace(s.variable->name);
    if (missing) at->second = file_.read(*s.variable);
    const auto first = at->second.begin() + static_cast<std::ptrdiff_t>(s.column * s.rows);
    return {first, first + static_cast<std::ptrdiff_t>(s.rows)};
  }

  const std::string& path_;
  const RunReadOptions& options_;
  MatFile file_;
  RunReadOptions assembler_options_;
  std::vector<ColumnMapping::Entry> entries_;
  std::optional<ColumnMapping::Entry> scalar_;
  std::vector<Source> sources_;     // the run's columns, in entry order
  std::vector<std::string> labels_;  // their labels, then (mapped) the variables left out
  std::vector<std::string> notes_;
  std::map<std::string, std::vector<double>> read_;  // each variable read once
};

}  // namespace

std::size_t MatVariable::elements() const {
  std::size_t n = dims.empty() ? 0 : 1;
  for (const std::size_t d : dims) {
    if (d != 0 && n > kMaxMatElements / d) return kMaxMatElements + 1;
    n *= d;
  }
  return n;
}

RecordedRun read_mat_run(const std::string& path, const RunReadOptions& options) {
  return MatRunReader(path, options).read();
}

bool starts_like_mat_file(std::string_view head) {
  return head.starts_with("MATLAB 5.0 MAT-file") || head.starts_with("MATLAB 7.3 MAT-file");
}

}  // namespace mrd::record
