#include "record/run_csv.hpp"

#include <algorithm>
#include <limits>

#include "record/csv.hpp"
#include "record/run_assembler.hpp"

namespace mrd::record {

namespace {

class RunCsvParser {
 public:
  RunCsvParser(std::string_view text, const std::string& name, const RunReadOptions& options)
      : lines_(text, name), options_(options), table_(name, options, RowPlace::kLine) {}

  RecordedRun parse() {
    const auto first = next_line();
    table_.set_position(lines_.line_number());
    if (!first) throw table_.fail("", "empty file: expected a header (time_s, displacement_mm, ...)");
    delimiter_ = find_delimiter(*first);
    const bool headerless = options_.columns && options_.columns->by_position;
    headerless ? map_positions(*first) : read_header(*first);
    const std::size_t header_line = lines_.line_number();
    table_.check_required();
    values_.resize(table_.columns().size());
    for (auto row = headerless ? first : next_line(); row; row = next_line()) read_row(*row);
    RecordedRun run = table_.finish(header_line);
    run.time_origin = time_origin_;
    return run;
  }

 private:
  std::optional<std::string_view> next_line() { return next_data_line(lines_, time_origin_); }

  std::vector<std::string_view> fields(std::string_view line) const {
    auto out = split_csv_line(line, delimiter_);
    for (auto& f : out) f = unquote(f);
    return out;
  }

  void map_positions(std::string_view first_row) {
    width_ = fields(first_row).size();
    table_.map_positions(width_);
  }

  void read_header(std::string_view line) {
    const auto names = fields(line);
    width_ = names.size();
    header_.assign(names.begin(), names.end());
    table_.map_names(names);
  }

  void read_row(std::string_view line) {
    table_.set_position(lines_.line_number());
    const auto cells = fields(line);
    if (cells.size() != width_) {
      const std::string where = header_.empty() ? "the first row" : "the header";
      const std::string column =
          cells.size() < width_ ? (header_.empty() ? std::to_string(cells.size() + 1) : header_[cells.size()])
                                : std::to_string(width_ + 1);
      throw table_.fail(column, "ragged row: " + std::to_string(cells.size()) + " fields, but " + where + " has " +
                                    std::to_string(width_));
    }
    // Cells are read in the run's column order up to the first non-finite one, which sets the
    // row aside whatever the cells after it hold.
    std::ranges::fill(values_, std::numeric_limits<double>::quiet_NaN());
    const bool decimal_comma = delimiter_ == Delimiter::kSemicolon;
    for (std::size_t k = 0; k < values_.size(); ++k) {
      const RunAssembler::Column& c = table_.columns()[k];
      const std::string_view cell = cells[c.index];
      if (is_non_finite(cell)) break;
      const auto value = parse_finite(cell, decimal_comma);
      if (!value) throw table_.fail(c.label, "'" + std::string(cell) + "' is not a finite number");
      values_[k] = table_.to_internal(k, *value, cell);
    }
    table_.add_row(values_, lines_.line_number());
  }

  LineReader lines_;
  const RunReadOptions& options_;
  RunAssembler table_;
  std::optional<double> time_origin_;
  Delimiter delimiter_ = Delimiter::kComma;
  std::size_t width_ = 0;
  std::vector<std::string> header_;
  std::vector<double> values_;
};

}  // namespace

RecordedRun parse_run_csv(std::string_view text, const std::string& name, const RunReadOptions& options) {
  return RunCsvParser(text, name, options).parse();
}

}  // namespace mrd::record
