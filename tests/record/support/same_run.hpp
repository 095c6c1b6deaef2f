#pragma once

// One short run written in every format the readers take, and the check that two readings are
// the same run (tests/record/test_run_delimiters.cpp, test_run_mat.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "record/recorded_run.hpp"
#include "record/run_columns.hpp"
#include "record/run_read_options.hpp"

namespace mrd::record::testing {

// A short damper run at 1 kHz, in the file's units: mm, N, A.
struct Columns {
  std::vector<double> t, x, F, I;
};

inline Columns a_run(std::size_t n = 200) {
  Columns c;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) / 1000.0;
    c.t.push_back(t);
    c.x.push_back(5.0 * std::sin(2.0 * std::numbers::pi * 3.0 * t));
    c.F.push_back(300.0 * std::tanh(std::cos(2.0 * std::numbers::pi * 3.0 * t) * 4.0) + 0.1 * static_cast<double>(i % 7));
    c.I.push_back(0.5 + 0.001 * static_cast<double>(i % 3));
  }
  return c;
}

inline std::string number(double v) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

// The run as text: `delimiter` between cells, `eol` after each line, a decimal comma on request.
inline std::string as_text(const Columns& c, const std::string& delimiter, const std::string& eol, bool decimal_comma = false,
                    const std::string& bom = "") {
  std::string out = bom + "t" + delimiter + "x" + delimiter + "F" + delimiter + "I" + eol;
  for (std::size_t i = 0; i < c.t.size(); ++i) {
    std::string row;
    for (const double v : {c.t[i], c.x[i], c.F[i], c.I[i]}) {
      std::string cell = number(v);
      if (decimal_comma && cell.find('.') != std::string::npos) cell[cell.find('.')] = ',';
      row += (row.empty() ? "" : delimiter) + cell;
    }
    out += row + eol;
  }
  return out;
}

inline RunReadOptions with_columns(const char* columns) {
  RunReadOptions o;
  o.columns = parse_column_mapping(columns);
  return o;
}

inline const RunReadOptions kTextColumns = with_columns("t=time_s,x=displacement_mm,F=force_N,I=current_A");

// Every channel sample for sample, bit for bit, and how the reader describes the run.
inline void expect_same_run(const RecordedRun& a, const RecordedRun& b, const std::string& what) {
  SCOPED_TRACE(what);
  EXPECT_EQ(a.time, b.time);
  EXPECT_EQ(a.displacement, b.displacement);
  EXPECT_EQ(a.coil, b.coil);
  EXPECT_EQ(a.force, b.force);
  EXPECT_EQ(a.velocity, b.velocity);
  EXPECT_EQ(a.sample_rate, b.sample_rate);
  EXPECT_EQ(a.coil_signal, b.coil_signal);
  EXPECT_EQ(a.coil_source, b.coil_source);
  EXPECT_EQ(a.set_aside_rows.size(), b.set_aside_rows.size());
}

}  // namespace mrd::record::testing
