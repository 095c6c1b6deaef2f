#include "tools/identification/bh_curve.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "record/csv.hpp"

namespace mrd::tools {

std::size_t BHCurve::points() const {
  std::size_t n = 0;
  for (const auto& loop : loops) n += loop.B.size();
  return n;
}

double BHCurve::max_abs_H() const {
  double h = 0.0;
  for (const auto& loop : loops) {
    for (const double x : loop.H) h = std::max(h, std::fabs(x));
  }
  return h;
}

double BHCurve::rms_B() const {
  double sum = 0.0;
  for (const auto& loop : loops) {
    for (const double b : loop.B) sum += b * b;
  }
  const auto n = points();
  return n > 0 ? std::sqrt(sum / static_cast<double>(n)) : 0.0;
}

namespace {

constexpr double kMaxAbsField = 1e9;     // [A/m]: mu0 H = 1257 T
constexpr double kMaxAbsDensity = 100.0; // [T]
constexpr double kMaxLoopIndex = 999'999'999.0;

std::string format_si(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

enum class Quantity { kField, kCurrent, kDensity, kLoopIndex, kOther };

struct Column {
  std::string name;
  Quantity quantity = Quantity::kOther;
  double to_si = 1.0;  // multiply the file's number by this
};

bool ends_with(const std::string& s, std::string_view suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

Column classify(const std::string& name) {
  struct Unit {
    char lead;
    std::string_view suffix;
    Quantity quantity;
    double to_si;
  };
  static constexpr Unit kUnits[] = {
      {'H', "_kA_per_m", Quantity::kField, 1e3}, {'H', "_A_per_m", Quantity::kField, 1.0},
      {'H', "_A/m", Quantity::kField, 1.0},      {'I', "_mA", Quantity::kCurrent, 1e-3},
      {'I', "_A", Quantity::kCurrent, 1.0},      {'B', "_mT", Quantity::kDensity, 1e-3},
      {'B', "_T", Quantity::kDensity, 1.0},
  };
  if (name == "loop") return {name, Quantity::kLoopIndex, 1.0};
  for (const auto& unit : kUnits) {
    if (!name.empty() && name.front() == unit.lead && ends_with(name, unit.suffix)) {
      return {name, unit.quantity, unit.to_si};
    }
  }
  return {name, Quantity::kOther, 1.0};
}

struct PairColumns {
  std::size_t field;
  std::size_t density;
};

}  // namespace

BHCurve parse_bh_curve(const std::string& text, const std::string& name,
                       const BHCurveOptions& options) {
  record::LineReader lines(text, name);
  auto fail = [&](std::string_view column, const std::string& message) -> record::InputError {
    return record::InputError(record::input_error_message(name, lines.line_number(), column, message));
  };

  // Header: the first non-blank line.
  std::vector<Column> columns;
  if (const auto header = lines.next()) {
    for (const auto field : record::split_csv_line(*header)) columns.push_back(classify(std::string(field)));
  }
  if (columns.empty()) throw fail("", "empty file: expected a header with H and B columns");

  std::vector<std::size_t> fields, densities;
  std::optional<std::size_t> loop_column;
  bool any_current = false, any_field = false;
  for (std::size_t i = 0; i < columns.size(); ++i) {
    switch (columns[i].quantity) {
      case Quantity::kField: any_field = true; fields.push_back(i); break;
      case Quantity::kCurrent: any_current = true; fields.push_back(i); break;
      case Quantity::kDensity: densities.push_back(i); break;
      case Quantity::kLoopIndex: loop_column = i; break;
      case Quantity::kOther:
        throw fail(columns[i].name,
                   "unknown column; expected H<n>_A_per_m, H<n>_kA_per_m, I<n>_A, I<n>_mA, "
                   "B<n>_T, B<n>_mT or loop");
    }
  }
  if (fields.empty()) throw fail("", "no field column (H<n>_A_per_m) or current column (I<n>_A)");
  if (densities.empty()) throw fail("", "no flux density column (B<n>_T)");
  if (fields.size() != densities.size()) {
    throw fail("", "field and flux density columns must come in pairs: " +
                       std::to_string(fields.size()) + " field and " +
                       std::to_string(densities.size()) + " density columns");
  }
  if (any_field && any_current) throw fail("", "mixes H and current columns; use one kind");
  if (any_current && !options.has_circuit) {
    throw fail(columns[fields.front()].name,
               "a B-I curve needs the magnetic circuit: give N and Le (--turns, --length)");
  }
  if (loop_column && fields.size() != 1) {
    throw fail("loop", "a loop column needs exactly one H/B pair");
  }
  const double current_to_field =
      any_current ? options.circuit.turns / options.circuit.effective_length : 1.0;

  std::vector<PairColumns> pairs;
  for (std::size_t i = 0; i < fields.size(); ++i) pairs.push_back({fields[i], densities[i]});
  std::vector<BHLoop> loops(pairs.size());
  std::vector<bool> ended(pairs.size(), false);
  std::map<long, std::size_t> loop_ids;  // loop column value -> index, in order of appearance

  while (const auto line = lines.next()) {
    const auto cells = record::split_csv_line(*line);
    if (cells.size() > columns.size()) {
      throw fail("", std::to_string(cells.size()) + " fields, but the header has " +
                         std::to_string(columns.size()));
    }
    auto cell = [&](std::size_t i) { return i < cells.size() ? cells[i] : std::string_view{}; };
    auto number = [&](std::size_t i) {
      const auto value = record::parse_finite(cell(i));
      if (!value) {
        throw fail(columns[i].name, "'" + std::string(cell(i)) + "' is not a finite number");
      }
      return *value * columns[i].to_si;
    };
    // Beyond any material and any lab magnet; also keeps sums of squares (rms_B) finite.
    auto physical = [&](std::size_t i, double value, double limit, const char* unit) {
      if (!(std::fabs(value) <= limit)) {
        throw fail(columns[i].name, "'" + std::string(cell(i)) + "' is " + format_si(value) + " " +
                                        unit + ", outside physics (at most " + format_si(limit) +
                                        " " + unit + ")");
      }
      return value;
    };
    std::size_t target_loop = 0;
    if (loop_column) {
      const double id = number(*loop_column);
      if (id != std::floor(id) || std::fabs(id) > kMaxLoopIndex) {
        throw fail("loop", "loop index must be an integer of at most 9 digits");
      }
      target_loop = loop_ids.try_emplace(static_cast<long>(id), loop_ids.size()).first->second;
      if (target_loop >= loops.size()) loops.resize(target_loop + 1);
    }
    for (std::size_t p = 0; p < pairs.size(); ++p) {
      const bool empty_H = cell(pairs[p].field).empty();
      const bool empty_B = cell(pairs[p].density).empty();
      if (empty_H && empty_B) {
        ended[p] = true;  // this loop is shorter than the others
        continue;
      }
      const auto& missing = columns[empty_H ? pairs[p].field : pairs[p].density];
      if (empty_H != empty_B) throw fail(missing.name, "empty cell, but its pair has a value");
      if (ended[p]) {
        throw fail(columns[pairs[p].field].name, "value after the loop ended with an empty cell");
      }
      auto& loop = loops[loop_column ? target_loop : p];
      loop.H.push_back(physical(pairs[p].field, number(pairs[p].field) * current_to_field,
                                kMaxAbsField, "A/m"));
      loop.B.push_back(physical(pairs[p].density, number(pairs[p].density), kMaxAbsDensity, "T"));
    }
  }
  BHCurve curve{name, {}};
  for (auto& loop : loops) {
    if (loop.H.size() < 4) {
      throw fail("", "a loop has " + std::to_string(loop.H.size()) +
                         " points; at least 4 are needed");
    }
    curve.loops.push_back(std::move(loop));
  }
  if (curve.loops.empty()) throw fail("", "no data rows");
  return curve;
}

BHCurve read_bh_curve(const std::string& path, const BHCurveOptions& options) {
  return parse_bh_curve(record::read_text_file(path), path, options);
}

}  // namespace mrd::tools
