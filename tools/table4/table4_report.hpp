#pragma once

#include <string>

#include "tools/table4/table4_run.hpp"

namespace mrd::tools {

// mrd-table4-run's job: the Table 4 test run twice, without and with hysteresis compensation;
// prints the B-tracking and force figures, writes OUT_DIR/table4_run.csv and, with `draw_plot`,
// OUT_DIR/table4_force_displacement.png (the paper's Figure 14 over B against time).
// `out_dir` exists and is writable. Returns the exit code (mrd::cli: ok, I/O).
int report_table4_comparison(Table4RunOptions options, const std::string& out_dir, bool draw_plot);

}  // namespace mrd::tools
